#pragma once
// Angular-dependent potential (ADP), LAMMPS pair_style adp (29 Sep 2021 semantics; Mishin, Mehl &
// Papaconstantopoulos, Acta Mater. 53 (2005) 4029). The energy of atom i is
//   E_i = F_i(ρ̄_i) + ½ Σ_j φ_ij(r_ij) + ½ Σ_α (μ_i^α)² + ½ Σ_αβ (λ_i^αβ)² − (1/6) ν_i²,
//   ρ̄_i = Σ_j ρ_j(r_ij),   μ_i^α = Σ_j u_ij(r_ij) r_ij^α,   λ_i^αβ = Σ_j w_ij(r_ij) r_ij^α r_ij^β,
//   ν_i = Σ_α λ_i^αα,      r_ij = x_i − x_j,
// with F, ρ, r·φ from the setfl part of the file and u, w from its two extra table blocks, all
// splined and looked up exactly as for eam/alloy (eam_tables.hpp). Evaluation (newton on):
//   1. moment pass over the half list: ρ̄, μ (μ_j gets −u r_ij) and λ of both atoms, ghosts too;
//   2. ghost moments summed onto their owners (Atoms::reverse_sum);
//   3. per owned atom: F, F' and E_i − ½Σφ above, and D_i = λ_i − (ν_i/3) I (= ∂E/∂λ_i);
//   4. F', μ, D copied to the ghosts (Atoms::forward_copy);
//   5. force pass, d = r_ij, r = |d|, the force on i (−dE/dd; j gets the opposite):
//        f_ij = −(F'_i ρ'_j + F'_j ρ'_i + φ') d/r                                      (EAM part)
//               − u (μ_i − μ_j) − u' ((μ_i − μ_j)·d) d/r                               (dipole)
//               − 2 w (D_i + D_j) d − w' (d·(D_i + D_j) d) d/r                        (quadrupole)
//      not along d, so the per-atom virial is half of d ⊗ f_ij to each atom (LAMMPS ev_tally_xyz).
// As for EAM, F(ρ̄) is extended linearly beyond the density table.
#include <array>
#include <string>
#include <vector>

#include "shockfield/md/potentials/embedded_atom.hpp"
#include "shockfield/md/potentials/pair_loop.hpp"

namespace shockfield::md::potentials {

/// Ten doubles per atom: moments (ρ̄, μ xyz, λ xx yy zz xy xz yz) after the first pass, then
/// (F', μ xyz, D xx yy zz xy xz yz) for the force pass.
struct AdpAtomTerms {
  std::array<double, 10> v{};
  AdpAtomTerms& operator+=(const AdpAtomTerms& o) {
    for (std::size_t k = 0; k < v.size(); ++k) v[k] += o.v[k];
    return *this;
  }
};

class AdpPotential final : public EmbeddedAtomPotential {
 public:
  /// `type_names[t]`: the element of atom type t (checked against the atoms' type names).
  AdpPotential(const AdpTables& tables, std::vector<std::string> type_names);

  void compute(Atoms& atoms, const geometry::NeighborList& list, ForceResult& out) override;

  /// ρ̄ at each owned atom after the last compute().
  std::vector<double> density() const;

 private:
  // Per ordered type pair (ti, tj) and grid interval, values [to_i c3..c6, to_j c3..c6, u c3..c6,
  // w c3..c6] and derivatives [ρ'_{i→j} c0..c2, ρ'_{j→i} c0..c2, rφ c0..c6, u c0..c6, w c0..c6].
  PackedPairRows moment_rows_;
  PackedPairRows force_rows_;
  std::vector<AdpAtomTerms> moments_, terms_;
  std::vector<std::vector<AdpAtomTerms>> thread_moments_;
  AcceptedPairs accepted_;  // pairs within the cutoff, found by the moment pass
  ThreadScratch scratch_;
};

}  // namespace shockfield::md::potentials

#pragma once
// Embedded-atom method, LAMMPS pair_style eam, eam/alloy and eam/fs (29 Sep 2021):
//   E = Σ_i F_i(ρ_i) + ½ Σ_i Σ_{j≠i} φ_ij(r_ij),   ρ_i = Σ_{j≠i} ρ_{j→i}(r_ij),
// with φ = (r φ)/r from the z2r table. Force evaluation follows PairEAM::compute() with newton on:
//   1. density pass over the half list (both atoms of each pair, ghosts included),
//   2. ghost densities summed onto their owners (Atoms::reverse_sum),
//   3. embedding pass on owned atoms: F'(ρ_i) and F(ρ_i); beyond the table (ρ > rhomax) the
//      energy is extended linearly, F(ρ) = F(ρmax⁻ spline) + F'·(ρ - ρmax), to conserve energy,
//   4. F' copied to the ghosts (Atoms::forward_copy),
//   5. force pass: f_pair = -(F'_i ρ'_{j→i} + F'_j ρ'_{i→j} + φ')/r on each pair (only the
//      pairs the density pass found within the cutoff: the list's skin pairs are skipped).
// Table look-ups use LAMMPS's arithmetic (p = r/dr + 1, m = min(int p, n-1), p -= m, p <= 1), so
// energies and forces agree with LAMMPS to round-off. For speed, the three spline rows one pair
// needs are packed side by side per type pair (like LAMMPS's OPT package).
#include <string>
#include <vector>

#include "shockfield/md/potentials/embedded_atom.hpp"
#include "shockfield/md/potentials/pair_loop.hpp"

namespace shockfield::md::potentials {

class EamPotential final : public EmbeddedAtomPotential {
 public:
  /// `style` is "eam", "eam/alloy" or "eam/fs"; see EmbeddedAtomPotential for `type_names`.
  EamPotential(std::string style, EamTables tables, std::vector<std::string> type_names);

  void compute(Atoms& atoms, const geometry::NeighborList& list, ForceResult& out) override;

  /// Electron density at each owned atom after the last compute().
  const std::vector<double>& density() const { return rho_; }

 private:
  // The density and force rows of fill_eam_density_row() and fill_eam_force_row().
  PackedPairRows density_rows_;
  PackedPairRows force_rows_;
  std::vector<double> rho_, fp_;
  AcceptedPairs accepted_;  // pairs within the cutoff, found by the density pass
  ThreadScratch scratch_;
};

}  // namespace shockfield::md::potentials

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

#include "shockfield/md/potential.hpp"
#include "shockfield/md/potentials/eam_tables.hpp"
#include "shockfield/md/potentials/pair_loop.hpp"

namespace shockfield::md::potentials {

class EamPotential final : public Potential {
 public:
  /// `style` is "eam", "eam/alloy" or "eam/fs"; `type_names[t]` names the element of type t
  /// ("" when the file does not name it), checked against the atoms' type names.
  EamPotential(std::string style, EamTables tables, std::vector<std::string> type_names);

  std::string style() const override { return style_; }
  double cutoff() const override { return tables_.cut; }
  void check_types(const Atoms& atoms) const override;
  void compute(Atoms& atoms, const geometry::NeighborList& list, ForceResult& out) override;

  const EamTables& tables() const { return tables_; }
  /// The mass of atom type t (0-based) given by the potential file, amu.
  double type_mass(int t) const { return tables_.type_mass[static_cast<std::size_t>(t)]; }
  /// The element of each atom type named by the potential file ("" where it names none).
  const std::vector<std::string>& type_names() const { return type_names_; }
  /// Electron density at each owned atom after the last compute().
  const std::vector<double>& density() const { return rho_; }

 private:
  std::string style_;
  EamTables tables_;
  std::vector<std::string> type_names_;
  // Per ordered type pair (ti, tj) and grid interval: density values [to_i c3..c6, to_j c3..c6]
  // and force derivatives [ρ'_{i→j} c0..c2, ρ'_{j→i} c0..c2, (rφ)' c0..c2, rφ c3..c6].
  std::vector<double> density_rows_;
  std::vector<double> force_rows_;
  std::vector<double> rho_, fp_;
  AcceptedPairs accepted_;  // pairs within the cutoff, found by the density pass
  ThreadScratch scratch_;
};

}  // namespace shockfield::md::potentials

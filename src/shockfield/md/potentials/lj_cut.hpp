#pragma once
// Lennard-Jones 12-6 with a cutoff per type pair, LAMMPS pair_style lj/cut (29 Sep 2021):
//   E(r) = 4ε[(σ/r)¹² − (σ/r)⁶] − E_shift   for r < r_c,
//   E_shift = 4ε[(σ/r_c)¹² − (σ/r_c)⁶] with `pair_modify shift yes`, else 0.
// Evaluated as LAMMPS does: lj1 = 48εσ¹², lj2 = 24εσ⁶, lj3 = 4εσ¹², lj4 = 4εσ⁶,
//   f_pair = r⁻⁶(lj1 r⁻⁶ − lj2) r⁻²,   E = r⁻⁶(lj3 r⁻⁶ − lj4) − E_shift.
// Unset unlike pairs are mixed geometrically (LAMMPS default pair_modify mix geometric):
//   ε_ij = √(ε_ii ε_jj), σ_ij = √(σ_ii σ_jj), r_c,ij = √(r_c,ii r_c,jj).
#include <optional>
#include <string>
#include <vector>

#include "shockfield/md/potential.hpp"
#include "shockfield/md/potentials/pair_loop.hpp"

namespace shockfield::md::potentials {

struct LjCoeff {
  double epsilon = 0;  ///< eV
  double sigma = 0;    ///< Å
  double cutoff = 0;   ///< Å
};

/// Completes a type-pair table ([i * ntypes + j], symmetric entries set together) by geometric
/// mixing of the like pairs. Throws InputError naming the types when a like pair needed for
/// mixing is unset.
std::vector<LjCoeff> mix_lj(int ntypes, const std::vector<std::optional<LjCoeff>>& set);

class LjCutPotential final : public Potential {
 public:
  /// `coeff[i * ntypes + j]` for every type pair (see mix_lj); `shift`: pair_modify shift yes.
  LjCutPotential(int ntypes, const std::vector<LjCoeff>& coeff, bool shift);

  std::string style() const override { return "lj/cut"; }
  double cutoff() const override { return cutoff_; }
  void check_types(const Atoms& atoms) const override;
  void compute(Atoms& atoms, const geometry::NeighborList& list, ForceResult& out) override;

 private:
  struct Terms {
    double cutsq, lj1, lj2, lj3, lj4, offset;
  };
  int ntypes_;
  double cutoff_ = 0;
  std::vector<Terms> terms_;  // [i * ntypes + j]
  ThreadScratch scratch_;
};

}  // namespace shockfield::md::potentials

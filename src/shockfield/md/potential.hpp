#pragma once
// The interface every interatomic potential implements, and what a force evaluation returns.
// Conventions (LAMMPS "newton on"): the caller zeroes atoms.f for owned and ghost entries and
// passes a half neighbour list; the potential adds forces to both atoms of a pair, ghosts
// included; the caller then folds ghost forces (and per-atom tallies) back onto their owners.
#include <memory>
#include <string>
#include <vector>

#include "shockfield/core/types.hpp"
#include "shockfield/geometry/neighbor_list.hpp"
#include "shockfield/md/atoms.hpp"

namespace shockfield::md {

struct ForceResult {
  double energy = 0;                   ///< total potential energy, eV
  Voigt6 virial = Voigt6::Zero();      ///< Σ_pairs r_ij ⊗ f_ij (xx yy zz xy xz yz), eV
  bool per_atom = false;               ///< whether the per-atom tallies below are filled
  std::vector<double> energy_atom;     ///< eV, size atoms.size() while computing
  std::vector<Voigt6> virial_atom;     ///< eV, LAMMPS split (half of each pair to each atom)

  /// Zeroes the totals and sizes the per-atom tallies for n entries if `per_atom`.
  void reset(std::size_t n, bool want_per_atom);
};

class Potential {
 public:
  virtual ~Potential() = default;
  /// LAMMPS pair style name ("eam", "eam/alloy", "eam/fs", "lj/cut", "table").
  virtual std::string style() const = 0;
  /// Interaction cutoff, Å.
  virtual double cutoff() const = 0;
  /// Throws InputError when the atoms' types do not fit this potential (count, element names).
  virtual void check_types(const Atoms& atoms) const = 0;
  /// Adds forces, energy and virial for the pairs in `list` (see the conventions above).
  virtual void compute(Atoms& atoms, const geometry::NeighborList& list, ForceResult& out) = 0;
};

}  // namespace shockfield::md

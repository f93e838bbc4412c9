#pragma once
// Test support for tests/unit/md_potentials: atoms from a LAMMPS dump, one complete force
// evaluation (ghosts, half list, evaluate_forces), potentials from TOML text.
#include <filesystem>
#include <memory>
#include <string>

#include "shockfield/core/config.hpp"
#include "shockfield/geometry/box.hpp"
#include "shockfield/md/atoms.hpp"
#include "shockfield/md/potential.hpp"

namespace shockfield::md::potentials::testing {

struct System {
  Atoms atoms;
  geometry::Box box;
};

/// The first frame of a LAMMPS dump (id, type, x, y, z) as owned atoms of mass 1.
System load_dump_system(const std::filesystem::path& file);

/// A potential from a [potential] table given as TOML text (files resolved from tests/).
std::unique_ptr<Potential> potential_from_toml(const std::string& toml, int ntypes);

/// Forces (owned atoms, in order), energy, virial and per-atom tallies of `potential` on a copy
/// of `system`.
struct Evaluation {
  ForceResult result;
  std::vector<Vec3> force;
};
Evaluation evaluate(const System& system, Potential& potential, bool per_atom = true);

/// max_k |a_k - b_k| / max_k |b_k| over all entries: the norm-relative (∞-norm) deviation.
double max_norm_relative(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace shockfield::md::potentials::testing

#pragma once
#include <gtest/gtest.h>

// Test support for tests/unit/md_potentials: atoms from a LAMMPS dump, one complete force
// evaluation (ghosts, half list, evaluate_forces), potentials from TOML text.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"
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

/// The deviations (max_norm_relative) from LAMMPS of one potential on one LAMMPS fixture.
struct LammpsDeviation {
  std::size_t atoms = 0;
  double energy = 0, energy_atom = 0, force = 0, virial_atom = 0, virial = 0;
  void print(const std::string& name) const;
  /// gtest expectations: each deviation below `tolerance`.
  void expect_below(double tolerance) const;
};

/// A known difference from LAMMPS's energy of owned atom i (added to LAMMPS's per-atom and total
/// energies before comparing), given the potential after the evaluation and the atoms.
using EnergyCorrection = std::function<double(const Potential&, const Atoms&, std::size_t i)>;

/// Evaluates the potential of the [potential] TOML `toml` on the atoms of `<base>.dump` (a
/// LAMMPS dump of id type x y z fx fy fz c_pe and the six c_st components of `compute
/// stress/atom NULL virial`) and compares with it and with `<base>.totals` (lines "energy E",
/// "volume V", "pressure_virial p1 .. p6" of `compute pressure NULL virial`).
LammpsDeviation compare_with_lammps(const std::string& base, const std::string& toml,
                                    const EnergyCorrection& correction = {});

/// Runs `f`, expecting an error of type E (InputError by default) whose message contains every
/// fragment.
template <class E = InputError, class F>
void expect_input_error(F&& f, const std::vector<std::string>& fragments) {
  try {
    f();
    ADD_FAILURE() << "no error";
  } catch (const E& e) {
    for (const auto& s : fragments)
      EXPECT_NE(std::string(e.what()).find(s), std::string::npos) << "'" << s << "' not in: " << e.what();
  }
}

}  // namespace shockfield::md::potentials::testing

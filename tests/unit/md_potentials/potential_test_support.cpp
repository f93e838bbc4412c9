#include "unit/md_potentials/potential_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "shockfield/core/units.hpp"
#include "shockfield/geometry/neighbor_list.hpp"
#include "shockfield/io/lammps_dump.hpp"
#include "shockfield/md/force_evaluation.hpp"
#include "shockfield/md/ghosts.hpp"
#include "shockfield/md/potentials/registry.hpp"

namespace shockfield::md::potentials::testing {

System load_dump_system(const std::filesystem::path& file) {
  const auto frames = io::read_dump(file);
  const auto& frame = frames.front();
  System s;
  s.box = frame.box;
  const auto ids = frame.ids();
  const auto types = frame.types();
  const auto x = frame.positions();
  int ntypes = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    s.atoms.add(x[i], types[i] - 1, ids[i]);
    ntypes = std::max(ntypes, types[i]);
  }
  s.atoms.mass.assign(static_cast<std::size_t>(ntypes), 1.0);
  return s;
}

std::unique_ptr<Potential> potential_from_toml(const std::string& toml, int ntypes) {
  const Config root = Config::parse(toml, "test.toml");
  auto potential = make_potential(root.table("potential"), std::filesystem::current_path(), ntypes);
  root.check_unknown_keys();
  return potential;
}

Evaluation evaluate(const System& system, Potential& potential, bool per_atom) {
  System s = system;
  constexpr double skin = 0.5;  // a realistic list: pairs beyond the cutoff must be skipped
  rebuild_ghosts(s.atoms, s.box, potential.cutoff() + skin);
  geometry::NeighborList list;
  build_neighbor_list(s.atoms.x, s.atoms.nlocal, potential.cutoff() + skin, true, list);
  Evaluation e;
  evaluate_forces(s.atoms, potential, list, e.result, per_atom);
  e.force.assign(s.atoms.f.begin(), s.atoms.f.begin() + static_cast<std::ptrdiff_t>(s.atoms.nlocal));
  return e;
}

double max_norm_relative(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0, scale = 0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    diff = std::max(diff, std::abs(a[k] - b[k]));
    scale = std::max(scale, std::abs(b[k]));
  }
  return diff / scale;
}

namespace {

struct Totals {
  double energy = 0, volume = 0;
  Voigt6 pressure_virial = Voigt6::Zero();
};

Totals read_totals(const std::string& file) {
  std::ifstream in(file);
  Totals t;
  std::string key;
  in >> key >> t.energy >> key >> t.volume >> key;
  for (int k = 0; k < 6; ++k) in >> t.pressure_virial[k];
  EXPECT_TRUE(in.good()) << file;
  return t;
}

}  // namespace

void LammpsDeviation::print(const std::string& name) const {
  std::printf("%-18s atoms %4zu  energy %.1e  energy/atom %.1e  force %.1e  virial/atom %.1e  "
              "virial %.1e\n", name.c_str(), atoms, energy, energy_atom, force, virial_atom, virial);
}

void LammpsDeviation::expect_below(double tolerance) const {
  EXPECT_LT(energy, tolerance);
  EXPECT_LT(energy_atom, tolerance);
  EXPECT_LT(force, tolerance);
  EXPECT_LT(virial_atom, tolerance);
  EXPECT_LT(virial, tolerance);
}

LammpsDeviation compare_with_lammps(const std::string& base, const std::string& toml,
                                    const EnergyCorrection& correction) {
  const System system = load_dump_system(base + ".dump");
  const auto frame = io::read_dump(base + ".dump").front();
  const Totals totals = read_totals(base + ".totals");
  auto potential = potential_from_toml(toml, system.atoms.ntypes());
  potential->check_types(system.atoms);
  const Evaluation ours = evaluate(system, *potential);

  const std::size_t n = system.atoms.nlocal;
  std::vector<double> f, f_ref, e, e_ref, v, v_ref;
  double energy_ref = totals.energy;
  const char* fcol[3] = {"fx", "fy", "fz"};
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 3; ++d) {
      f.push_back(ours.force[i][d]);
      f_ref.push_back(frame.column(fcol[d])[i]);
    }
    e.push_back(ours.result.energy_atom[i]);
    const double shift = correction ? correction(*potential, system.atoms, i) : 0.0;
    e_ref.push_back(frame.column("c_pe")[i] + shift);
    energy_ref += shift;
    for (int k = 0; k < 6; ++k) {
      // compute stress/atom NULL virial = -virial in bar·Å³.
      v.push_back(ours.result.virial_atom[i][k]);
      v_ref.push_back(-frame.column("c_st[" + std::to_string(k + 1) + "]")[i] / units::metal::nktv2p);
    }
  }
  std::vector<double> vt, vt_ref;
  for (int k = 0; k < 6; ++k) {
    vt.push_back(ours.result.virial[k]);
    vt_ref.push_back(totals.pressure_virial[k] * totals.volume / units::metal::nktv2p);
  }
  LammpsDeviation d;
  d.atoms = n;
  d.energy = std::abs(ours.result.energy - energy_ref) / std::abs(energy_ref);
  d.energy_atom = max_norm_relative(e, e_ref);
  d.force = max_norm_relative(f, f_ref);
  d.virial_atom = max_norm_relative(v, v_ref);
  d.virial = max_norm_relative(vt, vt_ref);
  return d;
}

}  // namespace shockfield::md::potentials::testing

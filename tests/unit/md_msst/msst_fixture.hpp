#pragma once
// MSST runs from the LAMMPS data files of tests/fixtures/lammps_msst (regenerate.sh there) and
// the reference thermo rows of LAMMPS `fix msst` on the same start (1 MPI rank) and on 2 ranks
// (the spread between the two is LAMMPS's own round-off growth).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../md/lammps_thermo_rows.hpp"
#include "../md/md_fixture.hpp"
#include "shockfield/core/units.hpp"
#include "shockfield/io/lammps_data.hpp"
#include "shockfield/md/fixes/msst.hpp"

namespace shockfield::md::msst_test {

/// The columns of <name>.thermo (in.msst's thermo_style).
enum Column { kStep, kTemp, kPe, kKe, kEtotal, kPress, kPxx, kPyy, kPzz, kVol, kLz, kEconserve, kFmsst,
              kDhug, kDray, kLgrVel, kLgrPos, kColumns };
inline const std::array<const char*, kColumns> kColumnNames{
    "step", "temp", "pe", "ke", "etotal", "press", "pxx", "pyy", "pzz", "vol", "lz", "econserve", "f_msst",
    "dhugoniot", "drayleigh", "lagrangian_speed", "lagrangian_position"};
using Row = lammps_rows::Row<kColumns>;

inline std::vector<Row> read_thermo(const std::string& file) {
  return lammps_rows::read<kColumns>("lammps_msst/" + file);
}

/// A simulation from <name>.data with shockfield's defaults as in in.msst (dt 1 fs, skin 2 Å).
inline Simulation from_data(const std::string& name) {
  io::DataFile data = io::read_data("fixtures/lammps_msst/" + name + ".data");
  for (auto& m : data.atoms.mask) m = 1u;
  return Simulation(data.box, std::move(data.atoms), fixture::cu_eam(), 0.001, 2.0);
}

/// in.msst's `fix msst z 60 q Q mu MU tscale 0.01`.
inline MsstSettings settings(double q, double mu, std::int64_t steps) {
  MsstSettings s;
  s.axis = 2;
  s.shock_speed = 60.0;
  s.q = q;
  s.mu = mu;
  s.tscale = 0.01;
  s.stage_steps = steps;
  return s;
}

/// Our row in the reference's columns.
inline Row thermo_row(const Simulation& sim, const FixMsst& fix) {
  const ThermoState t = sim.thermo();
  const MsstQuantities q = fix.quantities(sim);
  const double etotal = t.kinetic + t.potential;
  return {static_cast<double>(sim.step), t.temperature, t.potential, t.kinetic, etotal, t.pressure,
          t.pressure_tensor[0], t.pressure_tensor[1], t.pressure_tensor[2], t.volume, sim.box.length().z(),
          etotal + q.energy, q.energy, q.dhugoniot, q.drayleigh, q.lagrangian_speed, q.lagrangian_position};
}

/// Runs the msst fix from <name>.data and returns our rows at the reference's steps.
inline std::vector<Row> run_msst(const std::string& name, const MsstSettings& s, int every) {
  Simulation sim = from_data(name);
  sim.fixes.push_back(std::make_unique<FixMsst>(s));
  sim.setup(false);
  sim.fixes[0]->setup(sim);
  const auto& fix = static_cast<const FixMsst&>(*sim.fixes[0]);
  std::vector<Row> rows{thermo_row(sim, fix)};
  for (std::int64_t k = 1; k <= s.stage_steps; ++k) {
    sim.advance([](std::int64_t) { return false; });
    if (k % every == 0) rows.push_back(thermo_row(sim, fix));
  }
  return rows;
}

/// Our rows against LAMMPS's <name>.thermo and <name>_np2.thermo (lammps_thermo_rows.hpp).
inline void expect_follows_lammps(const std::vector<Row>& ours, const std::string& name, double factor,
                                  double floor_rel) {
  lammps_rows::expect_follows(ours, read_thermo(name + ".thermo"), read_thermo(name + "_np2.thermo"), kColumnNames,
                              factor, floor_rel);
}

}  // namespace shockfield::md::msst_test

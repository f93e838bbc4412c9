#pragma once
// Hugoniostat runs from the 512-atom Cu start of tests/fixtures/lammps_msst (cu_512.data) and the
// reference thermo rows of LAMMPS `fix nphug` on it (tests/fixtures/lammps_nphug/regenerate.sh),
// on 1 MPI rank and on 2 (the spread between the two is LAMMPS's own round-off growth).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../md_msst/msst_fixture.hpp"
#include "shockfield/md/fixes/nphug.hpp"

namespace shockfield::md::nphug_test {

/// The columns of <case>.thermo (in.nphug's thermo_style).
enum Column { kStep, kTemp, kPe, kKe, kEtotal, kPress, kPxx, kPyy, kPzz, kVol, kLz, kEconserve, kFhug, kDhug, kUs,
              kUp, kColumns };
inline const std::array<const char*, kColumns> kColumnNames{
    "step", "temp", "pe", "ke", "etotal", "press", "pxx", "pyy", "pzz", "vol", "lz", "econserve", "f_hug", "dhugoniot",
    "us", "up"};
using Row = lammps_rows::Row<kColumns>;

inline std::vector<Row> read_thermo(const std::string& file) {
  return lammps_rows::read<kColumns>("lammps_nphug/" + file);
}

/// in.nphug's `fix hug all nphug temp 1 1 0.1 <style> 200000 200000 0.5 tchain <tchain> pchain
/// <pchain>`: style "z" (uniaxial) or "iso".
inline NphugSettings settings(const std::string& style, std::int64_t steps, int tchain = 1, int pchain = 0) {
  NphugSettings s;
  s.npt.damping = 0.1;
  s.npt.pressure = 200000.0;
  s.npt.pressure_damping = 0.5;
  s.npt.chain = tchain;
  s.npt.pressure_chain = pchain;
  if (style == "iso") {
    s.npt.iso = true;
  } else {
    s.axis = 2;
    s.npt.dims = {false, false, true};
  }
  s.stage_steps = steps;
  return s;
}

/// Our row in the reference's columns (econserve = K + U + the fix's extended energy).
inline Row thermo_row(const Simulation& sim, const FixNphug& fix) {
  const ThermoState t = sim.thermo();
  const NphugQuantities q = fix.quantities(sim);
  const double etotal = t.kinetic + t.potential;
  return {static_cast<double>(sim.step), t.temperature, t.potential, t.kinetic, etotal, t.pressure,
          t.pressure_tensor[0], t.pressure_tensor[1], t.pressure_tensor[2], t.volume, sim.box.length().z(),
          etotal - fix.energy_added(), -fix.energy_added(), q.dhugoniot, q.us, q.up};
}

/// Runs the Hugoniostat from lammps_msst/<data>.data; our rows every `every` steps (and step 0).
inline std::vector<Row> run_nphug(const NphugSettings& s, int every, Simulation* out = nullptr,
                                  const std::string& data = "cu_512") {
  Simulation sim = msst_test::from_data(data);
  sim.fixes.push_back(std::make_unique<FixNphug>(s));
  sim.setup(false);
  sim.fixes[0]->setup(sim);
  const auto& fix = static_cast<const FixNphug&>(*sim.fixes[0]);
  std::vector<Row> rows{thermo_row(sim, fix)};
  for (std::int64_t k = 1; k <= s.stage_steps; ++k) {
    sim.advance([](std::int64_t) { return false; });
    if (k % every == 0) rows.push_back(thermo_row(sim, fix));
  }
  if (out) *out = std::move(sim);
  return rows;
}

/// Our rows against LAMMPS's <name>.thermo and <name>_np2.thermo (lammps_thermo_rows.hpp).
inline void expect_follows_lammps(const std::vector<Row>& ours, const std::string& name, double factor,
                                  double floor_rel) {
  lammps_rows::expect_follows(ours, read_thermo(name + ".thermo"), read_thermo(name + "_np2.thermo"), kColumnNames,
                              factor, floor_rel);
}

}  // namespace shockfield::md::nphug_test

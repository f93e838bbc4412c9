#pragma once
// Copper systems under FixNoseHooverNpt and the LAMMPS `fix npt` reference of
// tests/fixtures/lammps_npt (regenerate.sh there).
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "../md/md_fixture.hpp"
#include "shockfield/md/fixes/nose_hoover_npt.hpp"
#include "shockfield/md/velocity.hpp"

namespace shockfield::md::npt_test {

/// 300 K, τ_T = 0.1 ps, τ_P = 0.5 ps (the LAMMPS reference's) at `pressure` (bar).
inline NptSettings settings(double pressure, bool iso, std::array<bool, 3> dims = {true, true, true}) {
  NptSettings s;
  s.temperature = 300;
  s.damping = 0.1;
  s.pressure = pressure;
  s.pressure_damping = 0.5;
  s.iso = iso;
  s.dims = dims;
  return s;
}

/// n³ fcc cells of Cu_u3 copper at lattice constant a0 with velocities at `temperature`, an npt
/// fix set up as run_case does, dt = 2 fs (the LAMMPS reference's).
inline Simulation copper_npt(int n, double a0, double temperature, const NptSettings& settings,
                             std::uint64_t seed = 4928459) {
  geometry::Box box;
  Atoms atoms = fixture::fcc_atoms(a0, {n, n, n}, box, 63.55);
  create_velocities(atoms, temperature, seed);
  Simulation sim(box, std::move(atoms), fixture::cu_eam(), 0.002, 1.0);
  sim.fixes.push_back(std::make_unique<FixNoseHooverNpt>(settings));
  sim.setup(false);
  sim.fixes[0]->setup(sim);
  return sim;
}

inline void run(Simulation& sim, int steps) {
  for (int k = 0; k < steps; ++k) sim.advance([](std::int64_t) { return false; });
}

/// KE + PE − energy_added (the thermo column econserved), eV.
inline double econserved(const Simulation& sim) {
  return sim.kinetic_energy() + sim.forces.energy - sim.fixes[0]->energy_added();
}

/// A mean and its standard error.
struct Estimate {
  double mean = 0, error = 0;
};

/// Mean of `samples` and its standard error from `blocks` block averages (the same estimator as
/// regenerate.sh applies to the LAMMPS series).
inline Estimate block_estimate(const std::vector<double>& samples, int blocks) {
  Estimate e;
  for (double s : samples) e.mean += s / static_cast<double>(samples.size());
  const std::size_t per = samples.size() / static_cast<std::size_t>(blocks);
  double ss = 0;
  for (int b = 0; b < blocks; ++b) {
    double m = 0;
    for (std::size_t i = b * per; i < (b + 1) * per; ++i) m += samples[i] / static_cast<double>(per);
    ss += (m - e.mean) * (m - e.mean);
  }
  e.error = std::sqrt(ss / (blocks - 1) / blocks);
  return e;
}

/// The `<name>.ref` summary of a LAMMPS reference run: key → (mean, standard error).
inline std::map<std::string, Estimate> lammps_reference(const std::string& name) {
  std::ifstream in("fixtures/lammps_npt/" + name + ".ref");
  if (!in) throw std::runtime_error("missing fixtures/lammps_npt/" + name + ".ref (run the tests from tests/)");
  std::map<std::string, Estimate> ref;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key;
    Estimate e;
    words >> key >> e.mean >> e.error;
    ref[key] = e;
  }
  return ref;
}

}  // namespace shockfield::md::npt_test

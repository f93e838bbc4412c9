// Peridynamics benchmark: bond-updates per second (family bonds × steps / loop time) of the PMB
// and LPS force laws in the velocity-Verlet loop, on 1 and 2 threads, on the work of
// bench/lammps/in.peri_bench (an n³ simple-cubic lattice, lc = 0.5 mm, δ = 3.0002·lc, displaced
// by up to 0.2 µm, halves pulled apart at ±10 m/s, critical stretch 0.002), with LAMMPS's
// short-range contact force on ("pmb", "lps": LAMMPS always applies it) and off
// ("pmb-nocontact", "lps-nocontact"); also the
// correspondence model with the crystal law, one grain per point ("crystal") and 8 Taylor grains
// per point ("crystal8": grain-updates/s = 8 × point-steps/s). bench/run_pd_bench.sh runs LAMMPS
// on the same work and prints the ratios.
// Usage: pd_bench [n (default 30)] [steps (default 50)] [models, comma-separated (default all:
// pmb,pmb-nocontact,lps,lps-nocontact,crystal,crystal8)].
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "shockfield/core/rng.hpp"
#include "shockfield/materials/strength/crystal_lattice.hpp"
#include "shockfield/pd/bond_force.hpp"
#include "shockfield/pd/correspondence.hpp"
#include "shockfield/pd/crystal_material.hpp"
#include "shockfield/pd/simulation.hpp"

using namespace shockfield;
using namespace shockfield::pd;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double kSpacing = 0.0005, kHorizon = 0.0015001, kDensity = 2200.0, kDt = 1.0e-7, kCopperDensity = 8960.0;

// Loop time of `steps` steps of dt after setup, with the in.peri_bench displacement and velocities;
// `cpu` receives the process CPU time of the loop (on one thread the figure that a loaded
// machine does not inflate).
double loop_seconds(Simulation& sim, int steps, double dt, double& cpu) {
  sim.setup();  // LAMMPS's "run 1" of the resting lattice
  const double middle = 0.5 * sim.cloud().bounds().second[0];
  for (std::size_t i = 0; i < sim.cloud().size(); ++i) {
    for (int d = 0; d < 3; ++d) sim.positions()[i][d] += 2.0e-7 * (2.0 * rng::uniform(4928459, i, d) - 1.0);
    sim.velocities()[i] = Vec3(sim.cloud().x[i][0] <= middle ? -10.0 : 10.0, 0.0, 0.0);
  }
  sim.setup();
  const auto t0 = Clock::now();
  const std::clock_t c0 = std::clock();
  for (int k = 0; k < steps; ++k) sim.step(dt);
  cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::unique_ptr<ForceModel> make_model(const std::string& name, const PointCloud& cloud, const Family& family) {
  const CriticalStretch damage{0.0020, 0.25};
  const bool contact = !name.ends_with("-nocontact");
  if (name.starts_with("pmb"))
    return std::make_unique<PmbForce>(cloud, family, PmbModel{1.6863e22}, Influence(), damage, contact);
  if (name.starts_with("lps"))
    return std::make_unique<LpsForce>(cloud, family, LpsModel{14.9e9, 8.94e9}, Influence(Influence::Kind::inverse),
                                      damage, contact);
  // Table 1 copper: one grain, [111] along x ("crystal"), or 8 random grains per point under the
  // Taylor assumption ("crystal8", eqs. 42-43).
  std::vector<Mat3> grains{materials::rotation_loading_along(Vec3(1, 1, 1))};
  if (name == "crystal8")
    for (std::uint64_t k = 1; k < 8; ++k) {
      const Vec3 a = materials::random_bunge_angles(11, k);
      grains.push_back(materials::bunge_rotation(a[0], a[1], a[2]));
    }
  const CrystalMaterial m{kCopperDensity, {materials::CrystalViscoplasticity::ofhc_copper(), grains}, 0.0};
  return std::make_unique<CorrespondenceForce<CrystalMaterial>>(cloud, family, std::vector<CrystalMaterial>(1, m), Influence(),
                                                                CorrespondenceOptions{true, 0.0});
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  const int n = argc > 1 ? std::atoi(argv[1]) : 30;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 50;
  const std::string models = argc > 3 ? argv[3] : "pmb,pmb-nocontact,lps,lps-nocontact,crystal,crystal8";
  const PointCloud cloud = lattice_cloud(3, {n, n, n}, kSpacing);
  const Family family = build_family(cloud, kHorizon, VolumeCorrection::linear);
  std::printf("PD %d^3 lattice: %zu points, %zu bonds (both directions), %d steps\n", n, cloud.size(), family.bonds(),
              steps);
  std::printf("| model | threads | loop s | bond-updates/s | point-steps/s | cpu s |\n|---|---|---|---|---|---|\n");
  for (const std::string name : {"pmb", "pmb-nocontact", "lps", "lps-nocontact", "crystal", "crystal8"}) {
    if (("," + models + ",").find("," + name + ",") == std::string::npos) continue;
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      const bool crystal = name.starts_with("crystal");
      Simulation sim(cloud, family, make_model(name, cloud, family), {crystal ? kCopperDensity : kDensity});
      // The crystal (copper, 186 GPa) needs a shorter step than LAMMPS's 1e-7 s.
      double cpu = 0.0;
      const double s = loop_seconds(sim, steps, std::min(kDt, 0.5 * sim.stable_step()), cpu);
      const double updates = static_cast<double>(steps);
      std::printf("| %s | %d | %.3f | %.3g | %.3g | %.3f |\n", name.c_str(), threads, s,
                  updates * static_cast<double>(family.bonds()) / s, updates * static_cast<double>(cloud.size()) / s, cpu);
    }
  }
}

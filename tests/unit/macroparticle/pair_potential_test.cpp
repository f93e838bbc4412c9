// The macroparticle pair style inside the MD engine (reduced units r0 = D = 1): forces are
// −dE/dx by finite differences on a disordered cluster, a bulk particle holds −6D (eq 10), and
// the engine's strain–stress elastic constants of the fcc packing are the nearest-neighbour
// central-force ones (Cauchy: C12 = C44, C11 = 2 C12; ν = 1/3 along [001]).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "shockfield/core/units.hpp"
#include "shockfield/macroparticle/pair_potential.hpp"
#include "shockfield/md/elastic_constants.hpp"
#include "shockfield/md/force_evaluation.hpp"
#include "shockfield/md/simulation.hpp"
#include "unit/md/md_fixture.hpp"

namespace shockfield::macroparticle {
namespace {

constexpr double kCutoff = 1.2071;  // between the first (1) and second (√2) shells

double total_energy(md::Simulation& sim) {
  sim.rebuild();
  md::evaluate_forces(sim.atoms, *sim.potential, sim.list, sim.forces, false);
  return sim.forces.energy;
}

md::Simulation fcc_block(double p, double q, std::array<int, 3> n, geometry::Boundary b) {
  geometry::Box box;
  md::Atoms atoms = md::fixture::fcc_atoms(std::numbers::sqrt2, n, box, 1.0, {b, b, b});
  return md::Simulation(box, std::move(atoms), std::make_unique<MacroparticlePotential>(p, q, kCutoff), 0.01, 0.1);
}

TEST(MacroparticlePotential, ForcesAreMinusTheEnergyGradient) {
  for (auto [p, q] : {std::pair{4.0, 9.0}, std::pair{3.5, 8.25}}) {  // the integer and the pow path
    md::Simulation sim = fcc_block(p, q, {3, 3, 3}, geometry::Boundary::shrink);
    md::fixture::perturb(sim.atoms, 0.04, 7);
    total_energy(sim);
    const std::vector<Vec3> f = {sim.atoms.f.begin(), sim.atoms.f.begin() + static_cast<long>(sim.atoms.nlocal)};
    const double h = 1e-6;
    double worst = 0, scale = 0;
    for (std::size_t i = 0; i < sim.atoms.nlocal; i += 7) {
      for (int d = 0; d < 3; ++d) {
        const double x0 = sim.atoms.x[i][d];
        sim.atoms.x[i][d] = x0 + h;
        const double ep = total_energy(sim);
        sim.atoms.x[i][d] = x0 - h;
        const double em = total_energy(sim);
        sim.atoms.x[i][d] = x0;
        worst = std::max(worst, std::abs(-(ep - em) / (2 * h) - f[i][d]));
        scale = std::max(scale, std::abs(f[i][d]));
      }
    }
    // Central differences: truncation ~h²·φ''' ≈ 1e-10, round-off ~1e-16·|E|/h ≈ 1e-8 (|E| ≈ 600).
    EXPECT_LT(worst, 1e-6 * std::max(scale, 1.0)) << p << " " << q;
    EXPECT_GT(scale, 0.1);  // the perturbation makes real forces
  }
}

TEST(MacroparticlePotential, EveryExponentPathGivesTheEnergyOfEq5) {
  // Table 1's (p, q) take compile-time chains, (7, 11) the loop, (3.5, 8.25) std::pow: each must
  // give the pair sum of φ = [p r^-q − q r^-p]/(q − p) by std::pow over the perturbed cluster
  // (the pairs closer than the cutoff), to round-off (1e-13 relative over ~300 bonds).
  for (auto [p, q] : {std::pair{3.0, 9.0}, {4.0, 8.0}, {4.0, 9.0}, {4.0, 10.0}, {5.0, 9.0}, {5.0, 10.0}, {6.0, 12.0},
                      {7.0, 11.0}, {3.5, 8.25}}) {
    md::Simulation sim = fcc_block(p, q, {3, 3, 3}, geometry::Boundary::shrink);
    md::fixture::perturb(sim.atoms, 0.04, 7);
    const double engine = total_energy(sim);
    double direct = 0;
    for (std::size_t i = 0; i < sim.atoms.nlocal; ++i)
      for (std::size_t j = i + 1; j < sim.atoms.nlocal; ++j) {
        const double r = (sim.atoms.x[i] - sim.atoms.x[j]).norm();
        if (r < kCutoff) direct += (p * std::pow(r, -q) - q * std::pow(r, -p)) / (q - p);
      }
    EXPECT_NEAR(engine / direct, 1.0, 1e-13) << p << " " << q;
  }
}

TEST(MacroparticlePotential, ABulkParticleHoldsSixBondEnergies) {
  md::Simulation sim = fcc_block(4, 9, {3, 3, 3}, geometry::Boundary::periodic);
  const double e = total_energy(sim);
  EXPECT_NEAR(e / static_cast<double>(sim.atoms.nlocal), -6.0, 1e-12);
  EXPECT_LT(sim.forces.virial.cwiseAbs().maxCoeff(), 1e-10);  // stress free at r0
}

TEST(MacroparticlePotential, EngineElasticConstantsAreTheCauchyNearestNeighbourOnes) {
  md::CubicCrystal crystal;
  crystal.lattice.a0 = std::numbers::sqrt2;  // already relaxed: the box relaxation only confirms it
  crystal.mass = {1.0};
  crystal.type_names = {""};
  md::ElasticSettings settings;
  settings.repeat = {3, 3, 3};
  settings.fire_timestep = 0.05;
  const auto c = md::cubic_elastic_constants(
      crystal, [] { return std::make_unique<MacroparticlePotential>(4.0, 9.0, kCutoff); }, settings);
  // GPa back to engine units (eV/Å³ = D/r0³): k = pq = 36, C11 = √2 k, C12 = C44 = k/√2.
  const double to_reduced = 1.0 / (units::metal::nktv2p * units::metal::bar_to_GPa);
  const double k = 36.0;
  EXPECT_NEAR(c.a0, std::numbers::sqrt2, 1e-6);
  EXPECT_NEAR(c.cohesive_energy, -6.0, 1e-9);
  // 1e-3 strain central differences: the O(ε²) error is ~1e-6 relative, allow 1e-4.
  EXPECT_NEAR(c.c11 * to_reduced / (std::numbers::sqrt2 * k), 1.0, 1e-4);
  EXPECT_NEAR(c.c12 * to_reduced / (k / std::numbers::sqrt2), 1.0, 1e-4);
  EXPECT_NEAR(c.c44 * to_reduced / (k / std::numbers::sqrt2), 1.0, 1e-4);
  EXPECT_NEAR(c.c12 / (c.c11 + c.c12), 1.0 / 3.0, 1e-4);
}

}  // namespace
}  // namespace shockfield::macroparticle

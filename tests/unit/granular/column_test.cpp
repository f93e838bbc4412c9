// The 2D column of spheres (granular/column.hpp, on the MD engine's atoms, neighbour list and pair
// loop) against LAMMPS: 143 steel spheres in a box with walls under gravity, the top row pushed
// down at 0.5 m/s, run by LAMMPS (gran/hertz/history and fix wall/gran hertz/history without
// damping or tangential force, fix gravity, fix nve, fix enforce2d) and by Column at the same
// step; and the column's energy conservation. Fixture and script: fixtures/lammps_granular_column/
// (make_data.py, in.column, dump.column, regenerate.sh).
#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "shockfield/core/error.hpp"
#include "shockfield/granular/column.hpp"
#include "shockfield/granular/contact_law.hpp"
#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::granular {
namespace {

// in.column's box and spheres (R = 1 mm steel), the spheres of the dump's first frame.
Column lammps_column(const io::DumpFrame& first, double time_step) {
  ColumnSpec spec;
  spec.types = {SphereType{}};
  spec.right = 0.02002;
  spec.time_step = time_step;
  md::Atoms atoms;
  const auto& x = first.column("x");
  const auto& y = first.column("y");
  const auto& vy = first.column("vy");
  const auto ids = first.ids();
  for (std::size_t r = 0; r < first.natoms(); ++r)
    atoms.add(Vec3(x[r], y[r], 0.0), 0, ids[r], Vec3(0.0, vy[r], 0.0));
  return Column(spec, std::move(atoms));
}

TEST(GranularColumn, TrajectoriesOfEverySphereMatchLammpsGranHertzHistory) {
  const auto frames = io::read_dump("fixtures/lammps_granular_column/dump.column");
  ASSERT_EQ(frames.size(), 11u);
  ASSERT_EQ(frames[0].natoms(), 143u);
  const auto run = [&](int threads) {
    omp_set_num_threads(threads);
    Column column = lammps_column(frames[0], 5e-8);
    const double e0 = column.total_energy();
    double worst_x = 0, worst_v = 0, x_scale = 0, v_scale = 0, drift = 0;
    for (const auto& frame : frames) {
      while (column.step_count() < frame.timestep) {
        column.step();
        drift = std::max(drift, std::abs(column.total_energy() - e0) / e0);
      }
      const auto& x = frame.column("x");
      const auto& y = frame.column("y");
      const auto& vx = frame.column("vx");
      const auto& vy = frame.column("vy");
      const auto& x0 = frames[0].column("x");
      const auto& y0 = frames[0].column("y");
      const md::Atoms& s = column.spheres();
      for (std::size_t r = 0; r < frame.natoms(); ++r) {
        // Atoms are added in id order, so sphere r is id r + 1 in both.
        worst_x = std::max({worst_x, std::abs(x[r] - s.x[r].x()), std::abs(y[r] - s.x[r].y())});
        worst_v = std::max({worst_v, std::abs(vx[r] - s.v[r].x()), std::abs(vy[r] - s.v[r].y())});
        x_scale = std::max({x_scale, std::abs(x[r] - x0[r]), std::abs(y[r] - y0[r])});
        v_scale = std::max({v_scale, s.v[r].norm()});
        EXPECT_EQ(s.x[r].z(), 0.0);
      }
    }
    omp_set_num_threads(1);
    std::printf("%d threads: max |Δx| / max displacement = %.3g, max |Δv| / max |v| = %.3g, "
                "energy drift %.3g, %lld list builds\n",
                threads, worst_x / x_scale, worst_v / v_scale, drift, column.neighbor_builds());
    return std::array<double, 3>{worst_x / x_scale, worst_v / v_scale, drift};
  };
  // Same integrator and step, the same Hertz law for pairs and walls: the difference is round-off
  // carried through 5000 steps of contacts opening and closing. Measured 1.2e-8 of the largest
  // displacement and 5.6e-8 of the largest speed, on 1 and 2 threads; a κ off by 1e-4 (kn ×
  // 1.0001 in in.column, checked by hand) gives 2.7e-2 and 6.6e-2, so 1e-6 tells a model
  // difference from round-off. The total energy (kinetic + contacts + walls + gravity, 7.3e-4 J)
  // stays within Verlet's error at this step: measured 3.3e-6 of it at most (6e-5 of the push's
  // kinetic energy).
  for (int threads : {1, 2}) {
    const auto [dx, dv, drift] = run(threads);
    EXPECT_LT(dx, 1e-6);
    EXPECT_LT(dv, 1e-6);
    EXPECT_LT(drift, 1e-5);
  }
}

// Hertz's impact (Johnson, Contact Mechanics, 1985, §11.4): a body of mass μ meeting an elastic
// contact F = κ δ^{3/2} at relative speed u compresses it to δ_m = (5μu²/(4κ))^{2/5} and leaves it
// after t_c = 2 (δ_m/u) ∫₀¹ dx/√(1 − x^{5/2}) = 2 (δ_m/u) · 0.4 B(2/5, 1/2) ≈ 2.943 δ_m/u, at
// the same speed.
double hertz_contact_time(double mu, double u, double kappa) {
  const double delta_max = std::pow(5.0 * mu * u * u / (4.0 * kappa), 0.4);
  return 2.0 * delta_max / u * 0.4 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
}

TEST(GranularColumn, ImpactsLastHertzsContactTimeAndRestoreTheSpeed) {
  // Without gravity: sphere 1 hits the floor at 0.3 m/s; spheres 2 and 3 meet head-on at ±0.2 m/s
  // (relative 0.4 m/s, reduced mass m/2, far from the walls). The contact lasts Hertz's t_c
  // (6.79 µs and 7.37 µs here) to the step (5e-10 s: 7e-5 of t_c) and each sphere leaves at its
  // speed reversed (velocity Verlet conserves the energy of an impact to O(Δt²): 1e-6).
  const SphereType steel;
  ColumnSpec spec;
  spec.types = {steel};
  spec.right = 0.05;
  spec.gravity = 0.0;
  spec.time_step = 5e-10;
  const double R = steel.radius;
  md::Atoms atoms;
  atoms.add(Vec3(0.01, R + 1e-7, 0.0), 0, 1, Vec3(0.0, -0.3, 0.0));
  atoms.add(Vec3(0.03 - R - 1e-7, 0.02, 0.0), 0, 2, Vec3(0.2, 0.0, 0.0));
  atoms.add(Vec3(0.03 + R + 1e-7, 0.02, 0.0), 0, 3, Vec3(-0.2, 0.0, 0.0));
  Column column(spec, std::move(atoms));
  const md::Atoms& s = column.spheres();
  const double m = s.mass[0];
  const double wall_kappa = hertz_kappa(steel.youngs_modulus, steel.poisson_ratio, R, INFINITY, 0.0, INFINITY);
  const double pair_kappa = hertz_kappa(steel.youngs_modulus, steel.poisson_ratio, R, steel.youngs_modulus,
                                        steel.poisson_ratio, R);
  double floor_time = 0, pair_time = 0;
  while (column.time() < 1.2e-5) {  // the contacts begin at 0.33 and 0.5 µs
    column.step();
    if (s.x[0].y() < R) floor_time += spec.time_step;
    if (s.x[2].x() - s.x[1].x() < 2 * R) pair_time += spec.time_step;
  }
  EXPECT_NEAR(floor_time / hertz_contact_time(m, 0.3, wall_kappa), 1.0, 2e-4);
  EXPECT_NEAR(pair_time / hertz_contact_time(0.5 * m, 0.4, pair_kappa), 1.0, 2e-4);
  EXPECT_NEAR(s.v[0].y(), 0.3, 1e-6 * 0.3);
  EXPECT_NEAR(s.v[1].x(), -0.2, 1e-6 * 0.2);
  EXPECT_NEAR(s.v[2].x(), 0.2, 1e-6 * 0.2);
  std::printf("floor %.6g s (Hertz %.6g), pair %.6g s (Hertz %.6g), speeds %.9g %.9g\n", floor_time,
              hertz_contact_time(m, 0.3, wall_kappa), pair_time, hertz_contact_time(0.5 * m, 0.4, pair_kappa),
              s.v[0].y(), s.v[1].x());
}

TEST(GranularColumn, RefusesSpheresOutsideTheBoxAndTypesThatMakeNoSphere) {
  ColumnSpec spec;
  spec.types = {SphereType{}};
  spec.right = 0.01;
  spec.time_step = 1e-8;
  const auto refused = [&](const ColumnSpec& c, const Vec3& x, int type, const std::string& said) {
    md::Atoms atoms;
    atoms.add(x, type, 1);
    try {
      Column column(c, std::move(atoms));
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(said), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted; expected: " << said;
  };
  md::Atoms fine;
  fine.add(Vec3(0.005, 0.002, 0.0), 0, 1);
  EXPECT_NO_THROW(Column(spec, std::move(fine)));
  refused(spec, Vec3(0.02, 0.002, 0.0), 0, "outside the column's box");
  refused(spec, Vec3(0.005, 0.002, 1e-3), 0, "outside the column's box");
  refused(spec, Vec3(0.005, 0.002, 0.0), 1, "has type 2");
  ColumnSpec bad = spec;
  bad.types[0].radius = 0.0;
  refused(bad, Vec3(0.005, 0.002, 0.0), 0, "radius");
  bad = spec;
  bad.time_step = 0.0;
  refused(bad, Vec3(0.005, 0.002, 0.0), 0, "time step");
}

}  // namespace
}  // namespace shockfield::granular

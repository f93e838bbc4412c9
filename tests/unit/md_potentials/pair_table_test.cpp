// pair_style table (md/potentials/pair_table.hpp):
// 1. Against LAMMPS 29 Sep 2021 on the same table file and atoms (fixtures/lammps_table,
//    regenerate.sh): 864 atoms of two types, Morse tables given with an r column (+ FPRIME), R and
//    RSQ, linear and spline, N = 1000 and 300, default and explicit cutoffs, and compressed to
//    pairs a few nodes from the tables' inner ends (their end conditions). The fixture prints
//    %.17g, so the deviations are the round-off of sums taken in another order (measured ≤ 2e-14,
//    docs/md-potentials.md): criterion 1e-12 (∞-norm relative, as lammps_crosscheck_test.cpp).
// 2. An LJ table in r² with N points read as the inner table (linear, RSQ, n = N) equals lj/cut
//    to linear interpolation's error, pair by pair: for g = F/r or E as functions of s = r²,
//    |g_table(s) − g(s)| ≤ (s − s_k)(s_{k+1} − s)/2 · max_[s_k, s_k+1] |g''|, and for LJ
//    g''(s) = 2688 εσ¹² s⁻⁹ − 480 εσ⁶ s⁻⁶ (F/r), 168 εσ¹² s⁻⁸ − 48 εσ⁶ s⁻⁵ (E), each term
//    largest in magnitude at s_k. Forces on an atom: Σ_j r_ij · bound_ij; the energy: Σ pairs.
// 3. NVE with a table conserves energy.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "shockfield/core/error.hpp"
#include "shockfield/md/fixes/nve.hpp"
#include "shockfield/md/potentials/pair_table_file.hpp"
#include "shockfield/md/velocity.hpp"
#include "support/scratch_path.hpp"
#include "unit/md/md_fixture.hpp"
#include "unit/md_potentials/potential_test_support.hpp"

namespace shockfield::md::potentials::testing {
namespace {

constexpr double kLammpsTolerance = 1e-12;

std::string table_toml(const std::string& interpolation, int points, const std::string& cut11,
                       const std::string& cut22, const std::string& cut12) {
  const auto pair = [](const char* types, const char* keyword, const std::string& cut) {
    return fmt::format("[[potential.pair]]\ntypes = {}\nkeyword = \"{}\"\n{}", types, keyword,
                       cut.empty() ? "" : "cutoff = " + cut + "\n");
  };
  return fmt::format("[potential]\nstyle = \"table\"\ninterpolation = \"{}\"\npoints = {}\n"
                     "file = \"fixtures/lammps_table/pair.table\"\n",
                     interpolation, points) +
         pair("[1, 1]", "M11", cut11) + pair("[2, 2]", "M22", cut22) + pair("[1, 2]", "M12", cut12);
}

struct Case {
  std::string name;
  std::string toml;
};

std::ostream& operator<<(std::ostream& os, const Case& c) { return os << c.name; }

class PairTableLammps : public ::testing::TestWithParam<Case> {};

TEST_P(PairTableLammps, EnergyForcesAndVirialEqualLammps) {
  const Case& c = GetParam();
  const LammpsDeviation d = compare_with_lammps("fixtures/lammps_table/" + c.name, c.toml);
  d.print(c.name);
  d.expect_below(kLammpsTolerance);
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, PairTableLammps,
    ::testing::Values(Case{"linear_1000", table_toml("linear", 1000, "", "", "")},
                      Case{"spline_1000", table_toml("spline", 1000, "", "", "")},
                      Case{"linear_300_cut", table_toml("linear", 300, "6.5", "6.0", "6.8")},
                      Case{"spline_300_cut", table_toml("spline", 300, "6.5", "6.0", "6.8")},
                      Case{"linear_300_compressed", table_toml("linear", 300, "6.5", "6.0", "6.8")},
                      Case{"spline_300_compressed", table_toml("spline", 300, "6.5", "6.0", "6.8")}),
    [](const auto& info) { return info.param.name; });

// The fixture must exercise every way a section gives its distances and both end conditions of
// the force spline; a table that is silently taken for another would still agree with itself.
TEST(PairTableLammps, SpacingsOfTheFixtureTable) {
  const std::string file = "fixtures/lammps_table/pair.table";
  const auto m11 = read_pair_table(file, "M11"), m22 = read_pair_table(file, "M22"),
             m12 = read_pair_table(file, "M12");
  EXPECT_EQ(m11.spacing, PairTableSection::Spacing::file);
  EXPECT_TRUE(m11.has_fprime);
  EXPECT_EQ(m22.spacing, PairTableSection::Spacing::r);
  EXPECT_EQ(m12.spacing, PairTableSection::Spacing::rsq);
  EXPECT_EQ(m12.r.size(), 1000u);  // = points of linear_1000: the "match" path
  EXPECT_NEAR(m22.r[1] - m22.r[0], 5.6 / 399, 1e-14);
  EXPECT_NEAR(m12.r[1] * m12.r[1] - m12.r[0] * m12.r[0], (49.0 - 2.25) / 999, 1e-14);
}

// ---- LJ table against lj/cut ----

constexpr double kEps = 0.0104, kSigma = 3.4, kCut = 8.5, kInner = 2.8;

// LJ energy and force in a LAMMPS table section of n lines evenly spaced in r² (RSQ).
std::filesystem::path write_lj_table(int n) {
  const auto path = shockfield::testing::scratch_path("lj_" + std::to_string(n) + ".table");
  std::ofstream out(path);
  out << "LJ\nN " << n << " RSQ " << kInner << " " << kCut << "\n\n";
  for (int i = 0; i < n; ++i) {
    const double s = kInner * kInner + (kCut * kCut - kInner * kInner) * i / (n - 1), r = std::sqrt(s);
    const double sr6 = std::pow(kSigma * kSigma / s, 3);
    out << fmt::format("{} {} {} {}\n", i + 1, r, 4 * kEps * (sr6 * sr6 - sr6),
                       24 * kEps * (2 * sr6 * sr6 - sr6) / r);
  }
  return path;
}

struct LjComparison {
  double force_error = 0, force_bound = 0;    // max over atoms and components, eV/Å
  double energy_error = 0, energy_bound = 0;  // total, eV
};

LjComparison compare_lj(const std::string& interpolation, int n) {
  geometry::Box box;
  Atoms atoms = fixture::fcc_atoms(5.26, {4, 4, 4}, box, 39.95);
  fixture::perturb(atoms, 0.25, 17);
  const System system{atoms, box};
  const auto file = write_lj_table(n);
  auto table = potential_from_toml(fmt::format("[potential]\nstyle = \"table\"\ninterpolation = \"{}\"\n"
                                               "points = {}\nfile = \"{}\"\nkeyword = \"LJ\"\n",
                                               interpolation, n, file.string()), 1);
  auto lj = potential_from_toml(fmt::format("[potential]\nstyle = \"lj/cut\"\nepsilon = {}\n"
                                            "sigma = {}\ncutoff = {}\n", kEps, kSigma, kCut), 1);
  std::filesystem::remove(file);
  const auto ours = evaluate(system, *table, false), exact = evaluate(system, *lj, false);
  // The bounds pair by pair (all pairs by minimum image: the box is 21 Å > 2 r_c).
  const double delta = (kCut * kCut - kInner * kInner) / (n - 1);
  const double e12 = kEps * std::pow(kSigma, 12), e6 = kEps * std::pow(kSigma, 6);
  const std::size_t count = atoms.nlocal;
  std::vector<double> atom_bound(count, 0.0);
  LjComparison c;
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t j = i + 1; j < count; ++j) {
      const double s = box.minimum_image(atoms.x[i] - atoms.x[j]).squaredNorm();
      if (s >= kCut * kCut) continue;
      const double sk = kInner * kInner + std::floor((s - kInner * kInner) / delta) * delta;
      const double width = (s - sk) * (sk + delta - s) / 2;
      const double g2 = 2688 * e12 * std::pow(sk, -9) + 480 * e6 * std::pow(sk, -6);
      const double e2 = 168 * e12 * std::pow(sk, -8) + 48 * e6 * std::pow(sk, -5);
      atom_bound[i] += std::sqrt(s) * width * g2;
      atom_bound[j] += std::sqrt(s) * width * g2;
      c.energy_bound += width * e2;
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    c.force_bound = std::max(c.force_bound, atom_bound[i]);
    c.force_error = std::max(c.force_error, (ours.force[i] - exact.force[i]).cwiseAbs().maxCoeff());
  }
  c.energy_error = std::abs(ours.result.energy - exact.result.energy);
  std::printf("%s N = %d: force error %.3e (bound %.3e), energy error %.3e (bound %.3e)\n",
              interpolation.c_str(), n, c.force_error, c.force_bound, c.energy_error, c.energy_bound);
  return c;
}

TEST(PairTableLj, LinearTableEqualsLjCutToItsInterpolationError) {
  // Round-off of the sums: 1e-12 of the forces' scale (~0.1 eV/Å) and of the energy (~15 eV).
  const auto coarse = compare_lj("linear", 1001), fine = compare_lj("linear", 2001);
  for (const auto& c : {coarse, fine}) {
    EXPECT_LE(c.force_error, c.force_bound + 1e-13);
    EXPECT_LE(c.energy_error, c.energy_bound + 1e-11);
    // The bound is no wide margin: the error reaches a fair part of it.
    EXPECT_GT(c.force_error, 0.05 * c.force_bound);
    EXPECT_GT(c.energy_error, 0.05 * c.energy_bound);
  }
  // Halving Δ divides an O(Δ²) error by 4 (measured 3.5 for the largest force, whose pairs sit
  // elsewhere in their bins on the finer table, and 4.1 for the energy).
  EXPECT_NEAR(coarse.force_error / fine.force_error, 4.0, 1.0);
  EXPECT_NEAR(coarse.energy_error / fine.energy_error, 4.0, 1.0);
}

TEST(PairTableLj, SplineTableIsFarCloserThanTheLinearBound) {
  // Cubic splines in r² (O(Δ⁴) inside, the secant end slopes aside) after splines of the file.
  const auto c = compare_lj("spline", 1001);
  EXPECT_LT(c.force_error, 0.01 * c.force_bound);
  EXPECT_LT(c.energy_error, 0.01 * c.energy_bound);
}

// ---- dynamics ----

TEST(PairTableDynamics, NveConservesEnergy) {
  // 256 atoms on the Morse M11 table (energy shifted to 0 at its 7 Å end), 600 K, dt = 2 fs,
  // 2000 steps. Velocity Verlet: O(dt²) fluctuation, no drift, if F = −dE/dr; the tables
  // interpolate E and F/r separately, so they are consistent only to interpolation error.
  // Measured: fluctuation 1.25e-4 eV/atom (both), drift -2.1e-6 (linear) and -5e-7 (spline)
  // eV/atom over the 4 ps, against ~0.08 eV/atom of kinetic energy; bounds 3x and 5x those.
  for (const char* interpolation : {"linear", "spline"}) {
    geometry::Box box;
    Atoms atoms = fixture::fcc_atoms(3.615, {4, 4, 4}, box, 63.55);
    create_velocities(atoms, 600.0, 99);
    Simulation s(box, std::move(atoms),
                 fixture::potential_from(fmt::format("style = \"table\"\ninterpolation = \"{}\"\npoints = 1000\n"
                                                     "file = \"fixtures/lammps_table/pair.table\"\nkeyword = \"M11\"\n",
                                                     interpolation)),
                 0.002, 1.0);
    s.fixes.push_back(std::make_unique<FixNve>());
    s.setup(false);
    const double n = static_cast<double>(s.atoms.nlocal);
    std::vector<double> e;
    for (int k = 0; k < 2000; ++k) {
      s.advance([](std::int64_t) { return false; });
      e.push_back((s.kinetic_energy() + s.forces.energy) / n);
    }
    double max_dev = 0, head = 0, tail = 0;
    for (std::size_t k = 0; k < e.size(); ++k) {
      max_dev = std::max(max_dev, std::abs(e[k] - e.front()));
      if (k < 200) head += e[k] / 200;
      if (k >= 1800) tail += e[k] / 200;
    }
    std::printf("%s: max deviation %.2e eV/atom, drift %.2e eV/atom\n", interpolation, max_dev, tail - head);
    EXPECT_LT(max_dev, 4e-4);
    EXPECT_LT(std::abs(tail - head), 1e-5);
  }
}

}  // namespace
}  // namespace shockfield::md::potentials::testing

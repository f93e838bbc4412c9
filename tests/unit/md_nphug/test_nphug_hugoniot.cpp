// The Hugoniostat's physics: after equilibration the time-averaged state satisfies the
// Rankine–Hugoniot energy relation E − E₀ = ½ (P + P₀)(V₀ − V) (Ravelo et al., PRB 70, 014103
// (2004), eq. 2 of fixes/nphug.hpp) and holds the target pressure. 512 Cu_u3 atoms from
// cu_512.data (~320 K, P₀ ≈ 1.7 GPa of thermal pressure), uniaxial z at 20 GPa,
// τ_T = 0.1 ps, τ_P = 0.5 ps, 12,000 steps of 1 fs; means over the last 6 ps, sampled every 10 steps.
#include "nphug_fixture.hpp"

using namespace shockfield;
using namespace shockfield::md;
using namespace shockfield::md::nphug_test;

namespace {

struct Means {
  double e = 0, p = 0, v = 0, t = 0, dhug = 0;
};

Means means(const std::vector<Row>& rows, std::size_t first, std::size_t last) {
  Means m;
  for (std::size_t i = first; i < last; ++i) {
    m.e += rows[i][kEtotal];
    m.p += rows[i][kPzz];
    m.v += rows[i][kVol];
    m.t += rows[i][kTemp];
    m.dhug += rows[i][kDhug];
  }
  const auto n = static_cast<double>(last - first);
  return {m.e / n, m.p / n, m.v / n, m.t / n, m.dhug / n};
}

}  // namespace

TEST(NphugHugoniot, TimeAveragedStateSatisfiesTheRankineHugoniotEnergyRelation) {
  const std::int64_t steps = 12000;
  const std::vector<Row> rows = run_nphug(settings("z", steps), 10);
  const Row& start = rows.front();
  const double e0 = start[kEtotal], p0 = start[kPzz], v0 = start[kVol];
  const std::size_t half = rows.size() / 2;
  const Means m = means(rows, half, rows.size());
  const double n_atoms = 512.0, kb = units::metal::boltz, nf = 3.0 * n_atoms - 3.0;
  const double lhs = m.e - e0;                                             // eV
  const double rhs = 0.5 * (m.p + p0) * (v0 - m.v) / units::metal::nktv2p;  // eV
  // The residual's statistical error: the spread of the residual over 6 blocks of 1 ps.
  double block_var = 0;
  const std::size_t blocks = 6, per = (rows.size() - half) / blocks;
  for (std::size_t b = 0; b < blocks; ++b) {
    const Means mb = means(rows, half + b * per, half + (b + 1) * per);
    const double rb = (mb.e - e0) - 0.5 * (mb.p + p0) * (v0 - mb.v) / units::metal::nktv2p;
    block_var += (rb - (lhs - rhs)) * (rb - (lhs - rhs));
  }
  const double sem = std::sqrt(block_var / (blocks - 1) / blocks);
  std::printf("P0 %.4f GPa, <Pzz> %.4f GPa, V/V0 %.5f, <T> %.1f K, <dHug> %.3f K\n", p0 * 1e-4, m.p * 1e-4,
              m.v / v0, m.t, m.dhug);
  std::printf("E - E0 = %.6f eV/atom, 1/2 (P + P0)(V0 - V) = %.6f eV/atom, residual %.3e eV/atom "
              "(%.2f%%, %.2f K as N_f k_B T; block standard error %.2e eV/atom)\n",
              lhs / n_atoms, rhs / n_atoms, (lhs - rhs) / n_atoms, 100 * (lhs - rhs) / rhs, (rhs - lhs) / (nf * kb),
              sem / n_atoms);
  // The target pressure is held: within 1% (the barostat's breathing averages out over 12 periods).
  EXPECT_NEAR(m.p, 200000.0, 2000.0);
  // The compression is real (Cu_u3 at 20 GPa uniaxial: V/V0 ~ 0.91).
  EXPECT_LT(m.v / v0, 0.93);
  // The Rankine–Hugoniot energy relation: residual within 2% of the Hugoniot energy (about 5 K
  // of thermal energy of 512 atoms; the thermostat's integral control zeroes <dHug> only over
  // times long against τ_T, and the 6 ps window's block error is ~1%) and within 4 block errors.
  EXPECT_LT(std::fabs(lhs - rhs), 0.02 * rhs);
  EXPECT_LT(std::fabs(lhs - rhs), 4.0 * sem + 1e-3 * rhs);
}

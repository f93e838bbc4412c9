// The compressive instability of the plastic Al rod (Saitoh et al., Fig 6(b): a stress drop near
// 3.2 % strain). Here it is the Euler sway mode of the rod (theory §8): with sliding ends the
// loaded layers translate sideways but cannot tilt, so the critical stress is that of a pinned
// column of the rod's length, π²E_t D²/(16 L²) with the tangent modulus E_t past yield. A perfect
// packing under symmetric loading gets no sideways push (it does not drop to 5 %); a random
// imperfection of 10⁻³ r0 is the seed the mode grows from. Clamped ends (sway held) halve the
// buckling length (4× the load): no drop. n_phi = 4, n_h = 16 (L/D = 3.5, the
// paper's rod has 3.9), 809 particles, at half the stable time step: about 3 s per rod.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "unit/macroparticle/rod_fixture.hpp"

namespace shockfield::macroparticle {
namespace {

struct Curve {
  double peak_stress = 0, peak_strain = 0;  ///< largest compressive stress (Pa) and its strain
  double end_stress = 0, end_strain = 0;
  double tangent = 0;   ///< dσ/dε between 2 % and 2.5 % strain (past yield, before any drop), Pa
  double sway = 0;      ///< sideways offset of the top layer against the bottom one at the end, r0
  double length = 0;    ///< L between the loaded layers, r0
};

Curve compress(const std::string& ends) {
  const std::string text = fmt::format(R"([specimen]
diameter = 0.014
n_phi = 4
n_h = 16
perturbation = 0.001
[loading]
mode = "compression"
strain_rate = 140.0
final_strain = 0.04
ends = "{}"
[plasticity]
yield_strain = 0.0033
hardening = [0.1]
[run]
)", ends);
  const double stable = fixture::read_case(text).law.stable_time_step();
  const MacroparticleCase run = fixture::read_case(text + fmt::format("dt = {:.17g}\n", 0.5 * stable));
  Rod rod(run);
  Curve c;
  double s20 = 0, s25 = 0;
  while (rod.sim().step < run.steps) {
    for (int k = 0; k < 25 && rod.sim().step < run.steps; ++k) rod.advance(false);
    const RodMeasures m = rod.measure();
    const double strain = -m.strain, stress = -m.stress;
    if (stress > c.peak_stress) c.peak_stress = stress, c.peak_strain = strain;
    if (s20 == 0 && strain >= 0.020) s20 = stress;
    if (s25 == 0 && strain >= 0.025) s25 = stress;
    c.end_stress = stress, c.end_strain = strain;
  }
  c.tangent = (s25 - s20) / 0.005;
  const md::Atoms& a = rod.sim().atoms;
  Vec3 top = Vec3::Zero(), bottom = Vec3::Zero();
  double nt = 0, nb = 0;
  for (std::size_t i = 0; i < a.nlocal; ++i) {
    if (a.mask[i] & kTopBit) top += a.x[i], nt += 1;
    if (a.mask[i] & kBottomBit) bottom += a.x[i], nb += 1;
  }
  const Vec3 d = top / nt - bottom / nb;
  c.sway = std::hypot(d.x(), d.y());
  c.length = 16 * std::numbers::sqrt2;
  return c;
}

TEST(MacroparticleCompression, SlidingRodBucklesNearThreePercentAndAClampedOneDoesNot) {
  const Curve sliding = compress("sliding");
  // The tangent Euler stress of the sway mode, D = 14 mm = (4√2 + 1) r0: the rod is beyond it
  // from about 1 % strain, so the drop waits only for the imperfection to grow (the reduced-
  // modulus load bounds the peak from above; theory §8).
  const double diameter = 4 * std::numbers::sqrt2 + 1;
  const double euler_tangent = std::pow(std::numbers::pi, 2) * sliding.tangent * std::pow(diameter / sliding.length, 2) / 16;
  EXPECT_GT(sliding.tangent, 0.05 * 95e9);  // h_1 = 0.1 of the bond stiffness: E_t ≈ 0.09 E
  EXPECT_LT(sliding.tangent, 0.15 * 95e9);
  EXPECT_GT(sliding.peak_stress, 1.5 * euler_tangent) << euler_tangent;
  // The drop: the peak at 2.5-4 % strain (3.1 % with this imperfection, the paper's 3.2 %; 2.5 %
  // at 10⁻² r0, 4.6 % at 10⁻⁴ r0 and 3.1-4.3 % over three random seeds: the window is the
  // imperfection's, not a tolerance of round-off), then at 4 % the stress 15 % below it, the
  // top layer swayed sideways by more than a quarter of r0 (the bending mode, not slip).
  EXPECT_GT(sliding.peak_strain, 0.025);
  EXPECT_LT(sliding.peak_strain, 0.039);
  EXPECT_LT(sliding.end_stress, 0.85 * sliding.peak_stress);
  EXPECT_GT(sliding.sway, 0.25);

  const Curve clamped = compress("clamped");
  // Sway held: the clamped column's load is 4× the sliding one's, beyond the stress reached here.
  EXPECT_GE(clamped.end_stress, 0.999 * clamped.peak_stress);
  EXPECT_LT(clamped.sway, 0.01);
}

}  // namespace
}  // namespace shockfield::macroparticle

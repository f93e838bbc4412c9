// The compressive instability as {111} slip (Saitoh et al., Fig 6(b): the drop near 3.2 % strain,
// "slip motion between particles' layer ... along (111) planes"; theory §8). With bonds that yield
// at ε_y = 1.1 % and do not harden (h_1 = 0, the default route), the (001) in-plane bonds, stretched
// by the lateral expansion νε (ν = 1/3, Cauchy), yield at ε ≈ ε_y/ν = 3.3 %; from there the
// compressed inclined bonds' geometric stiffness −T/r is no longer balanced and the packing's
// acoustic tensor has a negative eigenvalue for a band normal to a ⟨111⟩ (the infinite packing:
// at 3.0 %, normal within 1° of ⟨111⟩; examples/macroparticle_rod/slip.py). The stress peaks
// there, and with a 10⁻³ r0 imperfection and sliding ends one {111} layer pair then slides
// across the whole section and the stress drops. The slip measure: the bonds of the start
// (r < 1.2 r0) between neighbouring layers of a family of planes, their relative displacement
// less the rod's best affine map, its in-plane part averaged over the layer pair. n_phi = 4,
// n_h = 8 (L/D = 1.7: too short to buckle, long enough for a {111} plane, inclined 54.7°, to
// cross the section without meeting the loaded layers), 417 particles, about 4 s per rod.
#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <unordered_map>
#include <vector>

#include "unit/macroparticle/rod_fixture.hpp"

namespace shockfield::macroparticle {
namespace {

struct LayerSlip {
  double largest = 0;  ///< largest layer-pair slip of the family, r0
  double median = 0;   ///< median over the layer pairs of the plane set holding the largest, r0
};

struct SlipRun {
  double peak_stress = 0, peak_strain = 0;  ///< largest |σ| (Pa) and its |ε|
  double end_stress = 0;                    ///< |σ| at the end
  double least_after_peak = 0;              ///< smallest |σ| after the peak
  std::vector<std::pair<double, double>> curve;  ///< (|ε|, |σ|) every 25 steps
  std::map<std::string, LayerSlip> slip;    ///< by family: "111", "100", "110"
};

// Slip between neighbouring layers of each plane of the families {111}, {100}, {110} (cubic cell
// √2 r0: spacings √(2/3), √2/2 and 1/2 r0).
std::map<std::string, LayerSlip> layer_slip(const std::vector<Vec3>& x0, const std::vector<Vec3>& x) {
  std::vector<std::array<std::size_t, 2>> bonds;
  for (std::size_t i = 0; i < x0.size(); ++i)
    for (std::size_t j = i + 1; j < x0.size(); ++j)
      if ((x0[j] - x0[i]).norm() < 1.2) bonds.push_back({i, j});
  Eigen::Matrix3d bb0 = Eigen::Matrix3d::Zero(), b0b0 = Eigen::Matrix3d::Zero();
  for (const auto& [i, j] : bonds) {
    bb0 += (x[j] - x[i]) * (x0[j] - x0[i]).transpose();
    b0b0 += (x0[j] - x0[i]) * (x0[j] - x0[i]).transpose();
  }
  const Eigen::Matrix3d affine = bb0 * b0b0.inverse();  // least squares: x_ij ≈ F X_ij
  const std::map<std::string, std::pair<std::vector<Vec3>, double>> families = {
      {"111", {{{1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}}, std::sqrt(2.0 / 3.0)}},
      {"100", {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, std::numbers::sqrt2 / 2}},
      {"110", {{{1, 1, 0}, {1, -1, 0}, {1, 0, 1}, {1, 0, -1}, {0, 1, 1}, {0, 1, -1}}, 0.5}}};
  std::map<std::string, LayerSlip> out;
  for (const auto& [name, family] : families) {
    for (Vec3 n : family.first) {
      n.normalize();
      std::map<long, std::pair<Vec3, int>> pairs;  // lower layer -> summed in-plane slip, bonds
      for (const auto& [i, j] : bonds) {
        const long li = std::lround(x0[i].dot(n) / family.second), lj = std::lround(x0[j].dot(n) / family.second);
        if (std::abs(li - lj) != 1) continue;
        Vec3 d = (x[j] - x[i]) - affine * (x0[j] - x0[i]);
        if (lj < li) d = -d;
        d -= d.dot(n) * n;
        auto& [sum, count] = pairs.try_emplace(std::min(li, lj), Vec3::Zero(), 0).first->second;
        sum += d, ++count;
      }
      std::vector<double> slips;
      for (const auto& [layer, p] : pairs)
        if (p.second >= 6) slips.push_back(p.first.norm() / p.second);
      if (slips.empty()) continue;
      std::sort(slips.begin(), slips.end());
      if (slips.back() > out[name].largest) out[name] = {slips.back(), slips[slips.size() / 2]};
    }
  }
  return out;
}

// The bond law of the first test: yield at 1.1 %, no hardening (the default route).
constexpr const char* kSoftBonds = "yield_strain = 0.011\nhardening = [0.0]\n";

SlipRun run(const std::string& mode, const std::string& ends, double perturbation,
            const std::string& plasticity = kSoftBonds, double final_strain = 0.05) {
  const std::string text = fmt::format(R"([specimen]
diameter = 0.014
n_phi = 4
n_h = 8
perturbation = {}
[loading]
mode = "{}"
strain_rate = 70.0
final_strain = {}
ends = "{}"
[plasticity]
{}[run]
)", perturbation, mode, final_strain, ends, plasticity);
  Rod rod(fixture::read_case(text));
  const MacroparticleCase c = fixture::read_case(text);
  auto positions = [&rod] {  // by particle id: the engine may reorder its arrays
    std::map<std::int64_t, Vec3> by_id;
    const md::Atoms& a = rod.sim().atoms;
    for (std::size_t i = 0; i < a.nlocal; ++i) by_id[a.id[i]] = a.x[i];
    std::vector<Vec3> out;
    for (const auto& [id, x] : by_id) out.push_back(x);
    return out;
  };
  const std::vector<Vec3> x0 = positions();
  SlipRun r;
  while (rod.sim().step < c.steps) {
    for (int k = 0; k < 25 && rod.sim().step < c.steps; ++k) rod.advance(false);
    const RodMeasures m = rod.measure();
    if (std::abs(m.stress) > r.peak_stress) r.peak_stress = r.least_after_peak = std::abs(m.stress), r.peak_strain = std::abs(m.strain);
    r.least_after_peak = std::min(r.least_after_peak, std::abs(m.stress));
    r.end_stress = std::abs(m.stress);
    r.curve.emplace_back(std::abs(m.strain), std::abs(m.stress));
  }
  r.slip = layer_slip(x0, positions());
  return r;
}

TEST(MacroparticleSlip, CompressedRodSlipsOnA111PlaneAndControlsDoNot) {
  const SlipRun slip = run("compression", "sliding", 0.001);
  // The peak where the in-plane bonds yield, ε_y/ν = 3ε_y = 3.3 % (3.0 % in the infinite packing,
  // 3.05-3.25 % for imperfections of 10⁻⁴-10⁻² r0 and three seeds): 10 % around 3.3 %.
  EXPECT_GT(slip.peak_strain, 0.9 * 0.03);
  EXPECT_LT(slip.peak_strain, 1.1 * 0.033);
  // The drop (2.33 -> 1.6 GPa by 5 %): more than 20 % below the peak.
  EXPECT_LT(slip.end_stress, 0.8 * slip.peak_stress);
  // Slip on one {111} layer pair (0.228 r0, 0.4 of a Shockley partial): larger than 0.15 r0, more
  // than 3× any {100} or {110} layer pair (measured 0.023, 0.040) and 4× the median layer pair of
  // its {111} plane set (measured 5.0×: the others carry 0.01-0.05 r0 of bending).
  const LayerSlip s111 = slip.slip.at("111");
  EXPECT_GT(s111.largest, 0.15);
  EXPECT_GT(s111.largest, 3 * slip.slip.at("100").largest);
  EXPECT_GT(s111.largest, 3 * slip.slip.at("110").largest);
  std::cout << "peak " << slip.peak_stress << " Pa at " << slip.peak_strain << ", end " << slip.end_stress << " Pa; slip {111} "
            << s111.largest << " (median " << s111.median << "), {100} " << slip.slip.at("100").largest << ", {110} "
            << slip.slip.at("110").largest << " r0\n";
  EXPECT_GT(s111.largest, 4 * s111.median);

  // Controls: the perfect rod (no sideways push) and the clamped one (its ends cannot translate
  // against each other) peak at the same strain but decline slowly without slip; tension does
  // not peak (the in-plane bonds are compressed: their geometric stiffness stabilises).
  for (const auto& [mode, ends, perturbation] :
       {std::tuple{"compression", "sliding", 0.0}, std::tuple{"compression", "clamped", 0.001},
        std::tuple{"tension", "sliding", 0.001}}) {
    const SlipRun control = run(mode, ends, perturbation);
    std::cout << mode << " " << ends << " " << perturbation << ": peak " << control.peak_stress << " Pa at "
              << control.peak_strain << ", end " << control.end_stress << " Pa, slip {111} " << control.slip.at("111").largest
              << " r0\n";
    EXPECT_LT(control.slip.at("111").largest, 0.05) << mode << " " << ends << " " << perturbation;
    EXPECT_GT(control.end_stress, 0.85 * control.peak_stress) << mode << " " << ends << " " << perturbation;
  }
}

// |σ| at the first sample at or past strain e.
double stress_at(const SlipRun& r, double e) {
  const auto it = std::find_if(r.curve.begin(), r.curve.end(), [e](const auto& p) { return p.first >= e; });
  return it == r.curve.end() ? std::nan("") : it->second;
}

// One bond law for both halves of Fig 6 (theory §8, "One law for tension and compression"): bonds
// yield in tension at ε_y = 0.33 % (rod yield ≈ 3ε_y ≈ 1 %, Fig 6(a)), harden with h_1 = 0.1 and
// saturate 1.6 % past yield; in compression they yield only at ε_c = 2 %. Under [001] tension the
// inclined bonds are stretched (they yield and harden: no peak); under compression the (001)
// in-plane bonds are stretched by the lateral expansion, yield, harden and saturate, while the
// compressed inclined bonds stay elastic and their geometric stiffness −T/r grows: the infinite
// packing loses ellipticity at 2.9 % for a band normal within 1° of ⟨111⟩, and the rod slips on
// one {111} layer pair (examples/macroparticle_rod/slip.py).
TEST(MacroparticleSlip, OneBondLawYieldsNearOnePercentInTensionAndSlipsOnA111PlaneInCompression) {
  const std::string law =
      "yield_strain = 0.0033\nhardening = [0.1]\nsaturation_strain = 0.016\ncompression_yield_strain = 0.02\n";
  const SlipRun tension = run("tension", "sliding", 0.001, law, 0.025);
  // Elastic to 1 % (the slope over 0.75-1 % within 20 % of that over 0.25-0.75 %), yielded by
  // 1.5-2 % (slope below 40 % of it: measured 78, 68 and 22 GPa, the knee at 1.2 %), hardening
  // without a drop (the last stress the largest, within 1 %; to 2.5 % here, the example's rod
  // hardens on to 5 %), no slip.
  auto slope = [&tension](double a, double b) { return (stress_at(tension, b) - stress_at(tension, a)) / (b - a); };
  const double young = slope(0.0025, 0.0075);
  std::cout << "tension: slopes " << young << ", " << slope(0.0075, 0.01) << ", " << slope(0.015, 0.02) << " Pa; end "
            << tension.end_stress << " Pa, slip {111} " << tension.slip.at("111").largest << " r0\n";
  EXPECT_GT(slope(0.0075, 0.01), 0.8 * young);
  EXPECT_LT(slope(0.015, 0.02), 0.4 * young);
  EXPECT_GT(tension.end_stress, 0.99 * tension.peak_stress);
  EXPECT_LT(tension.slip.at("111").largest, 0.05);
  const SlipRun compression = run("compression", "sliding", 0.001, law);
  std::cout << "compression: peak " << compression.peak_stress << " Pa at " << compression.peak_strain << ", least after "
            << compression.least_after_peak << " Pa; slip {111} " << compression.slip.at("111").largest << " (median "
            << compression.slip.at("111").median << "), {100} " << compression.slip.at("100").largest << ", {110} "
            << compression.slip.at("110").largest << " r0\n";
  // The peak near Fig 6(b)'s 3.2 % (measured 3.32 %; the infinite packing's onset 2.9 %), a drop
  // of more than 20 % after it (measured 1.21 -> 0.80 GPa), and one {111} layer pair sliding
  // (measured 0.23 r0 against a median of 0.044 and 0.016 / 0.037 for {100} / {110}).
  EXPECT_GT(compression.peak_strain, 0.029);
  EXPECT_LT(compression.peak_strain, 0.036);
  EXPECT_LT(compression.least_after_peak, 0.8 * compression.peak_stress);
  const LayerSlip s111 = compression.slip.at("111");
  EXPECT_GT(s111.largest, 0.15);
  EXPECT_GT(s111.largest, 3 * compression.slip.at("100").largest);
  EXPECT_GT(s111.largest, 3 * compression.slip.at("110").largest);
  EXPECT_GT(s111.largest, 4 * s111.median);
}

// The route's polynomial takes more than one coefficient (docs: h_1 ... h_8); the reader once
// demanded exactly one.
TEST(MacroparticleSlip, CaseReaderTakesSeveralHardeningCoefficients) {
  const MacroparticleCase c = fixture::read_case(
      fixture::rod(4, 8, 70.0, 0.01) + "[plasticity]\nyield_strain = 0.0033\nhardening = [0.1, -2.0, 30.0]\n");
  ASSERT_TRUE(c.plasticity);
  EXPECT_EQ(c.plasticity->hardening, (std::vector<double>{0.1, -2.0, 30.0}));
}

}  // namespace
}  // namespace shockfield::macroparticle

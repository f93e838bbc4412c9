// Nesterenko's solitary wave in a horizontal Hertzian chain without precompression: speed
// against peak grain velocity (the 1/5 power and the prefactor), width and shape against the
// long-wave solution (nesterenko.hpp), and an impulse spanning several grains breaking into a
// train of solitary waves.
#include <gtest/gtest.h>

#include <cmath>

#include "shockfield/granular/nesterenko.hpp"
#include "shockfield/granular/signal.hpp"
#include "shockfield/granular/simulation.hpp"

namespace shockfield::granular {
namespace {

constexpr double kRadius = 5e-3;

Chain horizontal_chain(long long n) {
  ChainSpec s;
  s.grains = n;
  s.radius = kRadius;
  return build_chain(s);
}

struct WaveMeasurement {
  double speed = 0.0;     ///< between grains 60 and 90 [m/s]
  double v_max = 0.0;     ///< peak velocity at grain 90 [m/s]
  double fwhm = 0.0;      ///< of v_90(t), times the speed, in diameters
  double base_width = 0.0;  ///< the same where v > 1e-3 v_m, in diameters
  double shape_error = 0.0;  ///< max |v/v_m − cos⁴| over the profile at grain 90
};

// A single grain hits a chain of 120 at rest; the wave is formed well before grain 60.
WaveMeasurement measure_wave(double v0) {
  const Chain c = horizontal_chain(120);
  const NesterenkoWave theory{c.kappa[0], c.mass[0], 2 * kRadius};
  const Impulse kick{Impulse::Kind::velocity, v0, 1, {}, {}};
  Simulation sim(c, kick, 0.01 * Simulation::stable_step(c, kick));
  PeakTracker peaks({60, 90});
  std::vector<std::pair<double, double>> series;  // (t, v_90)
  const double t_end = 100 * theory.diameter / (0.7 * theory.speed(v0));
  while (sim.time() < t_end) {
    sim.step();
    peaks.sample(sim);
    series.emplace_back(sim.time(), sim.velocity()[90]);
  }
  WaveMeasurement m;
  m.speed = (c.depth[90] - c.depth[60]) / (peaks.peak(1).time - peaks.peak(0).time);
  m.v_max = peaks.peak(1).velocity;
  double first = -1, last = -1, base_first = -1, base_last = -1;
  for (const auto& [t, v] : series) {
    if (v >= 0.5 * m.v_max && first < 0) first = t;
    if (v >= 0.5 * m.v_max) last = t;
    if (v >= 1e-3 * m.v_max && base_first < 0) base_first = t;
    if (v >= 1e-3 * m.v_max) base_last = t;
    const double s = m.speed * (peaks.peak(1).time - t);
    m.shape_error = std::max(m.shape_error, std::abs(v / m.v_max - theory.velocity_shape(s)));
  }
  m.fwhm = (last - first) * m.speed / theory.diameter;
  m.base_width = (base_last - base_first) * m.speed / theory.diameter;
  return m;
}

TEST(GranularSolitaryWave, SpeedFollowsNesterenkosOneFifthPowerAndPrefactor) {
  const Chain c = horizontal_chain(2);
  const NesterenkoWave theory{c.kappa[0], c.mass[0], 2 * kRadius};
  std::vector<double> vm, speed;
  std::vector<WaveMeasurement> waves;
  for (double v0 : {0.01, 0.1, 1.0}) {
    const WaveMeasurement m = measure_wave(v0);
    vm.push_back(m.v_max);
    speed.push_back(m.speed);
    waves.push_back(m);
    // Long-wave theory against the discrete chain: measured V_s = 0.992 of Nesterenko's for the
    // measured v_m (= 0.682 v0); tolerance 1.5%: the continuum limit drops terms of higher order
    // in a/L for a wave only ~5 grains wide.
    EXPECT_NEAR(m.speed / theory.speed(m.v_max), 1.0, 0.015) << v0;
    // Width: the discrete wave is narrower at half maximum than the long-wave cos⁴ (measured
    // 1.570 diameters against 1.808) and has tails beyond its compact support (4.74 diameters
    // above 1e-3 v_m against 4.40): about 5 diameters, as the theory says. Tolerances 15% and
    // 10% around the long-wave values; the shape differs from cos⁴ by at most 0.099 v_m.
    EXPECT_NEAR(m.fwhm / NesterenkoWave::velocity_fwhm(), 1.0, 0.15) << v0;
    EXPECT_NEAR(m.base_width / NesterenkoWave::width_above(1e-3), 1.0, 0.1) << v0;
    EXPECT_LT(m.shape_error, 0.11) << v0;
  }
  // The Hertz chain is scale invariant (v → s·v with t → s^{-1/5} t), so speed/v_m^{1/5}, width
  // and shape do not depend on the impulse: the exponent is 1/5 and the widths agree to 1e-6
  // (the measurement's resolution; sampled peaks and half-crossings).
  const PowerLaw fit = fit_power_law(vm, speed);
  EXPECT_NEAR(fit.exponent, 0.2, 1e-4);
  EXPECT_NEAR(waves[0].fwhm, waves[2].fwhm, 1e-4);
  EXPECT_NEAR(waves[0].v_max / 0.01, waves[2].v_max / 1.0, 1e-6);
}

TEST(GranularSolitaryWave, ImpulseOnSeveralGrainsBreaksIntoATrainOfSolitaryWaves) {
  const Chain c = horizontal_chain(400);
  const NesterenkoWave theory{c.kappa[0], c.mass[0], 2 * kRadius};
  const Impulse kick{Impulse::Kind::velocity, 0.5, 5, {}, {}};
  Simulation sim(c, kick, 0.02 * Simulation::stable_step(c, kick));
  const auto peaks_now = [&] {
    // Local maxima of v above 2% of the largest: (position, amplitude), front first.
    std::vector<std::pair<double, double>> out;
    const auto& v = sim.velocity();
    double vmax = 0;
    for (double x : v) vmax = std::max(vmax, x);
    for (std::size_t i = v.size() - 2; i > 0; --i)
      if (v[i] > 0.02 * vmax && v[i] >= v[i + 1] && v[i] > v[i - 1]) {
        const double curv = v[i - 1] - 2 * v[i] + v[i + 1];
        const double s = 0.5 * (v[i - 1] - v[i + 1]) / curv;
        out.emplace_back(static_cast<double>(i) + s, v[i] - 0.25 * (v[i - 1] - v[i + 1]) * s);
      }
    return out;
  };
  const auto run_to = [&](double t) { while (sim.time() < t) sim.step(); };
  const double t1 = 200 * theory.diameter / theory.speed(0.5);
  run_to(t1);
  const auto first = peaks_now();
  run_to(t1 * 1.4);
  const auto second = peaks_now();
  // A train: several waves, amplitudes falling from the front back.
  ASSERT_GE(first.size(), 3u);
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t j = 0; j + 1 < 3; ++j) EXPECT_GT(second[j].second, second[j + 1].second);
  // Each member is a solitary wave: its speed is Nesterenko's for its own amplitude (2%, as above;
  // amplitudes from one snapshot's grain velocities, refined by a parabola).
  for (std::size_t j = 0; j < 3; ++j) {
    const double speed = (second[j].first - first[j].first) * theory.diameter / (0.4 * t1);
    EXPECT_NEAR(speed / theory.speed(second[j].second), 1.0, 0.02) << j;
  }
}

}  // namespace
}  // namespace shockfield::granular

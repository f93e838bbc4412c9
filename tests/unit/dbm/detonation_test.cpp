// Planar detonation with the reactive DBM against Chapman–Jouguet theory (Xu et al. 2015, §2.3.3, §4.3):
// the CJ and von Neumann states satisfy the Rankine–Hugoniot relations; the measured front speed is
// within 2% of D_CJ (issue 6); Δ*_2xx is positive in the shock in front of the von Neumann
// pressure peak (compression) and negative in the reaction zone behind it (thermal expansion from
// the heat release), as Yan et al. (2013) found and Xu et al. (2015) §4.3 reports, while an inert shock has no
// such negative zone. Fresh gas ρ0 = 1, p0 = 0.6 so that every temperature of the run stays inside
// the range where the D2V16 model (speeds 1, 2, 3, 4; η0 = 2) is linearly stable (T ≲ 1.25).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include <cstdio>

#include "shockfield/dbm/detonation.hpp"

using namespace shockfield;
using namespace shockfield::dbm;

namespace {

constexpr double kGamma = 1.4, kP0 = 0.6, kQ = 0.6;
const GasState kFresh{1.0, 0.0, kP0};

DetonationTubeResult run(double rate, double length, double t_end, double ignition_width,
                         bool piston = false) {
  DetonationTubeSetup d;
  d.fresh = kFresh, d.gamma = kGamma;
  d.law.heat_release = kQ, d.law.rate = rate, d.law.ignition_temperature = 0.7;
  d.length = length, d.t_end = t_end, d.ignition_width = ignition_width, d.piston = piston;
  return run_detonation_tube(d);
}

double mean(const std::vector<double>& v, std::size_t from, std::size_t to) {
  double s = 0.0;
  for (std::size_t i = from; i < to; ++i) s += v[i];
  return s / static_cast<double>(to - from);
}

}  // namespace

TEST(DbmDetonation, ChapmanJouguetAndVonNeumannStatesSatisfyRankineHugoniot) {
  for (double Q : {0.3, 0.6, 2.0}) {
    const ChapmanJouguet r = chapman_jouguet(kFresh, kGamma, Q);
    const double D = r.speed;
    auto check = [&](const GasState& s, double q, const char* what) {
      const double w = D - s.u;  // outflow speed relative to the front
      const double h0 = kGamma / (kGamma - 1) * kP0, h1 = kGamma / (kGamma - 1) * s.p / s.rho;
      EXPECT_NEAR(s.rho * w, kFresh.rho * D, 1e-12) << what << " mass, Q = " << Q;
      EXPECT_NEAR(s.p + s.rho * w * w, kP0 + D * D, 1e-12) << what << " momentum, Q = " << Q;
      EXPECT_NEAR(h1 + 0.5 * w * w, h0 + q + 0.5 * D * D, 1e-12) << what << " energy, Q = " << Q;
    };
    check(r.cj, Q, "CJ");
    check(r.von_neumann, 0.0, "von Neumann");
    EXPECT_NEAR(D - r.cj.u, std::sqrt(kGamma * r.cj.p / r.cj.rho), 1e-12) << "CJ point is sonic";
    EXPECT_GT(r.von_neumann.p, r.cj.p);
  }
}

TEST(DbmDetonation, SpeedWithinTwoPercentOfChapmanJouguet) {
  // Fast reaction (k = 20, zone ≈ 4 cells): the front settles to D_CJ within the run.
  const DetonationTubeResult o = run(20.0, 6.0, 2.2, 0.1);
  const double D_cj = chapman_jouguet(kFresh, kGamma, kQ).speed;
  std::printf("measured D = %.5f, D_CJ = %.5f (%.2f%%)\n", o.speed, D_cj, 100 * (o.speed / D_cj - 1));
  EXPECT_NEAR(o.speed, D_cj, 0.02 * D_cj);
}

TEST(DbmDetonation, TneOppositeSignsAroundVonNeumannPeak) {
  // Slow reaction (k = 1, zone ≈ 0.7 = 70 cells) started from a ZND-like layer (0.7 thick, so
  // the front starts overdriven and is within 3% of D_CJ over t in [1.5, 3]; thinner layers let
  // it decay below D_CJ first): a resolved reaction zone behind the pressure peak; and, as control, the inert shock at D_CJ (k = 0,
  // driven by von Neumann gas flowing in), uniform behind.
  const DetonationTubeResult det = run(1.0, 7.0, 3.0, 0.7);
  const DetonationTubeResult inert = run(0.0, 4.0, 1.0, 0.5, true);
  double det_behind = 0.0;
  for (const DetonationTubeResult* o : {&det, &inert}) {
    const std::size_t peak = std::max_element(o->p.begin(), o->p.end()) - o->p.begin();
    std::size_t front_end = peak;  // the shock: p above 5% of the jump, ahead of the peak
    while (front_end + 1 < o->p.size() && o->p[front_end + 1] > kP0 + 0.05 * (o->p[peak] - kP0)) ++front_end;
    const double front_max = *std::max_element(o->d2xx.begin() + peak, o->d2xx.begin() + front_end + 1);
    const double front_mean = mean(o->d2xx, peak + 1, front_end + 1);
    const double behind = mean(o->d2xx, peak - 60, peak - 5);  // 0.55 behind the peak
    std::printf("%s: D %.5f (D_CJ %.5f), peak p %.4f at x %.3f (lambda %.3f); D*2xx at peak %.5f, in front "
                "mean %.5f max %.5f, behind mean %.6f\n",
                o == &det ? "detonation" : "inert shock", o->speed, o->theory.speed, o->p[peak], o->x[peak],
                o->lambda[peak], o->d2xx[peak], front_mean, front_max, behind);
    // Where Δ*_2xx changes sign near the peak, against the maxima of p and ρ (examples/dbm_detonation).
    const std::size_t rho_peak = std::max_element(o->rho.begin(), o->rho.end()) - o->rho.begin();
    std::size_t zero = peak;  // first cell ahead of the pressure peak with Δ*_2xx ≥ 0
    while (zero < front_end && o->d2xx[zero] < 0.0) ++zero;
    const double dx = o->x[1] - o->x[0];
    const double x_zero = o->x[zero] - dx * o->d2xx[zero] / (o->d2xx[zero] - o->d2xx[zero - 1]);
    std::printf("  rho peak at x %.3f (%+d cells from the p peak); D*2xx = 0 at x %.4f (%+.2f cells from the p peak)\n",
                o->x[rho_peak], static_cast<int>(rho_peak) - static_cast<int>(peak), x_zero,
                (x_zero - o->x[peak]) / dx);
    for (std::size_t i = peak - 3; i <= std::min(front_end, peak + 4); ++i)
      std::printf("  x %.3f  rho %.4f  p %.4f  lambda %.3f  D*2xx %+.5f\n", o->x[i], o->rho[i], o->p[i], o->lambda[i],
                  o->d2xx[i]);
    EXPECT_NEAR(o->speed, o->theory.speed, 0.03 * o->theory.speed) << "a detonation / shock near D_CJ";
    EXPECT_GT(front_mean, 0.0) << "compression in front of the peak";
    EXPECT_LT(std::abs(o->d2xx[peak]), 0.25 * front_max) << "near equilibrium at the peak";
    if (o == &det) {
      det_behind = behind;
      EXPECT_LT(behind, 0.0) << "expansion behind the peak";
    } else {
      EXPECT_LT(std::abs(behind), 0.2 * std::abs(det_behind)) << "uniform behind an inert shock";
    }
  }
}

// Speed of the steady detonation supported by a piston at u_p (complete reaction, the burnt gas
// moving at u_p): the strong root of the energy balance with ρ1 = ρ0 D/(D − u_p), p1 = p0 + ρ0 D u_p.
double piston_supported_speed(double u_p) {
  const auto residual = [&](double D) {
    const double rho1 = kFresh.rho * D / (D - u_p), p1 = kP0 + kFresh.rho * D * u_p, w = D - u_p;
    const double h = kGamma / (kGamma - 1);
    return h * p1 / rho1 + 0.5 * w * w - (h * kP0 / kFresh.rho + kQ + 0.5 * D * D);
  };
  double lo = chapman_jouguet(kFresh, kGamma, kQ).speed, hi = 10.0;  // residual < 0 at lo, > 0 at hi
  if (!(residual(lo) < 0.0 && residual(hi) > 0.0)) return NAN;
  for (int i = 0; i < 200; ++i) (residual(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

TEST(DbmDetonation, InflowDrivenControlBurnsWhenTheReactionIsOn) {
  // The von Neumann inflow of the inert control is a piston at u_vN > u_CJ: with k = 0 it drives
  // the inert shock at D_CJ; with k = 1 the fresh gas fed in (λ = 1, T_vN > T_ign) burns and the
  // front runs ahead of D_CJ toward the piston-supported detonation (docs/theory/dbm.md, open
  // observations: the recorded 4-8% over-speed). Measured: −0.01%; +4.10% (supported: +13.0%).
  const DetonationTubeResult inert = run(0.0, 4.0, 1.0, 0.5, true);
  const DetonationTubeResult burning = run(1.0, 4.0, 1.0, 0.5, true);
  const double D_cj = inert.theory.speed, D_piston = piston_supported_speed(inert.theory.von_neumann.u);
  std::printf("inflow-driven front: k = 0 %.5f, k = 1 %.5f; D_CJ %.5f, piston-supported %.5f\n", inert.speed,
              burning.speed, D_cj, D_piston);
  EXPECT_NEAR(inert.speed, D_cj, 1e-3 * D_cj);
  EXPECT_GT(burning.speed, 1.03 * D_cj);
  EXPECT_LT(burning.speed, D_piston);
  EXPECT_GT(D_piston, 1.1 * D_cj);
}

TEST(DbmDetonation, TwoDimensionalRippledFrontTurnsPlanarAtCjSpeed) {
  // 2D: 300 × 4 cells, periodic in y, the ignition layer rippled by ±2 cells across y. Every row's
  // front must run at D_CJ within 2% and the rows must end within half a cell of each other.
  const VelocityModel model = d2v16({1.0, 2.0, 3.0, 4.0}, 2.0);
  Lattice l;
  l.nx = 300, l.ny = 4, l.dx = l.dy = 0.01;
  Boundaries bc;
  bc.side[0].kind = BoundaryKind::reflecting;
  bc.side[1].kind = BoundaryKind::outflow;
  BgkSettings s;
  s.gamma = kGamma, s.dt = 0.1 * l.dx, s.tau = 2e-3;
  Simulation sim(model, l, bc, s);
  RateLaw law;
  law.heat_release = kQ, law.rate = 20.0, law.ignition_temperature = 0.7;
  ReactiveFlow flow(sim, bc, law);
  const ChapmanJouguet cj = chapman_jouguet(kFresh, kGamma, kQ);
  const auto edge = [&](double y) { return 0.5 + 0.02 * std::sin(2 * M_PI * y / (l.ny * l.dy)); };
  const auto macro = [](const GasState& g) { return Macro{g.rho, g.u, 0.0, g.p / g.rho}; };
  sim.initialize([&](double x, double y) {
    if (x < edge(y)) return macro(cj.cj);
    return x < edge(y) + 0.1 ? macro(cj.von_neumann) : Macro{1.0, 0.0, 0.0, kP0};
  });
  flow.initialize([&](double x, double y) { return x < edge(y) ? 0.0 : 1.0; });
  std::vector<double> t;
  std::vector<std::vector<double>> front(l.ny);
  for (int n = 1; n <= 1200; ++n) {
    sim.step();
    if (n % 20 == 0 && n >= 600) {
      t.push_back(sim.time());
      for (int j = 0; j < l.ny; ++j) front[j].push_back(pressure_front(sim, j, 0.5 * (kP0 + cj.cj.p)));
    }
  }
  sim.check_state();
  for (int j = 0; j < l.ny; ++j) {
    const double D = fitted_speed(t, front[j]);
    std::printf("row %d: D = %.5f (D_CJ %.5f), final front %.4f\n", j, D, cj.speed, front[j].back());
    EXPECT_NEAR(D, cj.speed, 0.02 * cj.speed) << "row " << j;
    EXPECT_NEAR(front[j].back(), front[0].back(), 0.5 * l.dx) << "row " << j;
  }
}

#pragma once
// Liquid–vapour coexistence of a reduced-unit equation of state P(ρ, T) (van der Waals,
// Carnahan–Starling): the critical point and the Maxwell equal-area construction, the reference
// for the GLS model's coexistence densities (issue 6; vdW at T/T_c = 0.9: ρ_l/ρ_c = 1.6573,
// ρ_v/ρ_c = 0.4257).
#include <algorithm>
#include <cmath>
#include <concepts>

namespace shockfield::dbm {

template <class E>
concept LiquidVapourEos = requires(const E& e, double rho, double T) {
  { e.pressure(rho, T) } -> std::convertible_to<double>;
  { e.dpressure_drho(rho, T) } -> std::convertible_to<double>;
  { e.max_density() } -> std::convertible_to<double>;
};

struct CriticalPoint {
  double rho = 0.0, T = 0.0, p = 0.0;
};

struct Coexistence {
  double rho_vapour = 0.0, rho_liquid = 0.0, p_saturation = 0.0;
};

namespace detail {

/// Maximiser of a unimodal g on (lo, hi) by golden-section search.
template <class G>
double golden_max(G g, double lo, double hi) {
  const double r = 0.6180339887498949;
  double a = lo, b = hi, c = b - r * (b - a), d = a + r * (b - a);
  for (int it = 0; it < 200 && b - a > 1e-15 * (1 + b); ++it) {
    if (g(c) > g(d)) b = d; else a = c;
    c = b - r * (b - a);
    d = a + r * (b - a);
  }
  return 0.5 * (a + b);
}

/// Root of a monotone h on [lo, hi] (h(lo), h(hi) of opposite signs) by bisection.
template <class H>
double bisect(H h, double lo, double hi) {
  const bool rising = h(hi) > h(lo);
  for (int it = 0; it < 200 && hi - lo > 1e-15 * (1 + hi); ++it) {
    const double mid = 0.5 * (lo + hi);
    ((h(mid) > 0) == rising ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace detail

/// The critical point: the highest temperature of the spinodal ∂P/∂ρ = 0. Since P is linear in T
/// with ∂P/∂ρ = T·r(ρ) − s(ρ), the spinodal temperature at ρ is T_s(ρ) = s/r, found from two
/// derivative evaluations at T = 1 and T = 2.
template <LiquidVapourEos E>
CriticalPoint critical_point(const E& eos) {
  auto spinodal_T = [&](double rho) {
    const double d1 = eos.dpressure_drho(rho, 1.0), d2 = eos.dpressure_drho(rho, 2.0);
    const double r = d2 - d1, s = r - d1;
    return s / r;
  };
  const double top = eos.max_density();
  const double rho = detail::golden_max(spinodal_T, 1e-6 * top, (1 - 1e-6) * top);
  const double T = spinodal_T(rho);
  return {rho, T, eos.pressure(rho, T)};
}

/// Maxwell equal-area construction at T < T_c: P(ρ_v) = P(ρ_l) = P_sat and
/// ∫_{v_l}^{v_v} (P − P_sat) dv = 0 with v = 1/ρ (Simpson's rule on 4000 intervals in ρ).
template <LiquidVapourEos E>
Coexistence maxwell_construction(const E& eos, double T) {
  const CriticalPoint c = critical_point(eos);
  const double top = eos.max_density();
  const auto dp = [&](double rho) { return eos.dpressure_drho(rho, T); };
  const auto p = [&](double rho) { return eos.pressure(rho, T); };
  // Spinodal densities: P has a maximum at ρ_a < ρ_c and a minimum at ρ_b > ρ_c.
  const double rho_a = detail::bisect(dp, 1e-9 * top, c.rho);
  const double rho_b = detail::bisect(dp, c.rho, (1 - 1e-9) * top);
  const auto branches = [&](double ps, double& rv, double& rl) {
    rv = detail::bisect([&](double r) { return p(r) - ps; }, 1e-12 * top, rho_a);
    rl = detail::bisect([&](double r) { return p(r) - ps; }, rho_b, (1 - 1e-12) * top);
  };
  const auto area = [&](double ps) {
    double rv, rl;
    branches(ps, rv, rl);
    const int n = 4000;
    const double h = (rl - rv) / n;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
      const double r = rv + i * h;
      const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
      sum += w * (p(r) - ps) / (r * r);  // dv = −dρ/ρ²
    }
    return sum * h / 3.0;
  };
  const double p_lo = std::max(p(rho_b), 1e-14), p_hi = p(rho_a);
  Coexistence out;
  out.p_saturation = detail::bisect(area, p_lo, p_hi);
  branches(out.p_saturation, out.rho_vapour, out.rho_liquid);
  return out;
}

/// Surface tension of a flat interface of the square-gradient (GLS, constant K) model at T:
/// σ = ∫_{ρ_v}^{ρ_l} sqrt(2K ω(ρ)) dρ with the excess grand potential density
/// ω(ρ) = ∫_{ρ_v}^{ρ} (μ(s) − μ_sat) ds and μ(s) − μ_sat = ∫_{ρ_v}^{s} (∂P/∂ρ)/ρ dρ (Gibbs–Duhem at
/// fixed T), on a uniform grid of n intervals by the trapezoidal rule. The reference of the
/// Laplace law Δp = σ/R.
template <LiquidVapourEos E>
double interface_tension(const E& eos, double T, double K, int n = 20000) {
  const Coexistence co = maxwell_construction(eos, T);
  const double h = (co.rho_liquid - co.rho_vapour) / n;
  double mu = 0.0, omega = 0.0, sigma = 0.0;
  double g_prev = eos.dpressure_drho(co.rho_vapour, T) / co.rho_vapour, s_prev = 0.0;
  for (int i = 1; i <= n; ++i) {
    const double r = co.rho_vapour + i * h;
    const double g = eos.dpressure_drho(r, T) / r;
    const double mu_next = mu + 0.5 * h * (g_prev + g);
    omega += 0.5 * h * (mu + mu_next);
    mu = mu_next, g_prev = g;
    const double s = std::sqrt(2.0 * K * std::max(omega, 0.0));
    sigma += 0.5 * h * (s_prev + s);
    s_prev = s;
  }
  return sigma;
}

}  // namespace shockfield::dbm

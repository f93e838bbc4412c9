#pragma once
// Elastic–perfectly-plastic bars in uniaxial strain (strip.hpp) and their two-wave solution
// (e.g. Meyers, Dynamic Behavior of Materials, 1994, ch. 7): a body at speed v hits one at rest,
// u_p = v/2. With a linear bulk response (materials::elastic_plastic) the elastic precursor runs at
// c_L = √((K + 4G/3)/ρ) carrying σ_HEL = (K + 4G/3)·Y/(2G), u_HEL = σ_HEL/(ρc_L), and the plastic
// wave at c_b = √(K/ρ) to σ = σ_HEL + ρc_b(u_p − u_HEL), with the deviator at yield behind it:
// s_yy = −(2/3)Y (compression).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "shockfield/materials/library.hpp"
#include "strip.hpp"

namespace plastic_bar {

namespace mpm = shockfield::mpm;

struct Material {
  std::string name;
  double rho, young, poisson, yield;
  double k() const { return young / (3.0 * (1.0 - 2.0 * poisson)); }
  double g() const { return young / (2.0 * (1.0 + poisson)); }
  double cl() const { return std::sqrt((k() + 4.0 * g() / 3.0) / rho); }
  double cb() const { return std::sqrt(k() / rho); }
  double hel() const { return (k() + 4.0 * g() / 3.0) * yield / (2.0 * g()); }
  double u_hel() const { return hel() / (rho * cl()); }
  /// Longitudinal stress (compression positive) of the plastic state behind the second wave.
  double plateau(double up) const { return hel() + rho * cb() * (up - u_hel()); }
  shockfield::materials::SolidMaterial material(double viscosity_linear) const {
    auto m = shockfield::materials::elastic_plastic(name, rho, young, poisson, yield);
    m.viscosity.linear = viscosity_linear;
    return m;
  }
};

/// 6061-T6-like aluminium of test_waves.cpp: σ_HEL = 541.6 MPa, c_L = 6549.7, c_b = 5351.8 m/s.
inline Material aluminium() { return {"al6061", 2703.0, 77.11e9, 0.334, 270e6}; }
/// Copper-like: G = 47.7 GPa and Y = 120 MPa of the library copper (Steinberg 1996), ν = 0.34,
/// no hardening; Y/G = 0.25 %, the small elastic range that makes the deviator fragile.
inline Material copper() { return {"cu_like", 8930.0, 2.0 * 47.7e9 * 1.34, 0.34, 120e6}; }

struct Result {
  double plateau = 0.0;      ///< mean −σ_yy over the window [Pa]
  double reference = 0.0;    ///< two-wave value [Pa]
  double deviator = 0.0;     ///< mean s_yy / (−(2/3)Y) over the window (1 at yield)
  double deviator_min = 0.0; ///< the smallest of that ratio over five equal parts of the window
};

/// Impact at `speed` onto a body at rest, `cells` per body of size h, measured at t = 0.6·len/c_L
/// over y in [u_p·t + 5h, 0.7·y_plastic] in the body that was at rest: from five cells above the
/// impact face (which moves at u_p) to well behind the plastic front.
inline mpm::SimulationOptions gimp() {
  mpm::SimulationOptions o;
  o.shape = mpm::ShapeKind::Gimp;
  return o;
}
/// cpGIMP with the XPIC(2) velocity update and the smoothed dilatation (docs/theory/mpm.md,
/// "Deviatoric stress behind shocks": the two together keep s_yy at yield behind the plastic front).
inline mpm::SimulationOptions strength_preserving() {
  auto o = gimp();
  o.xpic_order = 2;
  o.smooth_dilatation = true;
  return o;
}
inline Result run(const Material& mat, double speed, double h, int cells, double viscosity_linear,
                  const mpm::SimulationOptions& options = gimp()) {
  strip::Setup s;
  s.h = h;
  s.cells = cells;
  s.v_lower = speed;
  s.options = options;
  auto sim = strip::make(s, mat.material(viscosity_linear));
  const double up = 0.5 * speed, t = 0.6 * cells * h / mat.cl();
  sim.run_until(t);
  const auto rows = strip::profile(sim.particles(), h);
  const double front = strip::front_from_top(rows, 0.5 * (mat.u_hel() + up));
  const double lo = up * t + 5 * h, hi = 0.7 * front;
  const double two_thirds_y = 2.0 / 3.0 * mat.yield;
  Result r;
  r.reference = mat.plateau(up);
  r.plateau = -strip::mean(rows, lo, hi, [](const strip::Row& w) { return w.syy; });
  r.deviator = -strip::mean(rows, lo, hi, [](const strip::Row& w) { return w.dev; }) / two_thirds_y;
  r.deviator_min = 1e300;
  for (int k = 0; k < 5; ++k) {
    const double a = lo + k * (hi - lo) / 5, b = lo + (k + 1) * (hi - lo) / 5;
    r.deviator_min = std::min(r.deviator_min, -strip::mean(rows, a, b, [](const strip::Row& w) { return w.dev; }) / two_thirds_y);
  }
  return r;
}

}  // namespace plastic_bar

#include "shockfield/granular/chain.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "shockfield/core/error.hpp"
#include "shockfield/granular/contact_law.hpp"

namespace shockfield::granular {
namespace {

void check_spec(const ChainSpec& s) {
  if (s.grains < 2) throw InputError(fmt::format("a chain needs at least 2 grains, not {}", s.grains));
  if (!(s.radius > 0) || !(s.density > 0) || !(s.youngs_modulus > 0))
    throw InputError("grain radius, density and Young's modulus must be positive");
  if (!(s.poisson_ratio > -1.0 && s.poisson_ratio < 0.5))
    throw InputError(fmt::format("Poisson's ratio {} is outside (-1, 0.5)", s.poisson_ratio));
  if (s.gap < 0)
    throw InputError(fmt::format("gap {} < 0: the initial grains would overlap beyond the static "
                                 "equilibrium", s.gap));
  if (s.gravity != 0 && s.wall == WallKind::none)
    throw InputError("a chain under gravity needs a bottom wall to rest on");
  if (s.gravity != 0 && s.gap != 0)
    throw InputError("a gap between grains is only an equilibrium without gravity");
  for (const Impurity& imp : s.impurities) {
    if (imp.index < 0 || imp.index >= s.grains)
      throw InputError(fmt::format("impurity index {} is outside the chain [0, {})", imp.index, s.grains));
    if (!(imp.mass_ratio > 0) || !(imp.radius_ratio > 0) || !(imp.modulus_ratio > 0))
      throw InputError(fmt::format("impurity {}: ratios must be positive", imp.index));
    if (imp.poisson_ratio && !(*imp.poisson_ratio > -1.0 && *imp.poisson_ratio < 0.5))
      throw InputError(fmt::format("impurity {}: Poisson's ratio {} is outside (-1, 0.5)", imp.index, *imp.poisson_ratio));
  }
}

}  // namespace

Chain build_chain(const ChainSpec& s) {
  check_spec(s);
  const auto n = static_cast<std::size_t>(s.grains);
  Chain c;
  c.gravity = s.gravity;
  c.damping = s.damping;
  const double grain_mass = 4.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius * s.density;
  c.mass.assign(n, grain_mass);
  c.radius.assign(n, s.radius);
  c.youngs_modulus.assign(n, s.youngs_modulus);
  c.poisson_ratio.assign(n, s.poisson_ratio);
  for (const Impurity& imp : s.impurities) {
    const auto i = static_cast<std::size_t>(imp.index);
    c.radius[i] *= imp.radius_ratio;
    c.mass[i] *= imp.mass_ratio * imp.radius_ratio * imp.radius_ratio * imp.radius_ratio;
    c.youngs_modulus[i] *= imp.modulus_ratio;
    if (imp.poisson_ratio) c.poisson_ratio[i] = *imp.poisson_ratio;
  }
  c.inv_mass.resize(n);
  for (std::size_t i = 0; i < n; ++i) c.inv_mass[i] = 1.0 / c.mass[i];

  const std::vector<double>& nu = c.poisson_ratio;
  c.kappa.resize(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k)
    c.kappa[k] = hertz_kappa(c.youngs_modulus[k], nu[k], c.radius[k], c.youngs_modulus[k + 1], nu[k + 1], c.radius[k + 1]);
  constexpr double inf = std::numeric_limits<double>::infinity();
  c.has_wall = s.wall != WallKind::none;
  if (s.wall == WallKind::rigid) c.wall_kappa = hertz_kappa(c.youngs_modulus[n - 1], nu[n - 1], c.radius[n - 1], inf, 0.0, inf);
  if (s.wall == WallKind::elastic) {
    if (!(s.wall_youngs_modulus > 0)) throw InputError("an elastic wall needs a positive Young's modulus");
    c.wall_kappa = hertz_kappa(c.youngs_modulus[n - 1], nu[n - 1], c.radius[n - 1], s.wall_youngs_modulus,
                               s.wall_poisson_ratio, inf);
  }

  // Static equilibrium: contact k holds the weight of grains 0..k, δ_k = (W_k/κ_k)^{2/3}.
  c.rest_overlap.resize(n - 1);
  double weight = 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    weight += c.mass[k] * s.gravity;
    c.rest_overlap[k] = s.gravity != 0 ? std::cbrt(weight * weight / (c.kappa[k] * c.kappa[k])) : -s.gap;
  }
  weight += c.mass[n - 1] * s.gravity;
  if (c.has_wall) c.wall_rest_overlap = s.gravity != 0 ? std::cbrt(weight * weight / (c.wall_kappa * c.wall_kappa)) : 0.0;

  c.depth.resize(n);
  c.depth[0] = c.radius[0];
  for (std::size_t k = 0; k + 1 < n; ++k)
    c.depth[k + 1] = c.depth[k] + c.radius[k] + c.radius[k + 1] - c.rest_overlap[k];
  return c;
}

}  // namespace shockfield::granular

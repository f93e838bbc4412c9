#include "shockfield/phasefield/sharp_front.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shockfield/core/error.hpp"

namespace shockfield::phasefield {

FrontLaw front_law_from_name(const std::string& name) {
  if (name == "paper") return FrontLaw::paper;
  if (name == "allen_cahn") return FrontLaw::allen_cahn;
  throw InputError(fmt::format("unknown sharp-front law '{}' (expected paper or allen_cahn)", name));
}

const char* front_law_name(FrontLaw law) { return law == FrontLaw::paper ? "paper" : "allen_cahn"; }

double SharpFrontLaw::fixed_radius() const {
  const double R = c0 != 0.0 ? -sigma() / c0 : 0.0;
  return R > 0.0 ? R : INFINITY;
}

double SharpFrontLaw::time_between(double R0, double R) const {
  const double s = sigma();
  if (c0 == 0.0) return (R * R - R0 * R0) / (2.0 * s);
  if (s == 0.0) return (R - R0) / c0;
  // ∫ R dR/(c₀R + σ) = R/c₀ − (σ/c₀²) ln(c₀R + σ); the log's argument keeps its sign between R₀ and R.
  const double ratio = (c0 * R + s) / (c0 * R0 + s);
  if (!(ratio > 0.0)) return NAN;
  return (R - R0) / c0 - s / (c0 * c0) * std::log(ratio);
}

// Linearising v = c₀ + sDκ about the sphere r = R + δ Y_l: the normal speed is ṙ to first order and
// κ = (n − 1)/R + [l(l + n − 2) − (n − 1)] δ Y_l/R² (the surface Laplacian's eigenvalue
// −l(l + n − 2)/R² on the (n − 1)-sphere), so δ̇ = sD[l(l + n − 2) − (n − 1)]/R² δ = sD(l − 1)(l + n − 1)/R² δ.
double SharpFrontLaw::mode_growth_rate(int l, double R) const {
  return sign() * D * (l - 1.0) * (l + dim - 1.0) / (R * R);
}

double SharpFrontLaw::advance(double R, double dt) const {
  const double s2 = 2.0 * sigma();
  const auto f = [&](double u) { return 2.0 * c0 * std::sqrt(std::max(u, 0.0)) + s2; };
  const double u = R * R;
  const double k1 = f(u), k2 = f(u + 0.5 * dt * k1), k3 = f(u + 0.5 * dt * k2), k4 = f(u + dt * k3);
  const double next = u + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  // A radius below 1e-12 of the step's start is gone (a 1D segment with c₀ < 0 reaches u = 0 tangentially).
  return next > 1e-24 * u ? std::sqrt(next) : 0.0;
}

std::vector<SharpDomain> sharp_domains(const std::vector<Domain>& domains) {
  std::vector<SharpDomain> out;
  for (const Domain& d : domains) {
    if (d.kind != Domain::Kind::sphere) throw InputError("the sharp-front model evolves spheres only");
    out.push_back({static_cast<std::int64_t>(out.size()) + 1, d.center, d.size[0]});
  }
  return out;
}

void advance_domains(const SharpFrontLaw& law, double dt, std::vector<SharpDomain>& domains) {
  for (SharpDomain& d : domains) d.radius = law.advance(d.radius, dt);
  std::erase_if(domains, [](const SharpDomain& d) { return !(d.radius > 0.0); });
}

NodeCover cover_nodes(const Grid& grid, const std::vector<SharpDomain>& domains, bool indicator) {
  std::vector<std::uint8_t> count(grid.size(), 0);
  NodeCover out;
  out.nodes_inside.assign(domains.size(), 0);
  for (std::size_t m = 0; m < domains.size(); ++m) {
    const SharpDomain& dom = domains[m];
    // The nodes of the domain's bounding box along each axis (all of a periodic axis shorter than
    // it), bounded in floating point before the conversion: any finite centre and radius is safe.
    std::array<int, 3> lo{0, 0, 0}, hi{0, 0, 0};
    for (int d = 0; d < grid.dim; ++d) {
      const double L = grid.length(d), n = grid.n[d];
      const double c = grid.periodic(d) ? dom.center[d] - L * std::floor(dom.center[d] / L) : dom.center[d];
      double first = std::floor((c - dom.radius) / grid.dx), last = std::ceil((c + dom.radius) / grid.dx);
      if (!grid.periodic(d)) first = std::clamp(first, 0.0, n), last = std::clamp(last, -1.0, n - 1);
      else if (!(last - first + 1 < n)) first = 0, last = n - 1;
      lo[d] = static_cast<int>(first), hi[d] = static_cast<int>(last);
    }
    const double R2 = dom.radius * dom.radius;
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) {
          const std::array<int, 3> node{i, j, k};
          std::array<int, 3> wrapped{0, 0, 0};
          double r2 = 0.0;
          for (int d = 0; d < grid.dim; ++d) {
            wrapped[d] = ((node[d] % grid.n[d]) + grid.n[d]) % grid.n[d];
            double x = wrapped[d] * grid.dx - dom.center[d];
            if (grid.periodic(d)) x -= grid.length(d) * std::round(x / grid.length(d));
            r2 += x * x;
          }
          if (r2 > R2) continue;
          std::uint8_t& c = count[grid.index(wrapped[0], wrapped[1], wrapped[2])];
          c = static_cast<std::uint8_t>(std::min(c + 1, 2));
          ++out.nodes_inside[m];
        }
  }
  std::size_t once = 0, twice = 0;
  for (const std::uint8_t c : count) once += c >= 1, twice += c >= 2;
  out.volume_fraction = static_cast<double>(once) / static_cast<double>(grid.size());
  out.overlap_fraction = static_cast<double>(twice) / static_cast<double>(grid.size());
  if (indicator) out.indicator.assign(count.begin(), count.end()), std::replace(out.indicator.begin(), out.indicator.end(), 2.0, 1.0);
  return out;
}

double ball_volume(double R, int dim) {
  if (dim == 1) return 2.0 * R;
  if (dim == 2) return std::numbers::pi * R * R;
  return 4.0 / 3.0 * std::numbers::pi * R * R * R;
}

double equivalent_radius(double volume, int dim) {
  if (dim == 1) return 0.5 * volume;
  if (dim == 2) return std::sqrt(volume / std::numbers::pi);
  return std::cbrt(volume / (4.0 / 3.0 * std::numbers::pi));
}

}  // namespace shockfield::phasefield

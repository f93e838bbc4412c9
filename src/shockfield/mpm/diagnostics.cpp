#include "shockfield/mpm/diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shockfield::mpm {

std::vector<WindowQuantity> window_quantities(int dim) {
  std::vector<WindowQuantity> q{{"density", "kg_m3"}, {"pressure", "Pa"}, {"temperature", "K"}, {"vx", "m_s"},
                                {"vy", "m_s"}};
  if (dim == 3) q.push_back({"vz", "m_s"});
  for (const char* s : {"longitudinal_stress", "longitudinal_deviator", "von_mises"}) q.push_back({s, "Pa"});
  return q;
}

double quantity(const Particles& p, std::size_t i, std::size_t q, int dim) {
  const auto velocities = static_cast<std::size_t>(dim);
  const int axis = dim - 1;
  if (q == 0) return p.density(i);
  if (q == 1) return -p.state[i].stress().trace() / 3.0;
  if (q == 2) return p.state[i].temperature;
  if (q < 3 + velocities) return p.v[i][static_cast<int>(q - 3)];
  switch (q - 3 - velocities) {
    case 0: return p.state[i].stress()(axis, axis);
    case 1: return p.state[i].deviatoric.s(axis, axis);
    default: return materials::von_mises(p.state[i].deviatoric.s);
  }
}

std::array<double, 3> gradient_squares(const Mat3& l) {
  const Vec3 curl(l(2, 1) - l(1, 2), l(0, 2) - l(2, 0), l(1, 0) - l(0, 1));  // L_ij = ∂v_i/∂x_j
  const Mat3 d = 0.5 * (l + l.transpose());
  const double div = l.trace();
  return {curl.squaredNorm(), div * div, d.cwiseProduct(d).sum()};
}

WindowStats window_stats(const Particles& p, int dim, double lo, double hi, double cross_section) {
  const int axis = dim - 1;
  const std::size_t nq = window_quantities(dim).size();
  WindowStats w;
  w.mean.assign(nq, 0.0);
  w.std.assign(nq, 0.0);
  double mass = 0.0, volume = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!(p.x[i][axis] >= lo && p.x[i][axis] < hi)) continue;
    ++w.count;
    mass += p.mass[i];
    const double v = p.volume(i);
    volume += v;
    const auto g = gradient_squares(p.velocity_gradient[i]);
    for (std::size_t k = 0; k < 3; ++k) w.gradients[k] += v * g[k];
    for (std::size_t q = 0; q < nq; ++q) w.mean[q] += quantity(p, i, q, dim);
  }
  w.bulk_density = mass / ((hi - lo) * cross_section);
  if (w.count == 0) {
    w.mean.assign(nq, std::numeric_limits<double>::quiet_NaN());
    w.std = w.mean;
    w.gradients.fill(std::numeric_limits<double>::quiet_NaN());
    return w;
  }
  for (auto& m : w.mean) m /= static_cast<double>(w.count);
  for (auto& g : w.gradients) g /= volume;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!(p.x[i][axis] >= lo && p.x[i][axis] < hi)) continue;
    for (std::size_t q = 0; q < nq; ++q) {
      const double d = quantity(p, i, q, dim) - w.mean[q];
      w.std[q] += d * d;
    }
  }
  for (auto& s : w.std) s = std::sqrt(s / static_cast<double>(w.count));
  return w;
}

double highest(const Particles& p, int axis) {
  double top = -std::numeric_limits<double>::infinity();
  for (const Vec3& x : p.x) top = std::max(top, x[axis]);
  return top;
}

Ejecta ejecta(const Particles& p, const Grid& grid, double threshold) {
  const GridSpec& g = grid.spec();
  const int axis = g.dim - 1;
  // Lateral columns one cell wide; the surface is the median of the columns' highest particles.
  std::array<long, 2> n{1, 1};
  for (int a = 0; a < axis; ++a) n[static_cast<std::size_t>(a)] = std::max(1, g.cells[static_cast<std::size_t>(a)]);
  std::vector<double> tops(static_cast<std::size_t>(n[0] * n[1]), -std::numeric_limits<double>::infinity());
  for (const Vec3& x : p.x) {
    long c = 0;
    for (int a = axis - 1; a >= 0; --a) {
      const long i = std::clamp(static_cast<long>(std::floor((x[a] - g.origin[a]) / g.cell_size[a])), 0L,
                                n[static_cast<std::size_t>(a)] - 1);
      c = c * n[static_cast<std::size_t>(a)] + i;
    }
    double& t = tops[static_cast<std::size_t>(c)];
    t = std::max(t, x[axis]);
  }
  std::erase_if(tops, [](double t) { return !std::isfinite(t); });
  Ejecta e;
  if (tops.empty()) return e;
  std::nth_element(tops.begin(), tops.begin() + static_cast<long>(tops.size() / 2), tops.end());
  e.surface = tops[tops.size() / 2];
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double above = p.x[i][axis] - e.surface;
    e.max_height = std::max(e.max_height, above);
    if (above > threshold) e.mass += p.mass[i], e.count += 1.0;
  }
  return e;
}

}  // namespace shockfield::mpm

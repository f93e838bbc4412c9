#include "shockfield/mpm/cavity_tracker.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace shockfield::mpm {

namespace {

// Enlargement of each particle's domain when it is rasterised: neighbouring domains of a
// non-uniformly deformed body leave slivers between them that the raster would otherwise see as
// channels out of the cavity; 5 % of the half-width closes them and shifts the rim by 0.05·l_p.
constexpr double kDomainSlack = 1.05;

std::size_t raster_index(const std::array<int, 3>& dims, int i, int j, int k) {
  return (static_cast<std::size_t>(k) * dims[1] + j) * dims[0] + i;
}

}  // namespace

CavityTracker::CavityTracker(int dim, const Void& initial, double spacing)
    : dim_(dim), r0_(initial.radius), cell_(0.5 * spacing), centre_(initial.centre), radius_(initial.radius) {}

CavityMeasure CavityTracker::measure(const Particles& p, double t) {
  const int axis = dim_ - 1;
  // Move the centre with the surrounding material.
  Vec3 ring_v = Vec3::Zero();
  double ring_n = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = (p.x[i] - centre_).norm();
    if (r > radius_ && r < 2.0 * radius_ + 2.0 * cell_) ring_v += p.v[i], ring_n += 1.0;
  }
  if (ring_n > 0.0) centre_ += (t - last_time_) * ring_v / ring_n;
  last_time_ = t;

  // Raster of the box around the centre; covered[c] = 1 where a particle's box reaches.
  const double half = 2.0 * std::max(r0_, radius_) + 4.0 * cell_;
  const int n = static_cast<int>(std::ceil(2.0 * half / cell_));
  const std::array<int, 3> dims{n, n, dim_ == 3 ? n : 1};
  Vec3 lo = centre_ - Vec3::Constant(half);
  if (dim_ == 2) lo[2] = 0.0;
  std::vector<std::uint8_t> covered(static_cast<std::size_t>(dims[0]) * dims[1] * dims[2], 0);
  auto flat = [&](int i, int j, int k) { return raster_index(dims, i, j, k); };
  for (std::size_t q = 0; q < p.size(); ++q) cover_domain(p.x[q], p.half_size[q], p.state[q].deformation, lo, dims, covered);

  // Flood fill from the uncovered cells within the last radius of the centre.
  std::vector<std::uint8_t> seen(covered.size(), 0);
  std::size_t cells = 0;
  Vec3 sum = Vec3::Zero();
  std::array<int, 3> mn{n, n, n}, mx{-1, -1, -1};
  std::vector<std::array<int, 3>> stack, component;
  const double seed_r = std::max(radius_, 1.5 * cell_);
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) {
        const Vec3 c = lo + cell_ * Vec3(i + 0.5, j + 0.5, dim_ == 3 ? k + 0.5 : 0.0);
        const std::size_t s = flat(i, j, k);
        if (covered[s] || seen[s] || (c - centre_).norm() > seed_r) continue;
        bool open = false;
        component.clear();
        stack.push_back({i, j, k});
        seen[s] = 1;
        while (!stack.empty()) {
          const auto cur = stack.back();
          stack.pop_back();
          component.push_back(cur);
          for (int d = 0; d < dim_; ++d)
            for (int step : {-1, 1}) {
              auto nb = cur;
              nb[d] += step;
              if (nb[d] < 0 || nb[d] >= dims[d]) {
                open = true;
                continue;
              }
              const std::size_t f = flat(nb[0], nb[1], nb[2]);
              if (!covered[f] && !seen[f]) seen[f] = 1, stack.push_back(nb);
            }
        }
        if (open) continue;  // connected to the outside of the box: not the cavity
        for (const auto& c3 : component) {
          ++cells;
          sum += lo + cell_ * Vec3(c3[0] + 0.5, c3[1] + 0.5, dim_ == 3 ? c3[2] + 0.5 : 0.0);
          for (int d = 0; d < 3; ++d) mn[d] = std::min(mn[d], c3[d]), mx[d] = std::max(mx[d], c3[d]);
        }
      }

  CavityMeasure m;
  m.size = static_cast<double>(cells) * std::pow(cell_, dim_);
  if (cells > 0) {
    centre_ = sum / static_cast<double>(cells);
    m.horizontal = (mx[0] - mn[0] + 1) * cell_;
    m.vertical = (mx[axis] - mn[axis] + 1) * cell_;
  }
  radius_ = std::max(dim_ == 2 ? std::sqrt(m.size / std::numbers::pi) : std::cbrt(0.75 * m.size / std::numbers::pi), cell_);
  if (a0_ < 0.0) a0_ = m.size;
  m.collapsibility = a0_ > 0.0 ? (a0_ - m.size) / a0_ : 0.0;

  // Velocities of the columns above and below (lateral distance <= r0 from the centre).
  m.v_up_above = -INFINITY, m.v_down_below = INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i) {
    Vec3 d = p.x[i] - centre_;
    const double along = d[axis];
    d[axis] = 0.0;
    if (d.norm() > r0_) continue;
    if (along > 0.0) m.v_up_above = std::max(m.v_up_above, p.v[i][axis]);
    else m.v_down_below = std::min(m.v_down_below, p.v[i][axis]);
  }
  if (!std::isfinite(m.v_up_above)) m.v_up_above = NAN;
  if (!std::isfinite(m.v_down_below)) m.v_down_below = NAN;
  return m;
}

void CavityTracker::cover_domain(const Vec3& x, const Vec3& half, const Mat3& deformation, const Vec3& lo,
                                 const std::array<int, 3>& dims, std::vector<std::uint8_t>& covered) const {
  // The particle's current domain is x + F·ξ with |ξ_d| <= half_d (its reference box carried by
  // the deformation gradient, as in CPDI): a parallelogram (parallelepiped in 3D). Scan the raster
  // cells of its axis-aligned bounding box and keep those whose centre maps back into the box.
  Mat3 f = Mat3::Identity();
  f.topLeftCorner(dim_, dim_) = deformation.topLeftCorner(dim_, dim_);
  const Mat3 f_inv = f.inverse();
  std::array<int, 3> b{0, 0, 0}, e{0, 0, 0};
  for (int d = 0; d < dim_; ++d) {
    double reach = 0.0;  // half-width of the bounding box along d
    for (int j = 0; j < dim_; ++j) reach += std::abs(f(d, j)) * half[j];
    // cells whose centre lo + (i + ½)cell lies in [x − reach, x + reach]
    b[d] = std::max(0, static_cast<int>(std::ceil((x[d] - reach - lo[d]) / cell_ - 0.5)));
    e[d] = std::min(dims[d] - 1, static_cast<int>(std::floor((x[d] + reach - lo[d]) / cell_ - 0.5)));
    if (b[d] > e[d]) return;
  }
  for (int k = b[2]; k <= e[2]; ++k)
    for (int j = b[1]; j <= e[1]; ++j)
      for (int i = b[0]; i <= e[0]; ++i) {
        const Vec3 c = lo + cell_ * Vec3(i + 0.5, j + 0.5, dim_ == 3 ? k + 0.5 : 0.0);
        Vec3 xi = f_inv * (c - x);
        if (dim_ == 2) xi[2] = 0.0;
        bool inside = true;
        for (int d = 0; d < dim_; ++d) inside = inside && std::abs(xi[d]) <= half[d] * kDomainSlack;
        if (inside) covered[raster_index(dims, i, j, k)] = 1;
      }
}

std::vector<double> CavityTracker::state() const {
  return {centre_[0], centre_[1], centre_[2], radius_, a0_, last_time_};
}

void CavityTracker::restore(const std::vector<double>& s) {
  centre_ = Vec3(s.at(0), s.at(1), s.at(2));
  radius_ = s.at(3);
  a0_ = s.at(4);
  last_time_ = s.at(5);
}

}  // namespace shockfield::mpm

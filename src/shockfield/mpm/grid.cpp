#include "shockfield/mpm/grid.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::mpm {

namespace {
constexpr const char* kAxis = "xyz";
}

void GridSpec::validate() const {
  if (dim != 2 && dim != 3) throw InputError(fmt::format("mpm grid: dim = {} (expected 2 or 3)", dim));
  for (int a = 0; a < dim; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    if (!(cell_size[a] > 0.0) || !std::isfinite(cell_size[a]))
      throw InputError(fmt::format("mpm grid: cell size along {} = {} m (expected > 0)", kAxis[a], cell_size[a]));
    if (cells[ua] < 1)
      throw InputError(fmt::format("mpm grid: cells along {} = {} (expected >= 1)", kAxis[a], cells[ua]));
    if (periodic[ua] && (walls[ua][0] != Wall::Free || walls[ua][1] != Wall::Free))
      throw InputError(fmt::format("mpm grid: axis {} is periodic and cannot also have a wall", kAxis[a]));
  }
}

Grid::Grid(const GridSpec& spec, bool allocate_now) : spec_(spec) {
  spec_.validate();
  if (spec_.dim == 2) {
    spec_.cells[2] = 0;
    spec_.periodic[2] = false;
  }
  for (std::size_t a = 0; a < 3; ++a) nodes_[a] = spec_.periodic[a] ? spec_.cells[a] : spec_.cells[a] + 1;
  size_ = static_cast<std::size_t>(nodes_[0]) * static_cast<std::size_t>(nodes_[1]) *
          static_cast<std::size_t>(nodes_[2]);
  if (allocate_now) allocate();
}

void Grid::allocate() {
  const std::size_t n = field_size();
  if (mass.size() == n) return;
  mass.assign(n, 0.0);
  momentum.assign(n, Vec3::Zero());
  force.assign(n, Vec3::Zero());
  mass_gradient.assign(layers_ > 1 ? n : 0, Vec3::Zero());
}

std::array<int, 3> Grid::unflatten(std::size_t n) const {
  const auto nx = static_cast<std::size_t>(nodes_[0]), ny = static_cast<std::size_t>(nodes_[1]);
  return {static_cast<int>(n % nx), static_cast<int>((n / nx) % ny), static_cast<int>(n / (nx * ny))};
}

int Grid::wrap(int axis, int i) const {
  const int n = nodes_[static_cast<std::size_t>(axis)];
  if (spec_.periodic[static_cast<std::size_t>(axis)]) return ((i % n) + n) % n;
  return (i >= 0 && i < n) ? i : -1;
}

double Grid::min_cell_size() const {
  double h = spec_.cell_size[0];
  for (int a = 1; a < spec_.dim; ++a) h = std::min(h, spec_.cell_size[a]);
  return h;
}

double Grid::wrap_periodic(double r, double len) {
  r -= len * std::floor(r / len);
  return r >= len ? 0.0 : r;  // round-off of the floor above
}

bool Grid::fit_edge(int axis, Weights1D& w) const {
  if (spec_.periodic[static_cast<std::size_t>(axis)]) {
    w.base = wrap(axis, w.base);
    return true;
  }
  const int n = nodes_[static_cast<std::size_t>(axis)];
  auto shift = [&w](int by) {  // move the window by `by` nodes, dropping what falls off
    std::array<double, 3> ws{0, 0, 0}, ds{0, 0, 0};
    for (int k = 0; k < w.count; ++k) {
      const int src = k + by;
      if (src >= 0 && src < w.count) {
        ws[static_cast<std::size_t>(k)] = w.w[static_cast<std::size_t>(src)];
        ds[static_cast<std::size_t>(k)] = w.dw[static_cast<std::size_t>(src)];
      }
    }
    w.w = ws;
    w.dw = ds;
    w.base += by;
  };
  if (w.base < -1 || w.base + 1 > n) return false;  // the particle is off the grid
  if (w.base < 0) shift(-w.base);
  if (w.base + w.count > n) shift(n - w.count - w.base);
  return w.base >= 0;
}

void Grid::apply_walls(std::vector<Vec3>& p) const {
  for (int a = 0; a < spec_.dim; ++a) {
    for (int side = 0; side < 2; ++side) {
      const Wall wall = spec_.walls[static_cast<std::size_t>(a)][static_cast<std::size_t>(side)];
      if (wall == Wall::Free || spec_.periodic[static_cast<std::size_t>(a)]) continue;
      const int layer = side == 0 ? 0 : nodes_[static_cast<std::size_t>(a)] - 1;
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      for (int jb = 0; jb < nodes_[static_cast<std::size_t>(b)]; ++jb) {
        for (int jc = 0; jc < nodes_[static_cast<std::size_t>(c)]; ++jc) {
          std::array<int, 3> ijk{};
          ijk[static_cast<std::size_t>(a)] = layer;
          ijk[static_cast<std::size_t>(b)] = jb;
          ijk[static_cast<std::size_t>(c)] = jc;
          for (std::size_t at = flat(ijk[0], ijk[1], ijk[2]); at < p.size(); at += size_) {  // each layer
            Vec3& m = p[at];
            if (wall == Wall::Stick) m.setZero();
            else m[a] = 0.0;
          }
        }
      }
    }
  }
}

}  // namespace shockfield::mpm

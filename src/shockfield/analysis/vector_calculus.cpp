#include "shockfield/analysis/vector_calculus.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis {
namespace {

void check_components(std::initializer_list<const GridField*> components, int dimension) {
  const GridField& first = **components.begin();
  int i = 0;
  for (const GridField* c : components) {
    const std::string name = fmt::format("component {}", "xyz"[i++]);
    validate(*c, name);
    require_same_grid(first, *c, "component x", name);
  }
  if (first.dimension() != dimension)
    throw InputError(fmt::format("expected {} components for a {}D grid", first.dimension(),
                                 first.dimension()));
}

// ∂f/∂(axis) at every cell; marks void where a used cell is void.
GridField derivative(const GridField& f, int axis, bool periodic) {
  GridField d = f;
  d.is_void.assign(f.size(), 0);
  const std::size_t n = f.n[axis];
  const std::size_t stride = axis == 0 ? 1 : axis == 1 ? f.n[0] : f.n[0] * f.n[1];
  const auto total = static_cast<std::ptrdiff_t>(f.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ii = 0; ii < total; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    const std::size_t j = (i / stride) % n;
    std::size_t lo = i, hi = i;
    double span = 0.0;
    if (n > 1) {
      if (j > 0) lo = i - stride, span += 1.0;
      else if (periodic) lo = i + (n - 1) * stride, span += 1.0;
      if (j + 1 < n) hi = i + stride, span += 1.0;
      else if (periodic) hi = i - (n - 1) * stride, span += 1.0;
    }
    if (span == 0.0 || f.void_at(i) || f.void_at(lo) || f.void_at(hi)) {
      d.is_void[i] = 1, d.values[i] = 0.0;
      continue;
    }
    d.values[i] = (f.values[hi] - f.values[lo]) / (span * f.spacing[axis]);
  }
  return d;
}

// a + sign × b, void where either is void.
GridField combine(const GridField& a, const GridField& b, double sign) {
  GridField out = a;
  for (std::size_t i = 0; i < a.size(); ++i) {
    out.is_void[i] = a.is_void[i] | b.is_void[i];
    out.values[i] = out.is_void[i] ? 0.0 : a.values[i] + sign * b.values[i];
  }
  return out;
}

}  // namespace

GridField divergence(const GridField& vx, const GridField& vy, const GridField* vz,
                     bool periodic) {
  if (vz) check_components({&vx, &vy, vz}, 3);
  else check_components({&vx, &vy}, 2);
  GridField div = combine(derivative(vx, 0, periodic), derivative(vy, 1, periodic), 1.0);
  return vz ? combine(div, derivative(*vz, 2, periodic), 1.0) : div;
}

GridField curl_2d(const GridField& vx, const GridField& vy, bool periodic) {
  check_components({&vx, &vy}, 2);
  return combine(derivative(vy, 0, periodic), derivative(vx, 1, periodic), -1.0);
}

std::array<GridField, 3> curl_3d(const GridField& vx, const GridField& vy, const GridField& vz,
                                 bool periodic) {
  check_components({&vx, &vy, &vz}, 3);
  return {combine(derivative(vz, 1, periodic), derivative(vy, 2, periodic), -1.0),
          combine(derivative(vx, 2, periodic), derivative(vz, 0, periodic), -1.0),
          combine(derivative(vy, 0, periodic), derivative(vx, 1, periodic), -1.0)};
}

}  // namespace shockfield::analysis

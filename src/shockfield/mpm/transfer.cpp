#include "shockfield/mpm/transfer.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::mpm {

template <int Dim, class Shape, bool Contiguous>
void Transfer::evaluate(const Grid& grid, const Particles& p) {
  auto& stencils = [&]() -> auto& {
    if constexpr (Dim == 2) return stencils2_;
    else return stencils3_;
  }();
  stencils.resize(p.size());
  bin_of_.resize(p.size());
  const auto origin = grid.spec().origin;  // local copies: invariant in the loop (stores to the
  const auto cell = grid.spec().cell_size;  // stencils cannot alias them), so 1/h is hoisted
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  const bool layered = grid.layers() > 1;
  std::ptrdiff_t lost = -1;
#pragma omp parallel for schedule(static) reduction(max : lost)
  for (std::ptrdiff_t q = 0; q < n; ++q) {
    const auto uq = static_cast<std::size_t>(q);
    Stencil<Dim>& s = stencils[uq];
    for (int a = 0; a < Dim; ++a) {
      double half = p.half_size[uq][a];
      if constexpr (Contiguous) half = contiguous_half_width(half, p.state[uq].deformation(a, a), cell[a]);
      Weights1D w = Shape::evaluate(p.x[uq][a] - origin[a], cell[a], half);
      if (!grid.fit(a, w)) lost = std::max(lost, q);
      const auto ua = static_cast<std::size_t>(a);
      s.base[ua] = w.base;
      s.w[ua] = w.w;
      s.dw[ua] = w.dw;
    }
    bin_of_[uq] = grid.flat(s.base[0], s.base[1], Dim == 3 ? s.base[Dim - 1] : 0);
    if (layered) s.base[0] += p.body[uq] * static_cast<int>(row_);  // the body's block of x offsets
  }
  if (lost >= 0) {
    const Vec3& x = p.x[static_cast<std::size_t>(lost)];
    throw RunError(fmt::format("mpm: particle {} at ({}, {}, {}) m has left the grid", lost, x[0], x[1], x[2]));
  }
}

void Transfer::bin(const Grid& grid) {
  // Counting sort by the first node of the stencil; stable, so particle order within a bin.
  bin_start_.assign(grid.size() + 1, 0);
  for (const std::size_t b : bin_of_) ++bin_start_[b + 1];
  for (std::size_t b = 0; b < grid.size(); ++b) bin_start_[b + 1] += bin_start_[b];
  binned_.resize(bin_of_.size());
  std::vector<std::size_t> fill(bin_start_.begin(), bin_start_.end() - 1);
  for (std::size_t q = 0; q < bin_of_.size(); ++q) binned_[fill[bin_of_[q]]++] = q;
}

void Transfer::build(const Grid& grid, const Particles& p, ShapeKind shape) {
  dim_ = grid.dim();
  support_ = shape == ShapeKind::Linear ? LinearShape::support : GimpShape::support;
  for (std::size_t a = 0; a < 3; ++a) node_count_[a] = grid.nodes(static_cast<int>(a));
  stride_ = {1, static_cast<std::size_t>(node_count_[0]),
             static_cast<std::size_t>(node_count_[0]) * static_cast<std::size_t>(node_count_[1])};
  for (std::size_t a = 0; a < 3; ++a) {  // a wrapped base plus k < support runs past the end only when periodic
    offset_[a].resize(static_cast<std::size_t>(node_count_[a] + support_));
    for (int i = 0; i < node_count_[a] + support_; ++i)
      offset_[a][static_cast<std::size_t>(i)] = static_cast<std::size_t>(i % node_count_[a]) * stride_[a];
  }
  // With contact, one block of x offsets per body layer, shifted by the layer's start b·nodes.
  row_ = offset_[0].size();
  const auto bodies = static_cast<std::size_t>(grid.layers());
  offset_[0].resize(bodies * row_);
  for (std::size_t b = 1; b < bodies; ++b)
    for (std::size_t i = 0; i < row_; ++i) offset_[0][b * row_ + i] = offset_[0][i] + b * grid.size();
  if (dim_ == 2) {
    stencils3_.clear();
    if (shape == ShapeKind::Linear) evaluate<2, LinearShape, false>(grid, p);
    else if (shape == ShapeKind::Gimp) evaluate<2, GimpShape, true>(grid, p);
    else evaluate<2, GimpShape, false>(grid, p);
  } else {
    stencils2_.clear();
    if (shape == ShapeKind::Linear) evaluate<3, LinearShape, false>(grid, p);
    else if (shape == ShapeKind::Gimp) evaluate<3, GimpShape, true>(grid, p);
    else evaluate<3, GimpShape, false>(grid, p);
  }
  bin(grid);

  // Slabs of two layers along the outermost axis; the layers a slab's stencils touch are
  // [2s, 2s + 1 + support). Even slabs, then odd slabs, then (periodic axis) the slabs reaching
  // past the last layer, each alone.
  const auto outer = static_cast<std::size_t>(dim_ - 1);
  const int layers = node_count_[outer];
  const std::size_t slabs = static_cast<std::size_t>(layers + 1) / 2;
  slab_bins_ = 2 * stride_[outer];
  passes_.assign(2, {});
  for (std::size_t s = 0; s < slabs; ++s) {
    const bool wraps = static_cast<int>(2 * s) + 1 + support_ > layers;
    if (wraps && grid.spec().periodic[outer]) passes_.push_back({s});
    else passes_[s % 2].push_back(s);
  }
}

void Transfer::to_grid(Grid& grid, const Particles& p, const std::vector<double>& mean_stress_correction) const {
  const auto nn = static_cast<std::ptrdiff_t>(grid.field_size());
  const bool gradient = !grid.mass_gradient.empty();
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < nn; ++i) {
    const auto u = static_cast<std::size_t>(i);
    grid.mass[u] = 0.0;
    grid.momentum[u].setZero();
    grid.force[u].setZero();
    if (gradient) grid.mass_gradient[u].setZero();
  }
  dispatch([&](auto kernel) {
    scatter<decltype(kernel.first)::value, decltype(kernel.second)::value, true>(
        grid, p, [](std::size_t, const auto&, const auto&) {}, mean_stress_correction);
  });
}

void Transfer::mass_weighted_to_grid(const Particles& p, const std::vector<Vec3>& u, std::vector<Vec3>& out) const {
  const auto nn = static_cast<std::ptrdiff_t>(out.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < nn; ++i) out[static_cast<std::size_t>(i)].setZero();
  scatter_each<true>([&](std::size_t q, auto&& each) {
    const Vec3 weighted = p.mass[q] * u[q];
    each([&](std::size_t i, double w, const auto&) { out[i] += w * weighted; });
  });
}

}  // namespace shockfield::mpm

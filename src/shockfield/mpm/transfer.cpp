#include "shockfield/mpm/transfer.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::mpm {

template <ShapeFunction S>
void Transfer::evaluate(const Grid& grid, const Particles& p) {
  const GridSpec& spec = grid.spec();
  const auto n = static_cast<std::ptrdiff_t>(p.size());
  std::ptrdiff_t lost = -1;
#pragma omp parallel for schedule(static) reduction(max : lost)
  for (std::ptrdiff_t q = 0; q < n; ++q) {
    const auto uq = static_cast<std::size_t>(q);
    Stencil& s = stencils_[uq];
    s[2] = Weights1D{};
    for (int a = 0; a < spec.dim; ++a) {
      s[static_cast<std::size_t>(a)] =
          S::evaluate(p.x[uq][a] - spec.origin[a], spec.cell_size[a], p.half_size[uq][a]);
      if (!grid.fit(a, s[static_cast<std::size_t>(a)])) lost = std::max(lost, q);
    }
  }
  if (lost >= 0) {
    const Vec3& x = p.x[static_cast<std::size_t>(lost)];
    throw RunError(fmt::format("mpm: particle {} at ({}, {}, {}) m has left the grid", lost, x[0], x[1], x[2]));
  }
}

void Transfer::build(const Grid& grid, const Particles& p, ShapeKind shape) {
  stencils_.resize(p.size());
  if (shape == ShapeKind::Linear) evaluate<LinearShape>(grid, p);
  else evaluate<GimpShape>(grid, p);

  // Counting sort by the first node of the stencil; stable, so particle order within a bin.
  bin_start_.assign(grid.size() + 1, 0);
  auto bin_of = [&](const Stencil& s) { return grid.flat(s[0].base, s[1].base, s[2].base); };
  for (const Stencil& s : stencils_) ++bin_start_[bin_of(s) + 1];
  for (std::size_t b = 0; b < grid.size(); ++b) bin_start_[b + 1] += bin_start_[b];
  binned_.resize(p.size());
  std::vector<std::size_t> fill(bin_start_.begin(), bin_start_.end() - 1);
  for (std::size_t q = 0; q < p.size(); ++q) binned_[fill[bin_of(stencils_[q])]++] = q;
}

void Transfer::to_grid(Grid& grid, const Particles& p, bool with_force) {
  const auto np = static_cast<std::ptrdiff_t>(p.size());
  momentum_.resize(p.size());
  volume_stress_.resize(p.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t q = 0; q < np; ++q) {
    const auto uq = static_cast<std::size_t>(q);
    momentum_[uq] = p.mass[uq] * p.v[uq];
    if (with_force) volume_stress_[uq] = p.volume(uq) * p.state[uq].stress();
  }

  const GridSpec& spec = grid.spec();
  const int support = stencils_.empty() ? 1 : stencils_[0][0].count;
  const int support_z = spec.dim == 3 ? support : 1;
  const auto nn = static_cast<std::ptrdiff_t>(grid.size());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t node = 0; node < nn; ++node) {
    const auto [i, j, k] = grid.unflatten(static_cast<std::size_t>(node));
    double m = 0.0;
    Vec3 mv = Vec3::Zero(), f = Vec3::Zero();
    for (int c = 0; c < support_z; ++c) {
      const int bk = grid.wrap(2, k - c);
      if (bk < 0) continue;
      for (int b = 0; b < support; ++b) {
        const int bj = grid.wrap(1, j - b);
        if (bj < 0) continue;
        for (int a = 0; a < support; ++a) {
          const int bi = grid.wrap(0, i - a);
          if (bi < 0) continue;
          const std::size_t bin = grid.flat(bi, bj, bk);
          for (std::size_t e = bin_start_[bin]; e < bin_start_[bin + 1]; ++e) {
            const std::size_t q = binned_[e];
            const auto [w, grad] = weight(stencils_[q], a, b, c);
            m += w * p.mass[q];
            mv += w * momentum_[q];
            if (with_force) f -= volume_stress_[q] * grad;  // eq. 12, σ symmetric
          }
        }
      }
    }
    const auto un = static_cast<std::size_t>(node);
    grid.mass[un] = m;
    grid.momentum[un] = mv;
    if (with_force) grid.force[un] = f;
  }
}

}  // namespace shockfield::mpm

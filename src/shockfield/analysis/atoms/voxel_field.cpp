#include "shockfield/analysis/atoms/voxel_field.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/core/size_limits.hpp"

namespace shockfield::analysis::atoms {
namespace {

// Normalised Gaussian weights exp(−k²/2s²) for k = −r … r, s = σ/h in nodes, r = ceil(4s).
std::vector<double> gaussian_taps(double sigma_nodes) {
  const int r = static_cast<int>(std::ceil(4.0 * sigma_nodes));
  std::vector<double> w(static_cast<std::size_t>(2 * r + 1));
  double sum = 0.0;
  for (int k = -r; k <= r; ++k) sum += w[static_cast<std::size_t>(k + r)] = std::exp(-0.5 * k * k / (sigma_nodes * sigma_nodes));
  for (double& v : w) v /= sum;
  return w;
}

// Convolves `f` along axis d with `taps` (periodic wrap, or truncated at the walls).
void smooth_axis(std::vector<double>& f, const VoxelField& g, int d, const std::vector<double>& taps) {
  const auto n = g.n;
  const long r = static_cast<long>(taps.size() / 2), len = static_cast<long>(n[d]);
  const std::size_t stride = d == 0 ? 1 : d == 1 ? n[0] : n[0] * n[1];
  const std::size_t lines = f.size() / n[d];
  std::vector<double> out(f.size());
#pragma omp parallel for schedule(static)
  for (std::size_t line = 0; line < lines; ++line) {
    // The first node of the line: the index with coordinate 0 along d.
    const std::size_t lo = line % stride, hi = line / stride;
    const std::size_t base = lo + hi * stride * n[d];
    for (long i = 0; i < len; ++i) {
      double s = 0.0;
      for (long k = -r; k <= r; ++k) {
        long j = i + k;
        if (g.periodic[d]) j = ((j % len) + len) % len;
        else if (j < 0 || j >= len) continue;
        s += taps[static_cast<std::size_t>(k + r)] * f[base + static_cast<std::size_t>(j) * stride];
      }
      out[base + static_cast<std::size_t>(i) * stride] = s;
    }
  }
  f.swap(out);
}

}  // namespace

VoxelField voxel_fraction(const AtomFrame& frame, const std::vector<bool>& selected, const VoxelOptions& o) {
  if (!(o.spacing > 0.0) || !std::isfinite(o.spacing)) throw InputError(fmt::format("voxel spacing {} Å: expected a positive number", o.spacing));
  if (!(o.smoothing >= 0.0) || !std::isfinite(o.smoothing))
    throw InputError(fmt::format("voxel smoothing {} Å: expected a number >= 0", o.smoothing));
  if (selected.size() != frame.size()) throw InputError("voxel field: one selection flag per atom expected");
  geometry::require_orthogonal(frame.box, "a voxel field (a grid along x, y, z)");
  VoxelField g;
  g.spacing = o.spacing;
  double nodes = 1.0;
  for (int d = 0; d < 3; ++d) {
    const double L = frame.box.length()[d];
    g.periodic[d] = frame.box.periodic(d);
    g.origin[d] = frame.box.lo[d];
    const long cells = std::lround(L / o.spacing);
    if (cells < 1 || o.spacing > L)
      throw InputError(fmt::format("voxel spacing {} Å is longer than the box along {} ({} Å)", o.spacing, "xyz"[d], L));
    g.n[d] = static_cast<std::size_t>(cells + (g.periodic[d] ? 0 : 1));
    g.stretch[d] = static_cast<double>(cells) * o.spacing / L;
    nodes *= static_cast<double>(g.n[d]);
  }
  if (nodes > kMaxGridPoints)
    throw InputError(fmt::format("voxel spacing {} Å gives {:.3g} nodes; expected at most {:.0e}", o.spacing, nodes, kMaxGridPoints));
  std::vector<double> weight(static_cast<std::size_t>(nodes), 0.0), chosen(weight.size(), 0.0);
  // Cloud-in-cell deposit (serial: the sums are the same for any thread count).
  for (std::size_t a = 0; a < frame.size(); ++a) {
    std::array<std::size_t, 3> i0{}, i1{};
    std::array<double, 3> f{};
    for (int d = 0; d < 3; ++d) {
      const double L = frame.box.length()[d];
      const double cells = static_cast<double>(g.periodic[d] ? g.n[d] : g.n[d] - 1);
      double u = (frame.positions[a][d] - frame.box.lo[d]) / L * cells;  // in nodes
      if (g.periodic[d]) u -= cells * std::floor(u / cells);
      else u = std::clamp(u, 0.0, cells);
      const auto k = std::min(static_cast<std::size_t>(u), g.n[d] - 1);
      f[d] = u - static_cast<double>(k);
      i0[d] = k;
      i1[d] = g.periodic[d] ? (k + 1) % g.n[d] : std::min(k + 1, g.n[d] - 1);
    }
    const double s = selected[a] ? 1.0 : 0.0;
    for (int c = 0; c < 8; ++c) {
      double w = 1.0;
      std::array<std::size_t, 3> idx{};
      for (int d = 0; d < 3; ++d) {
        const bool up = (c >> d) & 1;
        w *= up ? f[d] : 1.0 - f[d];
        idx[d] = up ? i1[d] : i0[d];
      }
      const std::size_t p = idx[0] + g.n[0] * (idx[1] + g.n[1] * idx[2]);
      weight[p] += w;
      chosen[p] += w * s;
    }
    g.selected += selected[a] ? 1 : 0;
  }
  if (o.smoothing > 0.0) {
    for (int d = 0; d < 3; ++d) {
      const auto taps = gaussian_taps(o.smoothing / o.spacing);
      smooth_axis(weight, g, d, taps);
      smooth_axis(chosen, g, d, taps);
    }
  }
  g.fraction.resize(weight.size());
  g.density.resize(weight.size());
  const double cell_volume = o.spacing * o.spacing * o.spacing;
  for (std::size_t p = 0; p < weight.size(); ++p) {
    const bool empty = !(weight[p] > 1e-12);
    g.empty_nodes += empty ? 1 : 0;
    g.fraction[p] = empty ? 0.0 : std::clamp(chosen[p] / weight[p], 0.0, 1.0);
    g.density[p] = weight[p] / cell_volume;
  }
  return g;
}

}  // namespace shockfield::analysis::atoms

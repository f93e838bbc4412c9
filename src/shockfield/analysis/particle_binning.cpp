#include "shockfield/analysis/particle_binning.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "shockfield/analysis/point_frame_reader.hpp"
#include "shockfield/core/error.hpp"

namespace shockfield::analysis {

GridField bin_particles(std::span<const Vec3> positions, std::span<const double> quantity,
                        const GridField& grid, BinReduction reduction) {
  if (positions.size() != quantity.size())
    throw InputError(fmt::format("particle binning: {} positions but {} values", positions.size(),
                                 quantity.size()));
  GridField out = GridField::filled(grid.n[0], grid.n[1], grid.n[2], 0.0);
  out.spacing = grid.spacing;
  out.origin = grid.origin;
  validate(out, "binning grid");
  std::vector<std::size_t> count(out.size(), 0);
  const int dim = out.dimension();
  for (std::size_t p = 0; p < positions.size(); ++p) {
    if (!positions[p].allFinite() || !std::isfinite(quantity[p]))
      throw InputError(fmt::format("particle binning: particle {} has a non-finite position or "
                                   "value", p));
    std::array<std::size_t, 3> c{0, 0, 0};
    bool inside = true;
    for (int a = 0; a < dim; ++a) {
      const double u = std::floor((positions[p][a] - out.origin[a]) / out.spacing[a]);
      if (u < 0.0 || u >= double(out.n[a])) inside = false;
      else c[a] = static_cast<std::size_t>(u);
    }
    if (!inside) continue;
    const std::size_t i = out.index(c[0], c[1], c[2]);
    out.values[i] += quantity[p];
    ++count[i];
  }
  out.is_void.assign(out.size(), 0);
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (count[i] == 0) out.is_void[i] = 1;
    else if (reduction == BinReduction::mean) out.values[i] /= double(count[i]);
  }
  return out;
}

std::vector<GridField> bin_point_frames(const std::vector<std::string>& files, const std::string& array, double cell) {
  if (!(cell > 0.0) || !std::isfinite(cell))
    throw InputError(fmt::format("--bin-size {}: expected a positive cell side", cell));
  std::vector<PointFrame> frames;
  std::array<double, 3> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity()), hi.fill(-std::numeric_limits<double>::infinity());
  for (const auto& file : files) {
    frames.push_back(read_point_frame(file, array));
    const auto& xyz = frames.back().xyz;
    if (xyz.empty()) throw InputError(fmt::format("{}: no particles to bin", file));
    for (std::size_t i = 0; i < xyz.size(); ++i)
      lo[i % 3] = std::min(lo[i % 3], xyz[i]), hi[i % 3] = std::max(hi[i % 3], xyz[i]);
  }
  // Counted as doubles first: a tiny cell must be refused, not overflow a size_t.
  std::array<double, 3> along{};
  for (std::size_t a = 0; a < 3; ++a) along[a] = std::floor((hi[a] - lo[a]) / cell) + 1.0;
  if (along[0] * along[1] * along[2] > 1e8)
    throw InputError(fmt::format("--bin-size {}: the particles span {} x {} x {} cells; expected at most 1e8", cell,
                                 along[0], along[1], along[2]));
  GridField grid;
  for (std::size_t a = 0; a < 3; ++a) grid.n[a] = static_cast<std::size_t>(along[a]);
  grid.spacing = {cell, cell, cell};
  grid.origin = lo;
  std::vector<GridField> fields;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const PointFrame& frame = frames[f];
    std::vector<Vec3> positions(frame.xyz.size() / 3);
    for (std::size_t i = 0; i < positions.size(); ++i)
      positions[i] = {frame.xyz[3 * i], frame.xyz[3 * i + 1], frame.xyz[3 * i + 2]};
    try {
      fields.push_back(bin_particles(positions, frame.values, grid));
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", files[f], e.what()));
    }
    fields.back().units = frame.values_units;
    fields.back().length_units = frame.position_units;
  }
  return fields;
}

}  // namespace shockfield::analysis

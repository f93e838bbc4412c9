#include "shockfield/analysis/grid_field.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"

namespace shockfield::analysis {

GridField GridField::filled(std::size_t nx, std::size_t ny, std::size_t nz, double value) {
  GridField field;
  field.n = {nx, ny, nz};
  field.values.assign(nx * ny * nz, value);
  return field;
}

std::size_t GridFieldView::void_count() const {
  return static_cast<std::size_t>(std::count_if(is_void.begin(), is_void.end(),
                                                [](std::uint8_t v) { return v != 0; }));
}

void validate(const GridFieldView& field, const std::string& what) {
  if (field.size() == 0)
    throw InputError(fmt::format("{}: empty field ({} x {} x {} cells); expected at least one cell",
                                 what, field.n[0], field.n[1], field.n[2]));
  if (field.values.size() != field.size())
    throw InputError(fmt::format("{}: {} values for a grid of {} x {} x {} = {} cells", what,
                                 field.values.size(), field.n[0], field.n[1], field.n[2],
                                 field.size()));
  if (!field.is_void.empty() && field.is_void.size() != field.size())
    throw InputError(fmt::format("{}: void mask has {} flags for {} cells", what,
                                 field.is_void.size(), field.size()));
  for (int a = 0; a < 3; ++a)
    if (!(field.spacing[a] > 0.0) || !std::isfinite(field.spacing[a]))
      throw InputError(fmt::format("{}: grid spacing along {} is {}; expected a positive number",
                                   what, "xyz"[a], field.spacing[a]));
  for (std::size_t i = 0; i < field.size(); ++i) {
    if (!field.void_at(i) && !std::isfinite(field.values[i])) {
      const std::size_t x = i % field.n[0], y = (i / field.n[0]) % field.n[1],
                        z = i / (field.n[0] * field.n[1]);
      throw InputError(fmt::format(
          "{}: value {} at cell (x={}, y={}, z={}); expected a finite number (mark cells without "
          "material as void instead)",
          what, field.values[i], x, y, z));
    }
  }
}

void require_same_grid(const GridGeometry& a, const GridGeometry& b, const std::string& what_a,
                       const std::string& what_b) {
  if (a.n != b.n)
    throw InputError(fmt::format("mismatched grids: {} has {} x {} x {} cells, {} has {} x {} x {}",
                                 what_a, a.n[0], a.n[1], a.n[2], what_b, b.n[0], b.n[1], b.n[2]));
  if (a.spacing != b.spacing)
    throw InputError(fmt::format("mismatched grids: {} has spacing ({}, {}, {}), {} has ({}, {}, {})",
                                 what_a, a.spacing[0], a.spacing[1], a.spacing[2], what_b,
                                 b.spacing[0], b.spacing[1], b.spacing[2]));
}

}  // namespace shockfield::analysis

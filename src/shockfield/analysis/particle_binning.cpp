#include "shockfield/analysis/particle_binning.hpp"

#include <fmt/format.h>

#include <cmath>

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

}  // namespace shockfield::analysis

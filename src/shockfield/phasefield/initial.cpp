#include "shockfield/phasefield/initial.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/analysis/field_reader.hpp"
#include "shockfield/core/error.hpp"
#include "shockfield/core/rng.hpp"

namespace shockfield::phasefield {

std::vector<Domain> random_domains(const Grid& grid, const RandomNuclei& nuclei) {
  std::vector<Domain> out;
  for (std::int64_t m = 0; m < nuclei.count; ++m) {
    Domain d;
    d.size = {nuclei.radius, nuclei.radius, nuclei.radius};
    for (int axis = 0; axis < grid.dim; ++axis)
      d.center[axis] = rng::uniform(nuclei.seed, static_cast<std::uint64_t>(m), static_cast<std::uint64_t>(axis)) *
                       grid.length(axis);
    out.push_back(d);
  }
  return out;
}

double signed_distance(const Grid& grid, const Domain& domain, const std::array<double, 3>& x) {
  std::array<double, 3> r{0, 0, 0};
  for (int d = 0; d < grid.dim; ++d) {
    const double L = grid.length(d);
    r[d] = x[d] - domain.center[d];
    if (grid.periodic(d)) r[d] -= L * std::round(r[d] / L);  // minimum image
  }
  switch (domain.kind) {
    case Domain::Kind::slab: {
      const auto& n = domain.normal;
      const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      return std::abs((r[0] * n[0] + r[1] * n[1] + r[2] * n[2]) / norm) - domain.size[0];
    }
    case Domain::Kind::ellipsoid: {
      // ρ = |A⁻¹ r| (1 on the surface); the distance along the ray, |r|(1 − 1/ρ), is exact on the axes.
      double rho2 = 0.0, r2 = 0.0;
      for (int d = 0; d < grid.dim; ++d) {
        rho2 += r[d] * r[d] / (domain.size[d] * domain.size[d]);
        r2 += r[d] * r[d];
      }
      const double rho = std::sqrt(rho2);
      return rho > 0.0 ? std::sqrt(r2) * (1.0 - 1.0 / rho) : -*std::min_element(domain.size.begin(), domain.size.begin() + grid.dim);
    }
    case Domain::Kind::sphere:
    default:
      return std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]) - domain.size[0];
  }
}

std::vector<double> read_field_file(const FieldFile& file, const Grid& grid) {
  const std::string name = file.path.string();
  const analysis::GridField f = analysis::read_grid_field(name, file.array);
  for (int d = 0; d < 3; ++d)
    if (f.n[d] != static_cast<std::size_t>(grid.n[d]))
      throw InputError(fmt::format("{}: {} x {} x {} nodes, the case's grid has {} x {} x {}", name, f.n[0], f.n[1], f.n[2],
                                   grid.n[0], grid.n[1], grid.n[2]));
  for (int d = 0; d < grid.dim; ++d)
    if (std::abs(f.spacing[d] - grid.dx) > 1e-9 * grid.dx)
      throw InputError(fmt::format("{}: spacing {} along axis {}, the case's grid.spacing is {}", name, f.spacing[d], d,
                                   grid.dx));
  for (std::size_t p = 0; p < f.values.size(); ++p)
    if (f.void_at(p) || !std::isfinite(f.values[p]))
      throw InputError(fmt::format("{}: node {} (x fastest) has no finite value", name, p));
  return f.values;
}

std::vector<double> pressure_scale(const PressureDependence& pressure, const Grid& grid) {
  std::vector<double> scale = read_field_file(pressure.file, grid);
  for (std::size_t p = 0; p < scale.size(); ++p) {
    const double value = 1.0 + pressure.slope * (scale[p] - pressure.reference);
    if (!(value > 0.0))
      throw InputError(fmt::format("{}: at node {} (x fastest) the pressure {} gives D(p)/D = 1 + slope (p - reference) "
                                   "= {}; it must be positive",
                                   pressure.file.path.string(), p, scale[p], value));
    scale[p] = value;
  }
  return scale;
}

std::vector<double> initial_field(const Grid& grid, const Model& model, const std::vector<Domain>& domains,
                                  const FieldFile& file) {
  std::vector<double> xi = file.path.empty() ? std::vector<double>(grid.size(), 0.0) : read_field_file(file, grid);
#pragma omp parallel for collapse(2) schedule(static)
  for (int k = 0; k < grid.n[2]; ++k)
    for (int j = 0; j < grid.n[1]; ++j)
      for (int i = 0; i < grid.n[0]; ++i) {
        const std::array<double, 3> x{i * grid.dx, j * grid.dx, k * grid.dx};
        double& v = xi[grid.index(i, j, k)];
        for (const Domain& d : domains) v = std::max(v, model.profile(signed_distance(grid, d, x)));
      }
  return xi;
}

}  // namespace shockfield::phasefield

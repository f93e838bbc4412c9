#include "shockfield/pd/regions.hpp"

#include <fmt/format.h>

#include <utility>

namespace shockfield::pd {
namespace {

// Whether a region selects some point of the lattice (positions as lattice_cloud makes them).
bool selects_a_lattice_point(const geometry::Region& region, const std::array<int, 3>& counts, double spacing) {
  for (int k = 0; k < counts[2]; ++k)
    for (int j = 0; j < counts[1]; ++j)
      for (int i = 0; i < counts[0]; ++i)
        if (region.match(Vec3::Zero() + spacing * Vec3(i, j, k))) return true;
  return false;
}

}  // namespace

LoadRegion read_load_region(const Config& t, int dim, const std::array<int, 3>& counts, double spacing) {
  LoadRegion r{geometry::region_from_config(t), Vec3::Zero(), t.has("prescribed_velocity")};
  if (t.has("velocity") == r.prescribed)
    t.fail(r.prescribed ? "velocity" : "prescribed_velocity",
           "expected exactly one of velocity (initial) or prescribed_velocity (held for all time)");
  const auto v = t.get_doubles(r.prescribed ? "prescribed_velocity" : "velocity", static_cast<std::size_t>(dim));
  for (int d = 0; d < dim; ++d) r.velocity[d] = v[static_cast<std::size_t>(d)];
  if (!selects_a_lattice_point(r.shape, counts, spacing))
    t.fail("shape", fmt::format("the region selects no point of the body (points from (0, 0, 0) to ({}, {}, {}) m)",
                                (counts[0] - 1) * spacing, (counts[1] - 1) * spacing, (counts[2] - 1) * spacing));
  return r;
}

std::vector<std::size_t> points_in(const geometry::Region& region, const PointCloud& cloud) {
  std::vector<std::size_t> points;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (region.match(cloud.x[i])) points.push_back(i);
  return points;
}

void apply_regions(Simulation& sim, const std::vector<LoadRegion>& regions, bool initial) {
  std::vector<unsigned char> held(sim.cloud().size(), 0);
  std::vector<Vec3> held_velocity(sim.cloud().size(), Vec3::Zero());
  for (const bool prescribed : {false, true})
    for (const LoadRegion& r : regions) {
      if (r.prescribed != prescribed) continue;
      for (std::size_t i : points_in(r.shape, sim.cloud())) {
        if (initial) sim.velocities()[i] = r.velocity;
        if (prescribed) held[i] = 1, held_velocity[i] = r.velocity;
      }
    }
  std::vector<std::pair<std::size_t, Vec3>> hold;
  for (std::size_t i = 0; i < held.size(); ++i)
    if (held[i]) hold.emplace_back(i, held_velocity[i]);
  if (hold.empty()) return;
  sim.add_hook(Simulation::Stage::after_force, [hold = std::move(hold)](Simulation& s) {
    for (const auto& [i, v] : hold) {
      s.force_density()[i] = Vec3::Zero();
      s.velocities()[i] = v;
    }
  });
}

}  // namespace shockfield::pd

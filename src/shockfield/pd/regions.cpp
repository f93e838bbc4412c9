#include "shockfield/pd/regions.hpp"

#include <fmt/format.h>

#include <optional>
#include <utility>

namespace shockfield::pd {
namespace {

// The first lattice point (positions as lattice_cloud makes them) that `selects` accepts, if any.
template <class Selects>
std::optional<Vec3> first_lattice_point(const std::array<int, 3>& counts, double spacing, Selects selects) {
  for (int k = 0; k < counts[2]; ++k)
    for (int j = 0; j < counts[1]; ++j)
      for (int i = 0; i < counts[0]; ++i)
        if (const Vec3 x = Vec3::Zero() + spacing * Vec3(i, j, k); selects(x)) return x;
  return std::nullopt;
}

}  // namespace

LoadRegion read_load_region(const Config& t, int dim, const std::array<int, 3>& counts, double spacing) {
  LoadRegion r{geometry::region_from_config(t), Vec3::Zero(), t.has("prescribed_velocity"), true,
               t.get_bool_or("separate", false)};
  r.sets_velocity = t.has("velocity") || r.prescribed;
  if ((t.has("velocity") && r.prescribed) || (!r.sets_velocity && !r.separate))
    t.fail(r.prescribed ? "velocity" : "prescribed_velocity",
           "expected exactly one of velocity (initial) or prescribed_velocity (held for all time)");
  if (r.sets_velocity) {
    const auto v = t.get_doubles(r.prescribed ? "prescribed_velocity" : "velocity", static_cast<std::size_t>(dim));
    for (int d = 0; d < dim; ++d) r.velocity[d] = v[static_cast<std::size_t>(d)];
  }
  if (!first_lattice_point(counts, spacing, [&](const Vec3& x) { return r.shape.match(x); }))
    t.fail("shape", fmt::format("the region selects no point of the body (points from (0, 0, 0) to ({}, {}, {}) m)",
                                (counts[0] - 1) * spacing, (counts[1] - 1) * spacing, (counts[2] - 1) * spacing));
  return r;
}

void check_bodies_apart(const std::vector<Config>& tables, const std::vector<LoadRegion>& regions,
                        const std::array<int, 3>& counts, double spacing) {
  for (std::size_t b = 0; b < regions.size(); ++b)
    for (std::size_t a = 0; a < b && regions[b].separate; ++a) {
      if (!regions[a].separate) continue;
      const auto both = [&](const Vec3& x) { return regions[a].shape.match(x) && regions[b].shape.match(x); };
      if (const auto x = first_lattice_point(counts, spacing, both))
        tables[b].fail("separate", fmt::format("this body overlaps the separate body of region[{}] (the point ({}, {}, "
                                               "{}) m is in both); expected bodies that do not overlap",
                                               a, (*x)[0], (*x)[1], (*x)[2]));
    }
}

std::vector<unsigned char> bonds_between_bodies(const PointCloud& cloud, const Family& family,
                                                const std::vector<LoadRegion>& regions) {
  std::vector<int> body(cloud.size(), -1);
  for (std::size_t k = 0; k < regions.size(); ++k)
    if (regions[k].separate)
      for (std::size_t i : points_in(regions[k].shape, cloud)) body[i] = static_cast<int>(k);
  std::vector<unsigned char> between(family.bonds(), 0);
  for (std::size_t i = 0; i < cloud.size(); ++i)
    for (int b = family.begin(i); b < family.end(i); ++b)
      between[static_cast<std::size_t>(b)] = body[i] != body[static_cast<std::size_t>(family.neighbor[b])];
  return between;
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
      if (r.prescribed != prescribed || !r.sets_velocity) continue;
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

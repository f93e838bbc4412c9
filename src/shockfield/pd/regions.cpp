#include "shockfield/pd/regions.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <memory>
#include <utility>

#include "shockfield/core/error.hpp"
#include "shockfield/pd/velocity_file.hpp"

namespace shockfield::pd {
namespace {

constexpr std::array<std::pair<const char*, Loading>, 5> kLoadingKeys{{
    {"velocity", Loading::velocity},
    {"velocity_formula", Loading::velocity_formula},
    {"velocity_file", Loading::velocity_file},
    {"prescribed_velocity", Loading::prescribed_velocity},
    {"prescribed_displacement", Loading::prescribed_displacement},
}};

// `dim` numbers of key as a vector (0 beyond dim).
Vec3 read_vector(const Config& t, const char* key, int dim) {
  const auto v = t.get_doubles(key, static_cast<std::size_t>(dim));
  Vec3 r = Vec3::Zero();
  for (int d = 0; d < dim; ++d) r[d] = v[static_cast<std::size_t>(d)];
  return r;
}

// `components` of a held region: distinct names among the body's axes x, y (, z); all when absent.
std::array<bool, 3> read_components(const Config& t, int dim) {
  std::array<bool, 3> held{true, true, true};
  if (!t.has("components")) return held;
  const std::vector<std::string> axes{"x", "y", "z"};
  const std::vector<std::string> names = t.get_strings("components");
  if (names.empty()) t.fail("components", "an empty list (expected the held components, e.g. [\"x\"])");
  held = {false, false, false};
  for (const std::string& name : names) {
    const auto at = std::find(axes.begin(), axes.begin() + dim, name);
    if (at == axes.begin() + dim)
      t.fail("components", fmt::format("'{}' (expected components of the {}D body: {})", name, dim,
                                       fmt::join(axes.begin(), axes.begin() + dim, ", ")));
    bool& h = held[static_cast<std::size_t>(at - axes.begin())];
    if (h) t.fail("components", fmt::format("'{}' given twice", name));
    h = true;
  }
  return held;
}

// `dim` formulas, each compiled and finite at every selected point.
std::vector<Expression> read_formula(const Config& t, int dim, const std::vector<Vec3>& selected) {
  const std::vector<std::string> texts = t.get_strings("velocity_formula");
  if (texts.size() != static_cast<std::size_t>(dim))
    t.fail("velocity_formula",
           fmt::format("{} formulas (expected {}, one per velocity component of the {}D body)",
                       texts.size(), dim, dim));
  std::vector<Expression> formula;
  for (std::size_t d = 0; d < texts.size(); ++d) {
    try {
      formula.push_back(Expression::parse(texts[d]));
    } catch (const ExpressionError& e) {
      t.fail("velocity_formula", fmt::format("component {} '{}': {}", d, texts[d], e.what()));
    }
    for (const Vec3& x : selected)
      if (const double v = formula.back()(x); !std::isfinite(v))
        t.fail("velocity_formula", fmt::format("component {} '{}' is not finite ({}) at the point "
                                               "({}, {}, {}) m (expected a finite "
                                               "velocity at every point of the region)",
                                               d, texts[d], v, x[0], x[1], x[2]));
  }
  return formula;
}

}  // namespace

std::string BodyPoints::extent() const {
  if (cloud) {
    const auto [lo, hi] = cloud->bounds();
    return fmt::format("{} points within ({}, {}, {}) to ({}, {}, {}) m", cloud->size(), lo[0], lo[1], lo[2], hi[0],
                       hi[1], hi[2]);
  }
  const Vec3 last = origin + spacing * Vec3(counts[0] - 1, counts[1] - 1, counts[2] - 1);
  return fmt::format("points from ({}, {}, {}) to ({}, {}, {}) m", origin[0], origin[1], origin[2], last[0], last[1],
                     last[2]);
}

LoadRegion read_load_region(const Config& t, int dim, const BodyPoints& body) {
  LoadRegion r(geometry::region_from_config(t), Loading::none);
  r.separate = t.get_bool_or("separate", false);
  std::vector<const char*> given;
  for (const auto& [key, loading] : kLoadingKeys)
    if (t.has(key)) given.push_back(key), r.loading = loading;
  if (given.size() > 1 || (given.empty() && !r.separate && !t.has("body_force")))
    t.fail(
        given.empty() ? "shape" : given[1],
        "expected exactly one of velocity, velocity_formula, velocity_file (initial velocities), "
        "prescribed_velocity or prescribed_displacement (held for all time)");
  if (t.has("body_force")) r.body_force = read_vector(t, "body_force", dim);
  if (!body.first([&](const Vec3& x) { return r.shape.match(x); }))
    t.fail("shape", fmt::format("the region selects no point of the body ({})", body.extent()));
  // The selected points themselves only where the velocities depend on them (a huge body is
  // checked without building it).
  std::vector<Vec3> selected;
  if (r.loading == Loading::velocity_formula || r.loading == Loading::velocity_file)
    body.first([&](const Vec3& x) {
      if (r.shape.match(x)) selected.push_back(x);
      return false;
    });
  if (r.loading == Loading::velocity || r.loading == Loading::prescribed_velocity)
    r.velocity = read_vector(t, given[0], dim);
  if (r.loading == Loading::prescribed_displacement) {
    r.displacement = read_vector(t, "prescribed_displacement", dim);
    r.ramp_time = t.get_double_or("ramp_time", 0.0, Range::non_negative());
  } else if (t.has("ramp_time")) {
    t.fail("ramp_time", "only a prescribed_displacement is ramped (expected no ramp_time here)");
  }
  if (r.held())
    r.held_components = read_components(t, dim);
  else if (t.has("components"))
    t.fail("components", "only a prescribed_velocity or prescribed_displacement holds components (expected no "
                         "components here)");
  if (r.loading == Loading::velocity_formula) r.formula = read_formula(t, dim, selected);
  if (r.loading == Loading::velocity_file) {
    const std::filesystem::path file = t.get_input_file("velocity_file");
    try {
      r.point_velocity = read_point_velocities(file, dim, selected, body.spacing);
    } catch (const InputError& e) {
      t.fail("velocity_file", e.what());
    }
  }
  return r;
}

void check_bodies_apart(const std::vector<Config>& tables, const std::vector<LoadRegion>& regions,
                        const BodyPoints& body) {
  for (std::size_t b = 0; b < regions.size(); ++b)
    for (std::size_t a = 0; a < b && regions[b].separate; ++a) {
      if (!regions[a].separate) continue;
      const auto both = [&](const Vec3& x) {
        return regions[a].shape.match(x) && regions[b].shape.match(x);
      };
      if (const auto x = body.first(both))
        tables[b].fail(
            "separate",
            fmt::format("this body overlaps the separate body of region[{}] (the point ({}, {}, "
                        "{}) m is in both); expected bodies that do not overlap",
                        a, (*x)[0], (*x)[1], (*x)[2]));
    }
}

std::vector<unsigned char> bonds_between_bodies(const PointCloud& cloud, const Family& family,
                                                const std::vector<LoadRegion>& regions, const std::vector<int>& part) {
  // Files' bodies are 0, 1, ...; separate region k is −2 − k (the rest of a single body, −1).
  std::vector<int> body = part.empty() ? std::vector<int>(cloud.size(), -1) : part;
  for (std::size_t k = 0; k < regions.size(); ++k)
    if (regions[k].separate)
      for (std::size_t i : points_in(regions[k].shape, cloud)) body[i] = -2 - static_cast<int>(k);
  std::vector<unsigned char> between(family.bonds(), 0);
  for (std::size_t i = 0; i < cloud.size(); ++i)
    for (int b = family.begin(i); b < family.end(i); ++b)
      between[static_cast<std::size_t>(b)] =
          body[i] != body[static_cast<std::size_t>(family.neighbor[b])];
  return between;
}

std::vector<std::size_t> points_in(const geometry::Region& region, const PointCloud& cloud) {
  std::vector<std::size_t> points;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (region.match(cloud.x[i])) points.push_back(i);
  return points;
}

namespace {
// Sets the held components of `value` to those of `to` (a free component keeps its value).
void hold(Vec3& value, const Vec3& to, const LoadRegion& r) {
  for (int d = 0; d < 3; ++d)
    if (r.held_components[static_cast<std::size_t>(d)]) value[d] = to[d];
}
}  // namespace

void apply_regions(Simulation& sim, const std::vector<LoadRegion>& given, bool initial) {
  // The hooks below keep pointers to the regions: they point into this copy, which the hooks own,
  // so a caller may pass a temporary list (a held region's hook read freed memory before).
  const auto kept = std::make_shared<const std::vector<LoadRegion>>(given);
  const std::vector<LoadRegion>& regions = *kept;
  const PointCloud& cloud = sim.cloud();
  std::vector<const LoadRegion*> holder(cloud.size(), nullptr);
  for (const LoadRegion& r : regions) {
    const std::vector<std::size_t> points = points_in(r.shape, cloud);
    if (r.held()) {
      for (std::size_t i : points) holder[i] = &r;
      continue;
    }
    if (!initial || r.loading == Loading::none) continue;
    for (std::size_t k = 0; k < points.size(); ++k) {
      Vec3& v = sim.velocities()[points[k]];
      if (r.loading == Loading::velocity) v = r.velocity;
      if (r.loading == Loading::velocity_file) v = r.point_velocity[k];
      if (r.loading == Loading::velocity_formula)
        for (std::size_t d = 0; d < r.formula.size(); ++d)
          v[static_cast<int>(d)] = r.formula[d](cloud.x[points[k]]);
    }
  }
  std::vector<Vec3> force_sum(cloud.size(), Vec3::Zero());
  for (const LoadRegion& r : regions)
    if (r.body_force != Vec3::Zero())
      for (std::size_t i : points_in(r.shape, cloud)) force_sum[i] += r.body_force;
  std::vector<std::pair<std::size_t, Vec3>> pushed;
  for (std::size_t i = 0; i < force_sum.size(); ++i)
    if (force_sum[i] != Vec3::Zero()) pushed.emplace_back(i, force_sum[i]);
  if (!pushed.empty())  // ρü = L + b (eq. 1), before held points drop their force
    sim.add_hook(Simulation::Stage::after_force, [pushed = std::move(pushed)](Simulation& s) {
      for (const auto& [i, b] : pushed) s.force_density()[i] += b;
    });
  std::vector<std::pair<std::size_t, const LoadRegion*>> held, displaced;
  for (std::size_t i = 0; i < holder.size(); ++i) {
    if (!holder[i]) continue;
    held.emplace_back(i, holder[i]);
    if (holder[i]->loading == Loading::prescribed_displacement)
      displaced.emplace_back(i, holder[i]);
    if (initial) hold(sim.velocities()[i], holder[i]->held_velocity(0.0), *holder[i]);
  }
  if (held.empty()) return;
  if (!displaced.empty())
    sim.add_hook(Simulation::Stage::before_force,
                 [kept, displaced = std::move(displaced)](Simulation& s) {
                   for (const auto& [i, r] : displaced)
                     hold(s.positions()[i], Vec3(s.cloud().x[i] + r->displacement_at(s.time())), *r);
                 });
  sim.add_hook(Simulation::Stage::after_force, [kept, held = std::move(held)](Simulation& s) {
    for (const auto& [i, r] : held) {
      hold(s.force_density()[i], Vec3::Zero(), *r);
      hold(s.velocities()[i], r->held_velocity(s.time()), *r);
    }
  });
}

std::string describe(const LoadRegion& r, std::size_t count) {
  const auto vector = [](const Vec3& v) { return fmt::format("({}, {}, {})", v[0], v[1], v[2]); };
  std::string what;
  switch (r.loading) {
    case Loading::none:
      what = r.separate || r.body_force == Vec3::Zero() ? "keeping its velocity" : "";
      break;
    case Loading::velocity:
      what = fmt::format("starting at {} m/s", vector(r.velocity));
      break;
    case Loading::prescribed_velocity:
      what = fmt::format("held at {} m/s", vector(r.velocity));
      break;
    case Loading::velocity_file:
      what = "starting at the velocities of velocity_file";
      break;
    case Loading::velocity_formula: {
      std::string texts;
      for (const Expression& e : r.formula) texts += (texts.empty() ? "" : ", ") + e.text();
      what = fmt::format("starting at the velocity ({}) m/s", texts);
      break;
    }
    case Loading::prescribed_displacement:
      what = r.ramp_time > 0.0 ? fmt::format("displaced by {} m ramped over {} s",
                                             vector(r.displacement), r.ramp_time)
                               : fmt::format("held displaced by {} m", vector(r.displacement));
      break;
  }
  if (r.held() && r.held_components != std::array<bool, 3>{true, true, true}) {
    std::string axes;
    for (int d = 0; d < 3; ++d)
      if (r.held_components[static_cast<std::size_t>(d)]) axes += "xyz"[d];
    what += fmt::format(" in {} only (the other components free)", axes);
  }
  if (r.body_force != Vec3::Zero())
    what += fmt::format("{}with the body force {} N/m³", what.empty() ? "" : ", ", vector(r.body_force));
  return fmt::format("{} points {}{}", count, what, r.separate ? ", a separate body" : "");
}

}  // namespace shockfield::pd

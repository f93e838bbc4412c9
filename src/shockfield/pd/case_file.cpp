#include "shockfield/pd/case_file.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "shockfield/core/error.hpp"
#include "shockfield/core/size_limits.hpp"
#include "shockfield/materials/material_file.hpp"
#include "shockfield/pd/lattice_bonds.hpp"

namespace shockfield::pd {
namespace {

// The lattice's sizes, checked before it is built: at most kMaxParticles points, a finite extent
// and horizon (a spacing of 1e308 overflowed them to inf), and the bond list counted before it is
// built (its size grows as horizon_factor³).
void check_lattice(const Config& t, const BodySpec& b) {
  double points = 1;
  for (int d = 0; d < b.dim; ++d) points *= static_cast<double>(b.counts[static_cast<std::size_t>(d)]);
  if (points > kMaxParticles)
    t.fail("counts", fmt::format("{:.3g} points; expected at most {:.0e}", points, kMaxParticles));
  const int longest = *std::max_element(b.counts.begin(), b.counts.begin() + b.dim);
  if (!std::isfinite(b.spacing * longest * b.horizon_factor))
    t.fail("spacing", fmt::format("the body ({} points of {} m) or its horizon ({}·ΔX) is not finite",
                                  longest, b.spacing, b.horizon_factor));
  const double bonds = lattice_bonds(b.dim, b.counts, b.horizon_factor);
  if (!(bonds <= kMaxBonds))
    t.fail("horizon_factor", fmt::format("{}: the {:.3g} points would have {:.3g} bonds ({:.3g} per point; ~{} for the "
                                         "bonds alone); expected a horizon giving at most {:.0e} bonds (lower "
                                         "horizon_factor or the point counts)",
                                         b.horizon_factor, points, bonds, bonds / points,
                                         memory_text(pd_bytes(0.0, bonds)), kMaxBonds));
}

// The points of one file (pd::read_cloud: "x y z volume" lines) under the table's key.
PointCloud read_cloud_file(const Config& t, const char* key, const BodySpec& b) {
  const std::filesystem::path file = t.get_input_file(key);
  try {
    return read_cloud(file, b.dim, b.spacing);
  } catch (const InputError& e) {
    t.fail(key, e.what());
  }
}

// A body read from `points_file`, or several bodies from the `file` of each [[body.points]] table
// (their points in table order, each file a body of its own), with the lattice's size limits: at
// most kMaxParticles points, and bonds estimated before the families are built as N · (the
// horizon's length, area or volume) / (the mean point volume), the count of a point whose family
// is whole.
void read_points_files(const Config& t, BodySpec& b) {
  for (const char* key : {"counts", "origin"})
    if (t.has(key))
      t.fail(key, "a key of a lattice body; expected either counts (and origin) or points_file (a point cloud), "
                  "not both");
  const std::vector<Config> parts = t.tables("points");
  if (t.has("points_file") && !parts.empty())
    t.fail("points", "expected either points_file (one body) or [[body.points]] tables (a body per file), not both");
  if (!std::isfinite(b.spacing * b.horizon_factor))
    t.fail("spacing", fmt::format("the horizon {}·{} m is not finite", b.horizon_factor, b.spacing));
  if (parts.empty()) {
    b.cloud = read_cloud_file(t, "points_file", b);
  } else {
    b.cloud = PointCloud{b.dim, b.spacing, {}, {}};
    for (std::size_t k = 0; k < parts.size(); ++k) {
      const PointCloud part = read_cloud_file(parts[k], "file", b);
      b.cloud->x.insert(b.cloud->x.end(), part.x.begin(), part.x.end());
      b.cloud->volume.insert(b.cloud->volume.end(), part.volume.begin(), part.volume.end());
      b.part.insert(b.part.end(), part.size(), static_cast<int>(k));
      if (b.cloud->size() > kMaxParticles) break;  // refused below
    }
  }
  const std::string files = parts.empty() ? "points_file" : "points";
  const double points = static_cast<double>(b.cloud->size());
  if (points > kMaxParticles)
    t.fail(files, fmt::format("{:.3g} points; expected at most {:.0e}", points, kMaxParticles));
  double volume = 0.0;
  for (double v : b.cloud->volume) volume += v;
  const double reach = b.horizon(), ball = b.dim == 1 ? 2.0 * reach
                                          : b.dim == 2 ? std::numbers::pi * reach * reach
                                                       : 4.0 / 3.0 * std::numbers::pi * reach * reach * reach;
  const double bonds = points * ball / (volume / points);
  if (!(bonds <= kMaxBonds))
    t.fail("horizon_factor", fmt::format("{}: the {:.3g} points of {} would have ~{:.3g} bonds; expected a horizon "
                                         "giving at most {:.0e} bonds",
                                         b.horizon_factor, points, files, bonds, kMaxBonds));
}

BodySpec read_body(const Config& t) {
  BodySpec b;
  b.dim = static_cast<int>(t.get_int("dim", Range::closed(1, 3)));
  const bool from_file = t.has("points_file") || t.has("points");
  if (!from_file) {
    const auto counts = t.get_ints("counts", static_cast<std::size_t>(b.dim), Range::closed(1, 1e7));
    for (int d = 0; d < b.dim; ++d) b.counts[static_cast<std::size_t>(d)] = static_cast<int>(counts[static_cast<std::size_t>(d)]);
    if (t.has("origin")) {
      const auto origin = t.get_doubles("origin", static_cast<std::size_t>(b.dim));
      for (int d = 0; d < b.dim; ++d) b.origin[d] = origin[static_cast<std::size_t>(d)];
    }
  }
  b.spacing = t.get_double("spacing", Range::positive());
  b.horizon_factor = t.get_double_or("horizon_factor", 3.0, Range::positive());
  if (b.horizon_factor < 1.0)
    t.fail("horizon_factor", fmt::format("{}: the horizon δ = {}·ΔX is smaller than the spacing, so a point has no "
                                         "neighbour on the lattice (expected >= 1)",
                                         b.horizon_factor, b.horizon_factor));
  if (from_file)
    read_points_files(t, b);
  else
    check_lattice(t, b);
  b.influence = Influence::from_name(t.get_choice_or("influence", Influence::names(), "constant"));
  b.correction = volume_correction_from_name(t.get_choice_or("volume_correction", {"linear", "none"}, "linear"));
  return b;
}

// The families of a body from a file, built to check it before the run: every point has a
// neighbour within the horizon, and no two points coincide (closer than 1e-6 ΔX).
Family checked_cloud_family(const Config& t, const BodySpec& b) {
  const PointCloud& cloud = *b.cloud;
  const Family family = build_family(cloud, b.horizon(), b.correction);
  const auto at = [&](std::size_t i) { return fmt::format("({}, {}, {}) m", cloud.x[i][0], cloud.x[i][1], cloud.x[i][2]); };
  const char* files = b.part.empty() ? "points_file" : "points";  // points numbered through the files in order
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (family.begin(i) == family.end(i))
      t.fail("horizon_factor", fmt::format("point {} of {} at {} has no neighbour within the horizon δ = {}·ΔX "
                                           "= {} m: the horizon is smaller than the spacing of the points there "
                                           "(expected a larger horizon_factor or spacing, or no isolated point)",
                                           i, files, at(i), b.horizon_factor, b.horizon()));
    for (int k = family.begin(i); k < family.end(i); ++k)
      if (family.length[static_cast<std::size_t>(k)] < 1e-6 * b.spacing)
        t.fail(files, fmt::format("points {} and {} at {} overlap (expected distinct points, at least 1e-6 "
                                          "of the spacing apart)",
                                          i, family.neighbor[static_cast<std::size_t>(k)], at(i)));
  }
  return family;
}

// Keys that belong to some models only: given to another model they are refused by name.
struct ModelKey {
  const char* key;
  std::vector<std::string> models;
};
const std::vector<ModelKey>& model_keys() {
  static const std::vector<ModelKey> keys{
      {"young", {"j2"}},         {"poisson", {"j2"}},     {"yield_stress", {"j2"}},
      {"hardening", {"j2"}},     {"hugoniot_slope", {"j2", "crystal"}},
      {"micromodulus", {"pmb"}}, {"bulk", {"lps"}},       {"shear", {"lps"}},
      {"critical_stretch", {"pmb", "lps"}},               {"alpha", {"pmb", "lps"}},
      {"contact", {"pmb", "lps"}},                        {"plane", {"lps"}}};
  return keys;
}

// Density, critical-stretch damage (LAMMPS s00 and α) and short-range contact of a bond model.
template <class Law>
BondSpec<Law> read_bond(const Config& t, double density, Law law) {
  BondSpec<Law> s{law, density, {}};
  s.damage.s00 = t.get_double("critical_stretch", Range::positive());
  s.damage.alpha = t.get_double_or("alpha", 0.25, Range::non_negative());
  s.contact = t.get_bool_or("contact", true);
  return s;
}

// Young's modulus and Poisson's ratio from the case, else from a material file's isotropic K, G:
// E = 9KG/(3K + G), ν = (3K − 2G)/(2(3K + G)).
std::pair<double, double> young_poisson(const Config& t, const materials::MaterialFile* f) {
  const Range poisson{-1.0, 0.5, true, true};
  if (!f || t.has("young") || t.has("poisson")) return {t.get_double("young", Range::positive()), t.get_double("poisson", poisson)};
  const std::string needed_by = "[material] model = \"j2\"";
  const std::string alternative = fmt::format("young and poisson in [material] of {}", t.file());
  const auto k = f->get("elasticity.bulk"), g = f->get("elasticity.shear");
  if (!k) f->missing("elasticity.bulk", needed_by, alternative);
  if (!g) f->missing("elasticity.shear", needed_by, alternative);
  return {t.get_double_or("young", 9.0 * *k * *g / (3.0 * *k + *g), Range::positive()),
          t.get_double_or("poisson", (3.0 * *k - 2.0 * *g) / (2.0 * (3.0 * *k + *g)), poisson)};
}

std::variant<SmallStrainJ2, CrystalSpec, PmbSpec, LpsSpec> read_material(const Config& t, std::vector<std::string>& notes) {
  const std::string model = t.get_choice_or("model", {"j2", "crystal", "pmb", "lps"}, "j2");
  for (const ModelKey& k : model_keys())
    if (t.has(k.key) && std::find(k.models.begin(), k.models.end(), model) == k.models.end())
      t.fail(k.key, fmt::format("not a parameter of model = \"{}\" (only of model = \"{}\")", model,
                                fmt::join(k.models, "\" or \"")));
  const std::optional<materials::MaterialFile> file = materials::open_material_file(t);
  const materials::MaterialFile* f = file ? &*file : nullptr;
  if (f) notes = f->summary_lines();
  const std::string needed_by = fmt::format("[material] model = \"{}\"", model);
  const auto value = [&](std::string_view key, std::initializer_list<std::string_view> file_keys,
                         std::optional<double> fallback, Range range) {
    return materials::case_or_file(t, key, f, file_keys, fallback, range, needed_by);
  };
  if (model == "crystal") return read_crystal(t, f);
  const double density = value("density", {"elasticity.density", "eos.rho0"}, {}, Range::positive());
  if (model == "pmb") return read_bond(t, density, PmbModel{t.get_double("micromodulus", Range::positive())});
  if (model == "lps")
    return read_bond(t, density, LpsModel{value("bulk", {"elasticity.bulk"}, {}, Range::positive()),
                                          value("shear", {"elasticity.shear"}, {}, Range::positive()), 3,
                                          t.get_choice_or("plane", {"strain", "stress"}, "strain") == "stress"});
  const auto [young, poisson] = young_poisson(t, f);
  const double yield = value("yield_stress", {"strength.yield_stress"}, {}, Range::positive());
  const double hardening = value("hardening", {"strength.tangent_modulus"}, 0.0, Range::non_negative());
  const double slope = value("hugoniot_slope", {"eos.s"}, 0.0, Range::closed(0.0, 10.0));
  try {
    return SmallStrainJ2::from_young(density, young, poisson, yield, hardening, slope);
  } catch (const InputError& e) {
    t.fail("young", e.what());
  }
}

SolverSpec read_solver(const Config& t) {
  SolverSpec s;
  s.options.riemann = t.get_bool_or("riemann", true);
  s.options.hourglass = t.get_double_or("hourglass", 0.0, Range::non_negative());
  s.end_time = t.get_double("end_time", Range::positive());
  if (t.has("time_step")) s.time_step = t.get_double("time_step", Range::positive());
  s.safety = t.get_double_or("safety", 0.5, {0.0, 1.0, true, false});
  return s;
}

OutputSpec read_output(const std::optional<Config>& o, double end_time) {
  return read_output_intervals(o, end_time, {.profiles = true, .fields = false, .vtk = true, .dumps = true});
}

}  // namespace

PdCase read_pd_case(const Config& root) {
  PdCase c;
  c.body = read_body(root.table("body"));
  const std::optional<Family> cloud_family =
      c.body.cloud ? std::optional<Family>(checked_cloud_family(root.table("body"), c.body)) : std::nullopt;
  c.material = read_material(root.table("material"), c.material_notes);
  if (auto* lps = std::get_if<LpsSpec>(&c.material)) {  // the 1D/2D/3D LPS
    lps->law.dim = c.body.dim;
    if (lps->law.plane_stress && c.body.dim != 2)
      root.table("material").fail("plane", fmt::format("plane = \"stress\" is the 2D plate's constraint; this body has dim = {} "
                                                       "(1D is uniaxial strain, 3D has no missing direction)", c.body.dim));
  }
  c.solver = read_solver(root.table("solver"));
  const std::vector<Config> regions = root.tables("region");
  const bool bond_model = std::holds_alternative<PmbSpec>(c.material) || std::holds_alternative<LpsSpec>(c.material);
  const BodyPoints points = c.body.points();
  for (const Config& t : regions) {
    c.regions.push_back(read_load_region(t, c.body.dim, points));
    if (c.regions.back().separate && !bond_model)
      t.fail("separate", "a separate body touches the rest only through the short-range contact force, which "
                         "model = \"pmb\" and \"lps\" have (expected one of them, or no separate body)");
  }
  check_bodies_apart(regions, c.regions, points);
  if (!c.body.part.empty() && c.body.part.back() > 0 && !bond_model)
    root.table("body").fail("points", "bodies from several files touch only through the short-range contact force, "
                                      "which model = \"pmb\" and \"lps\" have (expected one of them, or one file)");
  if (const auto loading = root.optional_table("loading")) {
    loading->get_choice_or("type", {"impact"}, "impact");
    c.impact_speed = loading->get_double("speed", Range::positive());
  } else if (c.regions.empty()) {
    root.fail("loading", "missing required table [loading] (or [[region]] tables giving velocities)");
  }
  for (const Config& t : root.tables("crack")) {
    c.cracks.push_back(read_crack(t, c.body.dim));
    const bool cuts = cloud_family ? std::ranges::any_of(cut_bonds(*c.body.cloud, *cloud_family, {c.cracks.back()}),
                                                         [](unsigned char cut) { return cut != 0; })
                                   : cuts_a_lattice_bond(c.cracks.back(), c.body.dim, c.body.counts, c.body.spacing,
                                                         c.body.horizon(), c.body.origin);
    if (!cuts)
      t.fail(c.body.dim == 2 ? "from" : "vertices",
             fmt::format("the crack cuts no bond of the body ({}): it lies outside the body or on its surface",
                         points.extent()));
  }
  const auto output = root.optional_table("output");
  c.output = read_output(output, c.solver.end_time);
  if (output && c.solver.time_step) check_intervals_against_step(*output, c.output, *c.solver.time_step);
  return c;
}

}  // namespace shockfield::pd

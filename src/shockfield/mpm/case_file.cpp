#include "shockfield/mpm/case_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/error.hpp"
#include "shockfield/core/size_limits.hpp"
#include "shockfield/materials/library.hpp"
#include "shockfield/materials/material_file.hpp"

namespace shockfield::mpm {
namespace {

constexpr const char* kAxes = "xyz";

Wall read_wall(const Config& t, std::string_view key, const std::string& fallback) {
  const std::string w = t.get_choice_or(key, {"free", "stick", "slip"}, fallback);
  return w == "stick" ? Wall::Stick : w == "slip" ? Wall::Slip : Wall::Free;
}

Vec3 read_vec(const Config& t, std::string_view key, int dim, Range range = {}) {
  const auto v = t.get_doubles(key, static_cast<std::size_t>(dim), range);
  Vec3 out = Vec3::Zero();
  for (int a = 0; a < dim; ++a) out[a] = v[static_cast<std::size_t>(a)];
  return out;
}

// A library material or a material file (materials/material_file.hpp), with per-key overrides
// (Xu et al. 2015, §4.1 parameters by default).
materials::SolidMaterial read_material(const Config& t, std::vector<std::string>& notes) {
  materials::SolidMaterial m;
  const std::optional<materials::MaterialFile> file = materials::open_material_file(t);
  if (file && t.has("library")) t.fail("library", "give either library = \"...\" or file = \"...\", not both");
  if (!file) m = materials::make_material(t.get_choice("library", materials::material_names()));
  m.name = t.get_string("name");
  const materials::MaterialFile* f = file ? &*file : nullptr;
  const std::string needed_by = fmt::format("the MPM material '{}'", m.name);
  // From the case, else the material file, else the library's value (fallback nullopt: required).
  auto over = [&](std::string_view key, double& field, Range range, std::initializer_list<std::string_view> file_keys,
                  bool required) {
    field = materials::case_or_file(t, key, f, file_keys, required && f ? std::nullopt : std::optional(field), range,
                                    needed_by);
  };
  over("rho0", m.eos.rho0, Range::positive(), {"eos.rho0"}, true);
  over("c0", m.eos.c0, Range::positive(), {"eos.c0"}, true);
  over("lambda", m.eos.lambda, Range::closed(0.0, 10.0), {"eos.s"}, true);
  over("gamma0", m.eos.gamma0, Range::closed(0.0, 10.0), {"eos.gamma0"}, true);
  if (f && f->get("eos.s2").value_or(0.0) != 0.0)
    t.fail("file", fmt::format("{}: eos.s2 = {} s/m: the MPM's Mie-Gruneisen EOS is linear in Up (s2 = 0); write the "
                               "material with a linear fit (shockfield bridge hugoniot-to-eos --quadratic no)",
                               f->path().string(), *f->get("eos.s2")));
  if (t.has("young") || t.has("poisson")) {
    const double young = t.get_double("young", Range::positive());
    const double nu = t.get_double("poisson", {-1.0, 0.5, true, true});
    m.strength.shear_modulus = young / (2.0 * (1.0 + nu));
  } else if (f) {
    m.strength.shear_modulus = f->get("elasticity.shear").value_or(0.0);
    if (!f->get("elasticity.shear"))
      f->missing("elasticity.shear", needed_by, fmt::format("young and poisson in {} of {}", t.path(), t.file()));
  }
  over("yield_stress", m.strength.yield_stress0, Range::non_negative(), {"strength.yield_stress"}, true);
  over("tangent_modulus", m.strength.tangent_modulus, Range::non_negative(), {"strength.tangent_modulus"}, false);
  over("isotropic_fraction", m.strength.isotropic_fraction, Range::closed(0.0, 1.0), {}, false);
  over("heat_capacity", m.thermal.heat_capacity, Range::positive(), {"thermal.heat_capacity"}, true);
  over("conductivity", m.thermal.conductivity, Range::non_negative(), {"thermal.conductivity"}, false);
  over("initial_temperature", m.thermal.initial_temperature, Range::positive(), {"thermal.initial_temperature"}, false);
  over("viscosity_quadratic", m.viscosity.quadratic, Range::non_negative(), {}, false);
  over("viscosity_linear", m.viscosity.linear, Range::non_negative(), {}, false);
  over("spall_strength", m.spall.strength, Range::non_negative(), {"spall.strength"}, false);
  over("spall_tuler_butcher_exponent", m.spall.tuler_butcher_exponent, Range::non_negative(), {}, false);
  over("spall_tuler_butcher_integral", m.spall.tuler_butcher_integral, Range::non_negative(), {}, false);
  if (f)
    for (const std::string& line : f->summary_lines()) notes.push_back(fmt::format("'{}' from {}", m.name, line));
  try {
    m.validate();
  } catch (const InputError& e) {
    t.fail(f ? "file" : "library", e.what());
  }
  return m;
}

GridSpec read_grid(const Config& g) {
  GridSpec s;
  s.dim = static_cast<int>(g.get_int("dim", Range::closed(2, 3)));
  const double h = g.get_double("cell_size", Range::positive());
  s.cell_size = Vec3::Constant(h);
  s.origin = read_vec(g, "lo", s.dim);
  const Vec3 hi = read_vec(g, "hi", s.dim);
  double nodes = 1;
  for (int a = 0; a < s.dim; ++a) {
    const double cells = (hi[a] - s.origin[a]) / h;
    nodes *= std::abs(cells) + 1;
    if (!(nodes <= kMaxGridPoints))  // before the rounding to an integer (of 1e300 cells)
      g.fail("hi", fmt::format("(hi - lo) / cell_size = {:.3g} cells along {}: the grid would have more than {:.0e} "
                               "nodes", cells, kAxes[a], kMaxGridPoints));
    const long n = std::lround(cells);
    if (n < 1 || std::abs(cells - static_cast<double>(n)) > 1e-6)
      g.fail("hi", fmt::format("hi - lo along {} is {} m: expected a whole number (>= 1) of cells of {} m", kAxes[a],
                               hi[a] - s.origin[a], h));
    s.cells[static_cast<std::size_t>(a)] = static_cast<int>(n);
  }
  const std::string lateral = g.get_choice_or("lateral", {"periodic", "free", "stick", "slip"}, "periodic");
  for (int a = 0; a + 1 < s.dim; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    s.periodic[ua] = lateral == "periodic";
    if (!s.periodic[ua]) s.walls[ua][0] = s.walls[ua][1] = read_wall(g, "lateral", lateral);
  }
  return s;
}

BodySpec read_body(const Config& b, const MpmCase& c, std::size_t index) {
  BodySpec s;
  const int dim = c.grid.dim;
  const std::string material = b.get_string("material");
  const auto it = std::find(c.material_names.begin(), c.material_names.end(), material);
  if (it == c.material_names.end())
    b.fail("material", fmt::format("no [[material]] named \"{}\" (body {})", material, index));
  s.body.material = static_cast<int>(it - c.material_names.begin());
  s.body.lo = read_vec(b, "lo", dim);
  s.body.hi = read_vec(b, "hi", dim);
  s.body.spacing = b.get_double_or("spacing", 0.5 * c.grid.cell_size[0], Range::positive());
  // Its particles (the lattice points of the body, twice for a symmetric impact) before any is
  // made: a spacing far below the body's size asked for more than any machine holds.
  double points = c.loading == LoadingKind::Symmetric ? 2.0 : 1.0;
  for (int a = 0; a < dim; ++a) points *= std::max(1.0, std::floor((s.body.hi[a] - s.body.lo[a]) / s.body.spacing));
  if (!(points <= kMaxParticles))
    b.fail("spacing", fmt::format("{} m: the body (lo to hi) would have {:.3g} particles, (hi - lo) / spacing "
                                  "along each axis multiplied (expected at most {:.0e})",
                                  s.body.spacing, points, kMaxParticles));
  if (c.loading == LoadingKind::None && b.has("velocity")) s.body.velocity = read_vec(b, "velocity", dim);
  if (b.has("porosity")) {
    VoidSpec v;
    v.porosity = b.get_double("porosity", {0.0, 1.0, true, true});
    v.mean_radius = b.get_double("void_radius", Range::positive());
    v.radius_spread = b.get_double_or("void_radius_spread", 0.0, {0.0, 1.0, false, true});
    v.seed = static_cast<std::uint64_t>(b.get_int_or("seed", 1, Range::non_negative()));
    v.cross_periodic_sides = b.get_bool_or("periodic_voids", true);
    s.pores = v;
  }
  if (b.has("cavity_radius") || b.has("cavity_depth")) {
    if (s.pores) b.fail("cavity_radius", "a body is either porous (porosity) or has one cavity, not both");
    s.cavity = CavitySpec{b.get_double("cavity_depth", Range::non_negative()), b.get_double("cavity_radius", Range::positive())};
  }
  return s;
}

DiagnosticsSpec read_diagnostics(const std::optional<Config>& d, double default_bottom, double h) {
  DiagnosticsSpec s;
  s.ejecta_threshold = 2.0 * h;
  if (!d) return s;
  s.windows.bottom = d->get_double_or("window_bottom", default_bottom);
  s.windows.heights = d->get_doubles_or("window_heights", {}, Range::positive());
  s.histogram_times = d->get_doubles_or("histogram_times", {}, Range::non_negative());
  if (!std::is_sorted(s.histogram_times.begin(), s.histogram_times.end()))
    d->fail("histogram_times", "expected times in increasing order");
  s.histogram_bins = static_cast<int>(d->get_int_or("histogram_bins", 50, Range::closed(2, 100000)));
  s.histogram_all = d->get_choice_or("histogram_region", {"bottom", "all"}, "bottom") == "all";
  s.ejecta = d->get_bool_or("ejecta", true);
  s.ejecta_threshold = d->get_double_or("ejecta_threshold", s.ejecta_threshold, Range::positive());
  if (!s.histogram_all && !s.histogram_times.empty() && s.windows.heights.empty())
    d->fail("histogram_region", "\"bottom\" needs window_heights (or use \"all\")");
  return s;
}

// [shock_front]: which body, the way its shock runs (by default up from a wall, down from a
// symmetric impact's plane), the slabs and the windows (shock_front.hpp).
std::optional<ShockFrontSpec> read_shock_front(const std::optional<Config>& t, const MpmCase& c) {
  if (!t) return std::nullopt;
  // Every key is read (and checked) even when the tool is off, so switching it off keeps the case valid.
  const bool enabled = t->get_bool_or("enabled", true);
  ShockFrontSpec spec;
  ShockFrontSettings& s = spec.settings;
  s.body = static_cast<int>(t->get_int_or("body", 0, Range::closed(0, static_cast<double>(c.bodies.size()) - 1)));
  const char* by_loading = c.loading == LoadingKind::Wall ? "up" : c.loading == LoadingKind::Symmetric ? "down" : nullptr;
  if (enabled && !by_loading && !t->has("direction"))
    t->fail("direction", "\"up\" or \"down\", the way the shock runs along the shock axis (no default without wall or "
                         "symmetric loading)");
  s.direction = t->get_choice_or("direction", {"up", "down"}, by_loading ? by_loading : "up") == "up" ? 1 : -1;
  s.bin_width = t->get_double_or("bin_width", c.grid.cell_size[c.axis()], Range::positive());
  s.margin_bins = static_cast<int>(t->get_int_or("margin_bins", 6, Range::closed(0, 1000)));
  s.window_fraction = t->get_double_or("window_fraction", 1.0, {0.0, 1.0, true, false});
  s.skip_fraction = t->get_double_or("skip_fraction", 0.3, {0.0, 1.0, false, true});
  const auto& material = c.materials[static_cast<std::size_t>(c.bodies[static_cast<std::size_t>(s.body)].body.material)];
  s.hel = hugoniot_elastic_limit(material);
  spec.material = c.material_names[static_cast<std::size_t>(c.bodies[static_cast<std::size_t>(s.body)].body.material)];
  if (!enabled) return std::nullopt;
  return spec;
}

OutputSpec read_output(const std::optional<Config>& o, double end_time) {
  OutputSpec s;
  static_cast<OutputIntervals&>(s) = read_output_intervals(o, end_time, {.profiles = false, .fields = true, .vtk = true});
  if (!o) return s;
  s.particles = o->get_bool_or("particles", true);
  return s;
}

}  // namespace

MpmCase read_mpm_case(const Config& root) {
  MpmCase c;
  const Config grid = root.table("grid");
  c.grid = read_grid(grid);
  const int axis = c.axis();
  const auto ua = static_cast<std::size_t>(axis);

  const Config solver = root.table("solver");
  const std::string shape = solver.get_choice_or("shape", {"linear", "gimp", "ugimp"}, "gimp");
  c.options.shape = shape == "gimp" ? ShapeKind::Gimp : shape == "ugimp" ? ShapeKind::UniformGimp : ShapeKind::Linear;
  c.options.scheme = solver.get_choice_or("scheme", {"musl", "usl"}, "musl") == "musl" ? UpdateScheme::MUSL : UpdateScheme::USL;
  c.options.flip = solver.get_double_or("flip", 1.0, Range::closed(0.0, 1.0));
  c.options.xpic_order = static_cast<int>(solver.get_int_or("xpic_order", 0, Range::closed(0, 16)));
  if (c.options.xpic_order > 0 && solver.has("flip"))
    solver.fail("xpic_order", "0 with `flip` (XPIC replaces the FLIP/PIC blend: give one of them)");
  c.options.smooth_dilatation = solver.get_bool_or("smooth_dilatation", false);
  c.end_time = solver.get_double("end_time", Range::positive());
  c.options.heat_conduction = solver.get_bool_or("heat_conduction", false);  // off: results as before
  if (solver.has("time_step")) {
    c.time_step = solver.get_double("time_step", Range::positive());
    c.options.courant = 1.0;  // the CFL limit a fixed step is checked against
  } else {
    c.options.courant = solver.get_double_or("courant", 0.3, {0.0, 1.0, true, false});
  }

  if (const auto contact = root.optional_table("contact")) {  // off by default: the paper's runs glue bodies
    c.options.contact.enabled = contact->get_bool_or("enabled", false);
    c.options.contact.friction = contact->get_double_or("friction", 0.0, Range::non_negative());
    if (!c.options.contact.enabled && contact->has("friction"))
      contact->fail("friction", "friction acts only between bodies in contact: set enabled = true (without it all "
                                "bodies share one grid velocity field and stay glued)");
  }

  const auto materials = root.tables("material");
  if (materials.empty()) root.fail("material", "expected at least one [[material]] (name, library or file, overrides)");
  for (const Config& m : materials) {
    c.materials.push_back(read_material(m, c.material_notes));
    if (std::count(c.material_names.begin(), c.material_names.end(), c.materials.back().name))
      m.fail("name", fmt::format("material name \"{}\" is used twice", c.materials.back().name));
    c.material_names.push_back(c.materials.back().name);
  }

  const auto loading = root.optional_table("loading");
  const std::string kind = loading ? loading->get_choice_or("type", {"wall", "symmetric", "tensile", "none"}, "none") : "none";
  c.loading = kind == "wall" ? LoadingKind::Wall : kind == "symmetric" ? LoadingKind::Symmetric
              : kind == "tensile" ? LoadingKind::Tensile : LoadingKind::None;
  if (c.loading != LoadingKind::None) c.speed = loading->get_double("speed", Range::positive());
  auto& shock_walls = c.grid.walls[ua];
  if (c.loading == LoadingKind::Wall || c.loading == LoadingKind::Tensile) {
    if (grid.has("low"))
      grid.fail("low", fmt::format("the low face is the rigid wall of [loading] type \"{}\"; remove this key", kind));
    shock_walls[0] = c.loading == LoadingKind::Tensile ? Wall::Stick : read_wall(*loading, "wall", "slip");
    if (shock_walls[0] == Wall::Free) loading->fail("wall", "expected \"stick\" or \"slip\" for a wall impact");
  } else {
    shock_walls[0] = read_wall(grid, "low", "free");
  }
  shock_walls[1] = read_wall(grid, "high", "free");

  const auto bodies = root.tables("body");
  if (bodies.empty()) root.fail("body", "expected at least one [[body]] (material, lo, hi)");
  double lowest = c.grid.origin[axis] + c.grid.length(axis);
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    c.bodies.push_back(read_body(bodies[k], c, k));
    BodySpec& b = c.bodies.back();
    lowest = std::min(lowest, b.body.lo[axis]);
    if (c.loading != LoadingKind::None) {
      b.body.velocity = Vec3::Zero();
      b.body.velocity[axis] = c.loading == LoadingKind::Wall ? -c.speed : c.speed;
    }
  }

  c.diagnostics = read_diagnostics(root.optional_table("diagnostics"), lowest, c.grid.cell_size[0]);
  for (double t : c.diagnostics.histogram_times)
    if (t > c.end_time) root.table("diagnostics").fail("histogram_times", fmt::format("{} s is after end_time {} s", t, c.end_time));
  c.output = read_output(root.optional_table("output"), c.end_time);
  c.shock_front = read_shock_front(root.optional_table("shock_front"), c);
  try {
    c.options.validate();
  } catch (const InputError& e) {
    solver.fail("courant", e.what());
  }
  return c;
}

}  // namespace shockfield::mpm

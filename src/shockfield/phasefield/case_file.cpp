#include "shockfield/phasefield/case_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "shockfield/core/size_limits.hpp"
#include "shockfield/materials/material_file.hpp"

namespace shockfield::phasefield {

Grid read_phasefield_grid(const Config& t) {
  Grid g;
  g.dim = static_cast<int>(t.get_int("dimensions", Range::closed(1, 3)));
  const auto cells = t.get_ints("nodes", static_cast<std::size_t>(g.dim), Range::closed(3, 1 << 14));
  double nodes = 1;
  for (int d = 0; d < g.dim; ++d) g.n[d] = static_cast<int>(cells[d]), nodes *= static_cast<double>(cells[d]);
  if (nodes > kMaxGridPoints)
    t.fail("nodes", fmt::format("{:.3g} grid nodes; expected at most {:.0e}", nodes, kMaxGridPoints));
  g.dx = t.get_double("spacing", Range::positive());
  // [grid.boundary]: x, y, z = "periodic" (default), "neumann" or "dirichlet" with <axis>_lo, _hi.
  if (const auto b = t.optional_table("boundary")) {
    for (int d = 0; d < g.dim; ++d) {
      const std::string axis(1, "xyz"[d]);
      const std::string kind = b->get_choice_or(axis, {"periodic", "neumann", "dirichlet"}, "periodic");
      g.boundary[d] = kind == "neumann" ? Boundary::neumann : kind == "dirichlet" ? Boundary::dirichlet : Boundary::periodic;
      if (g.boundary[d] == Boundary::dirichlet)
        g.fixed[d] = {b->get_double(axis + "_lo", Range::closed(-10.0, 10.0)),
                      b->get_double(axis + "_hi", Range::closed(-10.0, 10.0))};
    }
  }
  return g;
}

namespace {

std::array<double, 3> point(const Config& t, const char* key, const Grid& g, Range range = {}) {
  const auto v = t.get_doubles(key, static_cast<std::size_t>(g.dim), range);
  std::array<double, 3> p{0, 0, 0};
  for (int d = 0; d < g.dim; ++d) p[d] = v[d];
  return p;
}

}  // namespace

std::vector<Domain> read_phasefield_domains(const Config& t, const Grid& g) {
  std::vector<Domain> out;
  for (const Config& s : t.tables("sphere")) {
    const double R = s.get_double("radius", Range::positive());
    out.push_back({Domain::Kind::sphere, point(s, "center", g), {R, R, R}});
  }
  for (const Config& s : t.tables("ellipsoid"))
    out.push_back({Domain::Kind::ellipsoid, point(s, "center", g), point(s, "semi_axes", g, Range::positive())});
  for (const Config& s : t.tables("slab")) {
    Domain d{Domain::Kind::slab, point(s, "center", g), {s.get_double("half_width", Range::positive()), 0, 0}};
    d.normal = point(s, "normal", g);
    if (d.normal[0] == 0 && d.normal[1] == 0 && d.normal[2] == 0) s.fail("normal", "a non-zero vector");
    out.push_back(d);
  }
  if (const auto r = t.optional_table("random")) {
    RandomNuclei n;
    n.count = r->get_int("count", Range::closed(1, 1e7));
    n.radius = r->get_double("radius", Range::positive());
    n.seed = static_cast<std::uint64_t>(r->get_int_or("seed", 1, Range::non_negative()));
    const auto nuclei = random_domains(g, n);
    out.insert(out.end(), nuclei.begin(), nuclei.end());
  }
  return out;
}

double reaction_step_limit(const Model& model) { return 1.0 / std::max(model.a, 1.0 - model.a); }

PhasefieldCase read_phasefield_case(const Config& root) {
  PhasefieldCase c;
  c.grid = read_phasefield_grid(root.table("grid"));
  const Config model = root.table("model");
  model.get_choice_or("kind", {"field", "sharp_front"}, "field");
  // [model] file: a material file with [phasefield] (bridge domain-growth): a from it, and
  // D = W²/(2ℓ²) in the case's length unit ℓ = length_unit (m) from its interface width W; its
  // relaxation time is the model's time unit. The case's own a and D win.
  const auto material = materials::open_material_file(model);
  const materials::MaterialFile* file = material ? &*material : nullptr;
  if (file && file->get_string("phasefield.kind") == "sharp_front")
    model.fail("file", fmt::format("{} holds a sharp-front law (bridge domain-growth --law paper: kind = \"sharp_front\"), "
                                   "not the field model's a and interface width; set [model] kind = \"sharp_front\"",
                                   file->path().string()));
  c.model.a = materials::case_or_file(model, "a", file, {"phasefield.a"}, std::nullopt, Range::closed(0.0, 1.0),
                                      "the phase-field model");
  if (file && !model.has("D")) {
    const double unit = model.get_double("length_unit", Range::positive());
    const auto width = file->get("phasefield.interface_width");
    if (!width) file->missing("phasefield.interface_width", "the phase-field model's D = W^2/2", model.key_path("D"));
    c.model.D = materials::file_default(model, "D", *file, "phasefield.interface_width", 0.5 * (*width / unit) * (*width / unit),
                                        Range::positive());
    if (const auto tau = file->get("phasefield.relaxation_time")) root.derive("time_unit_s", *tau);
  } else {
    c.model.D = model.get_double("D", Range::positive());
    if (file) model.get_double_or("length_unit", 1.0, Range::positive());
  }
  if (model.has("anisotropy")) {
    const auto w = model.get_doubles("anisotropy", static_cast<std::size_t>(c.grid.dim), Range::closed(1e-3, 1e3));
    for (int d = 0; d < c.grid.dim; ++d) c.model.anisotropy[d] = w[d];
  }
  const Config time = root.table("time");
  c.scheme = scheme_from_name(time.get_choice_or("scheme", {"explicit", "spectral"}, "spectral"));
  if (c.scheme == Scheme::spectral && !c.grid.all_periodic())
    time.fail("scheme", "\"explicit\": the spectral scheme needs periodic boundaries on every axis, and "
                        "[grid.boundary] sets a wall");
  double largest_scale = 1.0;
  if (const auto p = model.optional_table("pressure")) {
    c.pressure = {{p->get_input_file("file"), p->get_string_or("array", "")},
                  p->get_double("reference"),
                  p->get_double("slope")};
    if (c.scheme != Scheme::explicit_euler)
      time.fail("scheme", "\"explicit\": a pressure-dependent D ([model.pressure]) varies in space, which the "
                          "spectral scheme's constant implicit factor cannot hold");
    const std::vector<double> scale = pressure_scale(c.pressure, c.grid);  // validated now, again at the start
    largest_scale = *std::max_element(scale.begin(), scale.end());
  }
  const double limit = explicit_step_limit(c.grid, c.model) / largest_scale;
  c.dt = time.get_double("dt", Range::positive());
  // Forward Euler is unstable beyond dx²/(2 dim D); 0.9 of it keeps a margin for the reaction term.
  if (c.scheme == Scheme::explicit_euler && c.dt > 0.9 * limit)
    time.fail("dt", fmt::format("at most 0.9 dx^2/(2 sum D_d{}) = {:.6g} for scheme = \"explicit\" (the stability limit "
                                "is {:.6g}); use a smaller dt{}",
                                c.pressure.file.path.empty() ? "" : " max D(p)/D", 0.9 * limit, limit,
                                c.pressure.file.path.empty() ? " or scheme = \"spectral\"" : ""));
  // The reaction term is explicit in both schemes: about a well ξ* the update is
  // δξ ← (1 − dt f″(ξ*)) δξ, f″(0) = a, f″(1) = 1 − a, unstable (oscillating) beyond 2/f″. Half of
  // that keeps the wells monotone (1 − dt f″ ≥ 0): dt ≤ 1/max(a, 1 − a).
  if (c.dt > reaction_step_limit(c.model))
    time.fail("dt", fmt::format("at most 1/max(a, 1 - a) = {:.6g}: the reaction term f'(xi) is explicit, and a larger "
                                "step overshoots the wells (dt f''(well) > 1)",
                                reaction_step_limit(c.model)));
  c.end_time = time.get_double("end_time", Range::positive());
  c.steps = static_cast<long long>(std::ceil(c.end_time / c.dt - 1e-9));
  const auto initial = root.optional_table("initial");
  if (initial) {
    c.domains = read_phasefield_domains(*initial, c.grid);
    if (initial->has("file")) {
      c.field_file = {initial->get_input_file("file"), initial->get_string_or("array", "")};
      read_field_file(c.field_file, c.grid);  // validated now; read again when the run starts
    }
  }
  if (c.domains.empty() && c.field_file.path.empty())
    root.fail("initial", "a field file ([initial] file) or at least one [[initial.sphere]], [[initial.ellipsoid]], "
                         "[[initial.slab]] or [initial.random]");
  c.output = read_output_intervals(root.optional_table("output"), c.end_time, {.profiles = false, .fields = true, .vtk = true});
  return c;
}

}  // namespace shockfield::phasefield

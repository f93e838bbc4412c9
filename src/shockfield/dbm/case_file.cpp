#include "shockfield/dbm/case_file.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "shockfield/core/error.hpp"
#include "shockfield/core/size_limits.hpp"
#include "shockfield/dbm/reaction_case.hpp"

namespace shockfield::dbm {
namespace {

// Most steps a run may take (an end_time that needs more is refused, not cast past long long).
constexpr long long max_dbm_steps = 1'000'000'000;

const std::array<std::string, 4> kSides{"x_low", "x_high", "y_low", "y_high"};

// A velocity component, `name` (vx, vy), default 0. Its name before issue 15, `old_name` (u, v),
// is still read, with a warning: a velocity is v, a displacement u in every method
// (docs/conventions.md).
double read_velocity(const Config& t, const char* name, const char* old_name) {
  if (!t.has(old_name)) return t.get_double_or(name, 0.0);
  if (t.has(name)) t.fail(old_name, fmt::format("give {} only ({} is its deprecated name)", name, old_name));
  std::fprintf(stderr, "warning: %s: key '%s' is deprecated: name the velocity '%s' (docs/conventions.md)\n",
               t.file().c_str(), t.key_path(old_name).c_str(), name);
  return t.get_double(old_name);
}

// ρ, vx, vy and T or p (p = ρT) of an inline table such as { rho = 1.0, vx = 0.0, p = 1.0 }.
Macro read_state(const Config& t) {
  Macro m;
  m.rho = t.get_double("rho", Range::positive());
  m.ux = read_velocity(t, "vx", "u");
  m.uy = read_velocity(t, "vy", "v");
  if (t.has("T") == t.has("p")) t.fail("T", "give exactly one of T and p (p = rho*T)");
  m.T = t.has("T") ? t.get_double("T", Range::positive()) : t.get_double("p", Range::positive()) / m.rho;
  return m;
}

Lattice read_grid(const Config& t) {
  Lattice l;
  l.nx = static_cast<int>(t.get_int("nx", Range::closed(1, 1e6)));
  l.ny = static_cast<int>(t.get_int_or("ny", 1, Range::closed(1, 1e6)));
  if (static_cast<double>(l.nx) * l.ny > kMaxGridPoints)
    t.fail("ny", fmt::format("nx x ny = {} x {} cells; expected at most {:.0e}", l.nx, l.ny, kMaxGridPoints));
  l.dx = l.dy = t.get_double("dx", Range::positive());
  return l;
}

bool is_gls(const Config& model) { return model.get_choice_or("kind", {"bgk", "gls"}, "bgk") == "gls"; }

VelocityModel read_model(const Config& t, BgkSettings& bgk) {
  const bool gls = is_gls(t);
  bgk.gamma = t.get_double_or("gamma", gls ? 2.0 : 1.4, {1.0, 2.0, true, false});
  if (gls && bgk.gamma != 2.0)
    t.fail("gamma", "2 for kind = \"gls\": the GLS force moments assume b = 2 degrees of freedom (e = rho T)");
  bgk.tau = t.get_double("tau", Range::positive());
  const auto v = t.get_doubles_or("speeds", {1.0, 2.0, 3.0, 4.0}, Range::positive());
  if (v.size() != 4) t.fail("speeds", fmt::format("{} values given; D2V16 needs 4 group speeds", v.size()));
  VelocityModel model = d2v16({v[0], v[1], v[2], v[3]}, t.get_double_or("eta0", 2.0, Range::positive()));
  try {
    MomentInversion check(model);
  } catch (const InputError& e) {
    t.fail("speeds", e.what());
  }
  bgk.spectral_convection = t.get_choice_or("convection", {"nnd", "spectral"}, gls ? "spectral" : "nnd") == "spectral";
  if (gls && !bgk.spectral_convection)
    t.fail("convection", "\"spectral\" for kind = \"gls\": with NND the ideal and the non-ideal pressure see different "
                         "gradients and interfaces blow up (docs/theory/dbm.md)");
  // On by default for GLS: without it the modes the derivative filter removes stay in f, damped by
  // nothing, and fill with the force's aliased products until a cell's T crosses zero.
  bgk.filter_state = t.get_bool_or("filter_state", gls);
  if (bgk.filter_state && !bgk.spectral_convection)
    t.fail("filter_state", "true needs convection = \"spectral\" (the filter acts on FFT spectra)");
  return model;
}

InitialSpec read_initial(const Config& t, const Lattice& lattice) {
  InitialSpec s;
  s.riemann = t.get_choice_or("type", {"riemann", "uniform"}, "riemann") == "riemann";
  if (!s.riemann) {
    s.left = s.right = read_state(t.table("state"));
    return s;
  }
  s.left = read_state(t.table("left"));
  s.right = read_state(t.table("right"));
  const double length = lattice.nx * lattice.dx;
  s.split = t.get_double_or("split", 0.5 * length, {0.0, length, true, true});
  return s;
}

Boundaries read_boundaries(const std::optional<Config>& t, bool gls, double gamma) {
  Boundaries b;
  if (!gls) b.side[0].kind = b.side[1].kind = BoundaryKind::outflow;
  if (!t) return b;
  const std::vector<std::string>& kinds = boundary_kind_names();
  for (std::size_t s = 0; s < 4; ++s) {
    const std::string& side = kSides[s];
    BoundarySide& bs = b.side[s];
    bs.kind = boundary_kind(t->get_choice_or(side, kinds, s < 2 && !gls ? "outflow" : "periodic"));
    if (gls && bs.kind != BoundaryKind::periodic)
      t->fail(side, "\"periodic\" for kind = \"gls\": its spatial derivatives are taken by FFT");
    if (feeds_gas(bs.kind)) bs.state = read_state(t->table(side + "_state"));
    if (bs.kind == BoundaryKind::subsonic_inflow) {
      try {
        check_subsonic_inflow(bs.state, static_cast<int>(s / 2), s % 2 == 1, gamma);
      } catch (const InputError& e) {
        t->fail(side + "_state", e.what());
      }
    }
    if (bs.kind == BoundaryKind::wall) {
      const Config w = t->table(side + "_wall");
      bs.state = {1.0, read_velocity(w, "vx", "u"), read_velocity(w, "vy", "v"), w.get_double("T", Range::positive())};
    }
  }
  try {
    b.check();
  } catch (const InputError& e) {
    t->fail("x_low", e.what());
  }
  return b;
}

// dt from [run] (dt, or courant × dx / max|v|), then shortened so that whole steps land on
// end_time; refused when the collision (dt/τ) or the convection (Courant) would be unstable.
void read_run(const Config& t, const Config& model, DbmCase& c) {
  c.end_time = t.get_double("end_time", Range::positive());
  if (t.has("dt") && t.has("courant")) t.fail("courant", "give dt or courant, not both");
  const double vmax = c.model.max_speed(), dx = c.lattice.dx;
  const double wanted = t.has("dt") ? t.get_double("dt", Range::positive())
                                    : t.get_double_or("courant", 0.4, {0.0, 1.0, true, false}) * dx / vmax;
  if (t.has("dt") && vmax * wanted / dx > BgkSettings::max_courant)
    t.fail("dt", fmt::format("{} gives the Courant number max|v| dt/dx = {:.3g} > {} (max|v| = {}): the convection is "
                             "unstable; use dt <= {:.4g}",
                             wanted, vmax * wanted / dx, BgkSettings::max_courant, vmax,
                             BgkSettings::max_courant * dx / vmax));
  const double steps = std::ceil(c.end_time / wanted - 1e-9);
  if (!(steps <= static_cast<double>(max_dbm_steps)))
    t.fail("end_time", fmt::format("{} at dt = {:.4g} takes {:.4g} steps, more than the {} a run may take; use a "
                                   "shorter end_time or a larger dx",
                                   c.end_time, wanted, steps, max_dbm_steps));
  c.steps = static_cast<long long>(steps);
  c.bgk.dt = c.end_time / static_cast<double>(c.steps);
  // end_time / steps can exceed the wanted dt by round-off; one more step keeps a Courant number
  // at the limit (courant = 1.0, documented valid) valid instead of refused by the solver.
  while (vmax * c.bgk.dt / dx > BgkSettings::max_courant) c.bgk.dt = c.end_time / static_cast<double>(++c.steps);
  if (c.bgk.dt / c.bgk.tau > BgkSettings::max_dt_over_tau)
    model.fail("tau", fmt::format("{} is too small for dt = {:.4g}: dt/tau = {:.3g} > {} makes the explicit collision "
                                  "term unstable; use tau >= {:.4g} or a smaller dt",
                                  c.bgk.tau, c.bgk.dt, c.bgk.dt / c.bgk.tau, BgkSettings::max_dt_over_tau,
                                  c.bgk.dt / BgkSettings::max_dt_over_tau));
}

DbmOutputSpec read_output(const std::optional<Config>& t, const DbmCase& c) {
  DbmOutputSpec s;
  static_cast<OutputIntervals&>(s) = read_output_intervals(t, c.end_time, {.profiles = true, .fields = true, .vtk = true});
  s.profile_row = c.lattice.ny / 2;
  if (!t) return s;
  check_intervals_against_step(*t, s, c.bgk.dt);
  s.profile_row = static_cast<int>(t->get_int_or("profile_row", s.profile_row, Range::closed(0, c.lattice.ny - 1)));
  return s;
}

std::optional<RiemannStar> exact_star(const InitialSpec& s, double gamma) {
  if (!s.riemann || s.left.uy != 0.0 || s.right.uy != 0.0) return std::nullopt;
  const auto primitive = [](const Macro& m) { return Primitive{m.rho, m.ux, m.rho * m.T}; };
  try {
    return ExactRiemann(primitive(s.left), primitive(s.right), gamma).star();
  } catch (const InputError&) {
    return std::nullopt;  // vacuum-generating jump: no star region to report
  }
}

// ---- GLS liquid–vapour (kind = "gls", gls_case.hpp): model keys, the quench, the L(t) threshold
// ([output].threshold, default ρ0), the u_DG window ([output].growth_window) and the GLS time-step limit.
void read_gls_part(const Config& root, const Config& model, DbmCase& c) {
  GlsCaseSpec g;
  g.settings = read_gls_model(model, c.bgk.tau);
  const Config initial = root.table("initial");
  initial.get_choice_or("type", {"quench"}, "quench");
  g.quench = read_quench(initial, g.settings, c.lattice);
  expected_density_range(g, c.lattice);
  const std::optional<Config> output = root.optional_table("output");
  g.threshold = output ? output->get_double_or("threshold", g.quench.rho0, {0.0, eos_max_density(g.settings.eos), true, true})
                       : g.quench.rho0;
  if (output) {
    g.extra_thresholds = output->get_doubles_or("extra_thresholds", {}, {0.0, eos_max_density(g.settings.eos), true, true});
    g.growth_window = output->get_double_or("growth_window", g.growth_window, Range::positive());
  }
  check_gls_time_step(root.table("run"), g, c.lattice, c.model.max_speed(), c.bgk.tau, c.bgk.dt);
  c.gls = g;
}
// ---- end GLS

}  // namespace

DbmCase read_dbm_case(const Config& root) {
  DbmCase c;
  c.lattice = read_grid(root.table("grid"));
  const Config model = root.table("model");
  c.model = read_model(model, c.bgk);
  const bool gls = is_gls(model);
  if (!gls) c.initial = read_initial(root.table("initial"), c.lattice);
  const std::optional<Config> boundary = root.optional_table("boundary");
  c.boundaries = read_boundaries(boundary, gls, c.bgk.gamma);
  if (c.bgk.spectral_convection)
    for (const BoundarySide& s : c.boundaries.side)
      if (s.kind != BoundaryKind::periodic)
        model.fail("convection", "\"spectral\" (FFT) convection needs periodic boundaries on all four sides");
  read_run(root.table("run"), model, c);
  if (gls) read_gls_part(root, model, c);
  c.output = read_output(root.optional_table("output"), c);
  c.exact_star = exact_star(c.initial, c.bgk.gamma);
  c.reaction = read_reaction(root, c);
  return c;
}

}  // namespace shockfield::dbm

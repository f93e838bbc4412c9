#include "shockfield/granular/case_file.hpp"

#include <fmt/format.h>

#include "shockfield/core/error.hpp"

namespace shockfield::granular {
namespace {

ChainSpec read_chain(const Config& t, const std::optional<Config>& wall) {
  ChainSpec s;
  s.grains = t.get_int("grains", Range::closed(2, 1e9));
  s.radius = t.get_double("radius");
  if (!(s.radius > 0)) t.fail("radius", fmt::format("{} m makes no grain: expected a radius > 0", s.radius));
  s.density = t.get_double("density", Range::positive());
  s.youngs_modulus = t.get_double("youngs_modulus", Range::positive());
  s.poisson_ratio = t.get_double("poisson_ratio", {-1.0, 0.5, true, true});
  s.gravity = t.get_double_or("gravity", 0.0, Range::non_negative());
  s.damping = t.get_double_or("damping", 0.0, Range::non_negative());
  s.gap = t.get_double_or("gap", 0.0);
  if (s.gap < 0)
    t.fail("gap", fmt::format("{} m: neighbouring grains would start overlapping beyond the static "
                              "equilibrium (expected a gap >= 0)", s.gap));
  if (s.gap > 0 && s.gravity > 0) t.fail("gap", "a gap between grains is no equilibrium under gravity: give gap = 0");
  const std::string kind = wall ? wall->get_choice_or("kind", {"none", "rigid", "elastic"}, "rigid") : "none";
  s.wall = kind == "rigid" ? WallKind::rigid : kind == "elastic" ? WallKind::elastic : WallKind::none;
  if (s.wall == WallKind::elastic) {
    s.wall_youngs_modulus = wall->get_double("youngs_modulus", Range::positive());
    s.wall_poisson_ratio = wall->get_double("poisson_ratio", {-1.0, 0.5, true, true});
  }
  if (s.gravity > 0 && s.wall == WallKind::none)
    t.fail("gravity", "a chain under gravity must rest on a bottom wall: add [wall] kind = \"rigid\" or \"elastic\"");
  return s;
}

std::vector<Impurity> read_impurities(const Config& root, long long grains) {
  std::vector<Impurity> out;
  for (const Config& t : root.tables("impurity")) {
    Impurity imp;
    imp.index = t.get_int("index", Range::closed(0, static_cast<double>(grains - 1)));
    imp.mass_ratio = t.get_double_or("mass_ratio", 1.0, Range::positive());
    imp.radius_ratio = t.get_double_or("radius_ratio", 1.0, Range::positive());
    imp.modulus_ratio = t.get_double_or("modulus_ratio", 1.0, Range::positive());
    if (t.has("poisson_ratio")) imp.poisson_ratio = t.get_double("poisson_ratio", {-1.0, 0.5, true, true});
    out.push_back(imp);
  }
  return out;
}

Impulse read_impulse(const Config& t, long long grains) {
  Impulse imp;
  imp.kind = t.get_choice("kind", {"velocity", "force"}) == "force" ? Impulse::Kind::force : Impulse::Kind::velocity;
  if (imp.kind == Impulse::Kind::velocity) {
    imp.velocity = t.get_double("velocity");
    imp.grains = t.get_int_or("grains", 1, Range::closed(1, static_cast<double>(grains)));
    return imp;
  }
  imp.times = t.get_doubles("times", 0, Range::non_negative());
  imp.forces = t.get_doubles("forces", imp.times.size());
  if (imp.times.size() < 2) t.fail("times", "a force history needs at least two (time, force) points");
  for (std::size_t j = 1; j < imp.times.size(); ++j)
    if (!(imp.times[j] > imp.times[j - 1])) t.fail("times", fmt::format("times must increase (entry {} does not)", j));
  return imp;
}

OutputSpec read_output(const std::optional<Config>& t, double end_time, double dt, long long grains) {
  OutputSpec o;
  o.schedule = read_output_intervals(t, end_time, {.profiles = true, .fields = true, .vtk = true, .dumps = true});
  o.probe_interval = dt;
  if (!t) return o;
  if (o.schedule.dumps && o.schedule.profile_interval == 0)
    t->fail("dump", "dump = true writes a LAMMPS dump with every particle frame, and profile_interval = 0 writes "
                    "none: give profile_interval > 0");
  if (t->has("probes"))
    for (long long g : t->get_ints("probes", 0, Range::closed(0, static_cast<double>(grains - 1))))
      o.probes.push_back(static_cast<std::size_t>(g));
  o.probe_interval = t->get_double_or("probe_interval", dt, Range::positive());
  o.spacetime_stride = t->get_int_or("spacetime_stride", 1, Range::closed(1, static_cast<double>(grains)));
  o.signal_interval = t->get_double_or("signal_interval", 0.0, Range::non_negative());
  if (t->has("energy_above"))
    for (long long g : t->get_ints("energy_above", 0, Range::closed(1, static_cast<double>(grains))))
      o.energy_above.push_back(static_cast<std::size_t>(g));
  return o;
}

}  // namespace

GranularCase read_granular_case(const Config& root) {
  GranularCase c;
  const Config chain = root.table("chain");
  c.chain = read_chain(chain, root.optional_table("wall"));
  c.chain.impurities = read_impurities(root, c.chain.grains);
  const Config impulse = root.table("impulse");
  c.impulse = read_impulse(impulse, c.chain.grains);
  const Config run = root.table("run");
  c.run.end_time = run.get_double("end_time", Range::positive());
  if (run.has("time_step")) c.run.time_step = run.get_double("time_step", Range::positive());
  c.run.safety = run.get_double_or("safety", 0.05, {0.0, 1.0, true, false});

  Chain built;
  try {
    built = build_chain(c.chain);
  } catch (const InputError& e) {
    chain.fail("grains", e.what());
  }
  c.run.stable_step = Simulation::stable_step(built, c.impulse);
  if (c.run.time_step && *c.run.time_step > c.run.stable_step)
    run.fail("time_step", fmt::format("{:.6g} s is above the stable step {:.6g} s of the stiffest contact "
                                      "(docs/theory/granular.md): expected <= {:.6g} s",
                                      *c.run.time_step, c.run.stable_step, c.run.stable_step));
  if (!c.run.time_step && !std::isfinite(c.run.stable_step))
    run.fail("time_step", "nothing loads the chain, so no contact sets a time step: give time_step");
  const double dt = c.run.time_step ? *c.run.time_step : c.run.safety * c.run.stable_step;
  c.output = read_output(root.optional_table("output"), c.run.end_time, dt, c.chain.grains);
  root.derive("stable_step", c.run.stable_step);
  root.derive("time_step", dt);
  root.derive("grain_mass", built.mass.front());
  root.derive("contact_kappa", built.kappa.front());
  root.derive("steps", static_cast<long long>(std::ceil(c.run.end_time / dt)));
  return c;
}

Simulation build_simulation(const GranularCase& c) {
  return Simulation(build_chain(c.chain), c.impulse, c.run.time_step, c.run.safety);
}

}  // namespace shockfield::granular

#include "shockfield/md/case_file.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "shockfield/core/error.hpp"
#include "shockfield/md/analysis_table.hpp"

namespace shockfield::md {

int read_axis(const Config& table, std::string_view key, const std::string& fallback) {
  const std::string a = table.get_choice_or(key, {"x", "y", "z"}, fallback);
  return a[0] - 'x';
}

const std::vector<std::string>& known_dump_fields() {
  static const std::vector<std::string> fields{
      "id", "type", "element", "mass", "x", "y", "z", "xu", "yu", "zu", "ix", "iy", "iz",
      "vx", "vy", "vz", "fx", "fy", "fz", "pe", "ke", "sxx", "syy", "szz", "sxy", "sxz", "syz"};
  return fields;
}

namespace {

// More steps than any run can take (10^12 steps of 1 fs are a millisecond, years of computing);
// the bound keeps the step counters and their sum far from overflowing.
constexpr double kMaxTotalSteps = 1e12;

// [stage.msst] (LAMMPS `fix msst dir shockvel q mu p0 v0 e0 tscale`; docs/md.md).
MsstSettings read_msst(const Config& stage, long long steps) {
  const auto table = stage.optional_table("msst");
  if (!table) stage.fail("msst", "a [stage.msst] table with at least shock_speed (A/ps) for ensemble = \"msst\"");
  const Config& m = *table;
  MsstSettings s;
  s.axis = read_axis(m, "axis", "z");
  s.shock_speed = m.get_double("shock_speed", Range::positive());
  s.q = m.get_double_or("q", 10.0, Range::positive());
  s.mu = m.get_double_or("mu", 0.0, Range::non_negative());
  if (m.has("p0")) s.p0 = m.get_double("p0", Range::closed(-1e7, 1e8));
  if (m.has("v0")) s.v0 = m.get_double("v0", Range::positive());
  if (m.has("e0")) s.e0 = m.get_double("e0");
  s.tscale = m.get_double_or("tscale", 0.01, Range{0.0, 1.0, false, true});
  s.stage_steps = steps;
  return s;
}

// [stage.nphug] (LAMMPS `fix nphug temp T T τ_T iso|aniso|x|y|z P P τ_P tchain pchain` with
// `fix_modify e0 v0 p0`; docs/md.md).
NphugSettings read_nphug(const Config& stage, long long steps) {
  const auto table = stage.optional_table("nphug");
  if (!table) stage.fail("nphug", "a [stage.nphug] table with at least pressure (bar) for ensemble = \"nphug\"");
  const Config& h = *table;
  NphugSettings s;
  NptSettings& npt = s.npt;
  npt.pressure = h.get_double("pressure", Range::closed(-1e7, 1e8));  // bar: −1 TPa to 10 TPa
  const std::string style = h.get_choice_or("style", {"iso", "aniso", "x", "y", "z"}, "z");
  if (style.size() == 1) {  // uniaxial: only that dimension is barostatted
    s.axis = style[0] - 'x';
    npt.dims = {false, false, false};
    npt.dims[static_cast<std::size_t>(s.axis)] = true;
  }
  npt.iso = style == "iso";
  npt.damping = h.get_double_or("damping", 0.1, Range::positive());
  npt.pressure_damping = h.get_double_or("pressure_damping", 1.0, Range::positive());
  npt.chain = static_cast<int>(h.get_int_or("chain", 3, Range::closed(1, 10)));
  npt.pressure_chain = static_cast<int>(h.get_int_or("pressure_chain", 3, Range::closed(0, 10)));
  if (h.has("p0")) s.p0 = h.get_double("p0", Range::closed(-1e7, 1e8));
  if (h.has("v0")) s.v0 = h.get_double("v0", Range::positive());
  if (h.has("e0")) s.e0 = h.get_double("e0");
  s.stage_steps = steps;
  return s;
}

StageSpec read_stage(const Config& t, std::size_t index) {
  StageSpec s;
  s.name = t.get_string_or("name", fmt::format("stage{}", index + 1));
  s.ensemble = t.get_choice_or("ensemble", {"nve", "langevin", "nvt", "npt", "msst", "nphug", "minimize"}, "nve");
  s.steps = s.ensemble == "minimize" ? 0 : t.get_int("steps", Range::closed(0, kMaxTotalSteps));
  s.group = t.get_string_or("group", "all");
  if (s.ensemble == "langevin" || s.ensemble == "nvt" || s.ensemble == "npt") {
    s.temperature = t.get_double("temperature", Range::positive());
    s.damping = t.get_double_or("damping", 0.1, Range::positive());
    if (s.ensemble != "langevin") s.chain = static_cast<int>(t.get_int_or("chain", 3, Range::closed(1, 10)));
  }
  if (s.ensemble == "npt") {
    s.pressure = t.get_double("pressure", Range::closed(-1e7, 1e8));  // bar: −1 TPa to 10 TPa
    s.pressure_damping = t.get_double_or("pressure_damping", 1.0, Range::positive());
    const std::string couple = t.get_choice_or("couple", {"iso", "aniso", "tri"}, "aniso");
    s.couple_iso = couple == "iso";
    if (couple == "tri") {  // LAMMPS `tri`: x y z xy xz yz, each on its own
      if (t.has("pressure_dims"))
        t.fail("pressure_dims",
               "couple = \"tri\" barostats x, y, z, xy, xz and yz (LAMMPS tri); for a subset give "
               "pressure_dims with couple = \"aniso\" or \"iso\"");
      s.pressure_dims = std::array<bool, 3>{true, true, true};
      s.pressure_tilts = {true, true, true};
    }
    if (t.has("pressure_dims")) {  // periodicity is checked against the box in run_case
      s.pressure_dims = std::array<bool, 3>{false, false, false};
      const std::array<std::string, 3> tilts{"xy", "xz", "yz"};
      for (const auto& dim : t.get_strings("pressure_dims")) {
        const auto tilt = std::find(tilts.begin(), tilts.end(), dim);
        if (tilt != tilts.end())
          s.pressure_tilts[static_cast<std::size_t>(tilt - tilts.begin())] = true;
        else if (dim == "x" || dim == "y" || dim == "z")
          (*s.pressure_dims)[dim[0] - 'x'] = true;
        else
          t.fail("pressure_dims", "expected a list of \"x\", \"y\", \"z\", \"xy\", \"xz\", \"yz\"");
      }
    }
    if (t.has("shear_pressure")) {  // LAMMPS `xy P P τ xz P P τ yz P P τ`, constant targets
      const auto p = t.get_doubles("shear_pressure", 3, Range::closed(-1e7, 1e7));
      for (std::size_t k = 0; k < 3; ++k)
        if (p[k] != 0 && !s.pressure_tilts[k])
          t.fail("shear_pressure",
                 fmt::format("a target for the {} tilt, which is not barostatted: use couple = "
                             "\"tri\" or list \"{}\" in pressure_dims",
                             std::array{"xy", "xz", "yz"}[k], std::array{"xy", "xz", "yz"}[k]));
      s.shear_pressure = Vec3(p[0], p[1], p[2]);
    }
  }
  if (s.ensemble == "msst") s.msst = read_msst(t, s.steps);
  else if (t.has("msst")) t.fail("msst", "a [stage.msst] table only with ensemble = \"msst\"");
  if (s.ensemble == "nphug") {
    s.nphug = read_nphug(t, s.steps);
    // LAMMPS: the Hugoniostat's temperature, pressure and energy computes are of group all.
    if (s.group != "all") t.fail("group", "\"all\" for ensemble = \"nphug\" (its pressure and energy are the whole system's)");
  } else if (t.has("nphug")) {
    t.fail("nphug", "a [stage.nphug] table only with ensemble = \"nphug\"");
  }
  if (s.ensemble == "minimize") {
    MinimizeSettings& m = s.minimize;
    m.force_tolerance = t.get_double_or("force_tolerance", 1e-6, Range::positive());
    m.pressure_tolerance = t.get_double_or("pressure_tolerance", 1.0, Range::positive());
    m.max_iterations = t.get_int_or("max_iterations", 100000, Range::closed(1, 1e9));
    m.target_pressure = t.get_double_or("pressure", 0.0);
    if (t.has("relax_box")) {
      for (const auto& dim : t.get_strings("relax_box")) {
        if (dim != "x" && dim != "y" && dim != "z") t.fail("relax_box", "expected a list of \"x\", \"y\", \"z\"");
        m.relax_box[dim[0] - 'x'] = true;
      }
    }
  }
  if (auto p = t.optional_table("piston")) {
    PistonSpec piston;
    piston.axis = read_axis(*p, "axis", "z");
    piston.side = p->get_choice_or("from", {"lo", "hi"}, "lo") == "lo" ? +1 : -1;
    piston.speed = p->get_double("speed", Range::positive());
    if (p->has("position")) piston.position = p->get_double("position");
    s.piston = piston;
  }
  if (t.has("deform_rate")) {
    const auto r = t.get_doubles("deform_rate", 3, Range::closed(-10, 10));
    s.deform_rate = Vec3(r[0], r[1], r[2]);
  }
  if (t.has("deform_tilt_rate")) {
    const auto r = t.get_doubles("deform_tilt_rate", 3, Range::closed(-10, 10));
    s.deform_tilt_rate = Vec3(r[0], r[1], r[2]);
  }
  if (s.ensemble == "npt" || s.deform_rate || s.deform_tilt_rate) s.flip = t.get_bool_or("flip", true);
  if ((s.ensemble == "minimize" || s.ensemble == "msst" || s.ensemble == "nphug") &&
      (s.piston || s.deform_rate || s.deform_tilt_rate))
    t.fail("ensemble", fmt::format("{} stage cannot have a piston, deform_rate or deform_tilt_rate",
                                   s.ensemble == "minimize" ? "a minimisation" : "an " + s.ensemble));
  return s;
}

// [analysis] (docs/md.md): which analyses, how often, and whether the dumps carry their columns.
AnalysisSpec read_analysis(const Config& t) {
  AnalysisSpec a;
  a.every = t.get_int("every", Range::closed(1, 1e12));
  static const std::vector<std::string> known{"acna", "cna", "csp", "coordination", "bpa", "diamond"};
  if (t.has("methods")) a.methods = t.get_strings("methods");
  if (a.methods.empty()) t.fail("methods", "at least one of \"acna\", \"cna\", \"csp\", \"coordination\", \"bpa\", \"diamond\"");
  for (std::size_t k = 0; k < a.methods.size(); ++k) {
    const std::string& m = a.methods[k];
    if (std::find(known.begin(), known.end(), m) == known.end())
      t.fail("methods", fmt::format("one of \"acna\", \"cna\", \"csp\", \"coordination\", \"bpa\", \"diamond\"; got \"{}\"", m));
    if (std::find(a.methods.begin(), a.methods.begin() + static_cast<std::ptrdiff_t>(k), m) != a.methods.begin() + static_cast<std::ptrdiff_t>(k))
      t.fail("methods", fmt::format("each method once; \"{}\" is listed twice", m));
  }
  const bool needs_cutoff = std::any_of(a.methods.begin(), a.methods.end(),
                                        [](const std::string& m) { return m == "cna" || m == "coordination" || m == "bpa"; });
  if (needs_cutoff) a.cutoff = t.get_double("cutoff", Range{0.0, 100.0, true, false});
  else if (t.has("cutoff")) a.cutoff = t.get_double("cutoff", Range{0.0, 100.0, true, false});
  a.csp_neighbors = static_cast<int>(t.get_int_or("csp_neighbors", 12, Range::closed(2, 64)));
  if (a.csp_neighbors % 2 != 0) t.fail("csp_neighbors", "an even number of neighbours (12 fcc, 8 bcc)");
  a.dump_columns = t.get_bool_or("dump_columns", false);
  // The excess energy (Xu et al. 2015 §3.2.3): e0 given, or the median pe of the crystal's atoms
  // by the first structure method (cna, acna, bpa) — one must run.
  a.excess_energy = t.get_bool_or("excess_energy", false);
  if (a.excess_energy) {
    if (t.has("excess_reference")) a.excess_reference = t.get_double("excess_reference", Range::closed(-1e4, 1e4));
    a.excess_crystal = t.get_choice_or("excess_crystal", {"fcc", "hcp", "bcc"}, "fcc");
    const bool structures = std::any_of(a.methods.begin(), a.methods.end(),
                                        [](const std::string& m) { return m == "acna" || m == "cna" || m == "bpa"; });
    if (!a.excess_reference && !structures)
      t.fail("excess_energy", "\"acna\", \"cna\" or \"bpa\" in methods (to find the crystal atoms whose median pe is "
                              "the reference), or excess_reference (eV)");
  } else {
    for (const char* key : {"excess_reference", "excess_crystal"})
      if (t.has(key)) t.fail(key, "excess_energy = true (this key sets its reference)");
  }
  if (t.has("clusters") != t.has("cluster_select"))
    t.fail(t.has("clusters") ? "cluster_select" : "clusters",
           "clusters (a cutoff, Å) and cluster_select (which atoms) go together");
  if (t.has("clusters")) {
    a.clusters = t.get_double("clusters", Range{0.0, 100.0, true, false});
    a.cluster_select = t.get_string("cluster_select");
    a.cluster_min_size = static_cast<std::size_t>(t.get_int_or("cluster_min_size", 1, Range::closed(1, 1e12)));
    try {
      (void)structure_analyses(a);
    } catch (const InputError& e) {
      t.fail("cluster_select", e.what());
    }
  }
  return a;
}

}  // namespace

MdCase read_md_case(const Config& root) {
  MdCase c;
  const Config md = root.table_or_empty("md");  // every key has a default
  c.timestep = md.get_double_or("timestep", 0.001, Range{0.0, 0.1, true, false});
  c.skin = md.get_double_or("skin", 2.0, Range::positive());
  c.neighbor_every = static_cast<int>(md.get_int_or("neighbor_every", 1, Range::closed(1, 1000)));
  c.neighbor_delay = static_cast<int>(md.get_int_or("neighbor_delay", 0, Range::closed(0, 1000)));
  c.neighbor_check = md.get_bool_or("neighbor_check", true);
  c.seed = static_cast<std::uint64_t>(md.get_int_or("seed", 12345, Range::non_negative()));
  md.derive("timestep_fs", c.timestep * 1000.0);

  if (auto v = root.optional_table("velocity")) {
    if (v->has("temperature")) c.temperature = v->get_double("temperature", Range::non_negative());
    for (const Config& add : v->tables("add")) {
      VelocityAdd a;
      a.group = add.get_string("group");
      const auto vel = add.get_doubles("velocity", 3);
      a.velocity = Vec3(vel[0], vel[1], vel[2]);
      c.velocity_adds.push_back(a);
    }
  }

  if (auto o = root.optional_table("output")) {
    OutputSpec& out = c.output;
    out.thermo_every = o->get_int_or("thermo_every", 100, Range::closed(1, 1e12));
    out.checkpoint_every = o->get_int_or("checkpoint_every", 0, Range::non_negative());
    out.dump_every = o->get_int_or("dump_every", 0, Range::non_negative());
    out.dump_fields = o->has("dump_fields") ? o->get_strings("dump_fields")
                                            : std::vector<std::string>{"id", "type", "x", "y", "z", "vx", "vy", "vz", "pe"};
    for (const auto& f : out.dump_fields)
      if (std::find(known_dump_fields().begin(), known_dump_fields().end(), f) == known_dump_fields().end()) {
        std::string list;
        for (const auto& k : known_dump_fields()) list += (list.empty() ? "" : " ") + k;
        o->fail("dump_fields", fmt::format("unknown field \"{}\"; known fields: {}", f, list));
      }
    out.dump_format = o->get_choice_or("dump_format", {"lammps", "extxyz"}, "lammps");
    out.dump_full_precision = o->get_bool_or("dump_full_precision", false);
    out.thermo_full_precision = o->get_bool_or("thermo_full_precision", false);
    out.dump_time = o->get_bool_or("dump_time", false);
    out.h5md_every = o->get_int_or("h5md_every", 0, Range::non_negative());
    out.h5md_forces = o->get_bool_or("h5md_forces", false);
    out.profile_every = o->get_int_or("profile_every", 0, Range::non_negative());
    out.profile_axis = read_axis(*o, "profile_axis", "z");
    out.profile_bin_width = o->get_double_or("profile_bin_width", 5.0, Range::positive());
  }

  if (const auto t = root.optional_table("analysis")) {
    c.output.analysis = read_analysis(*t);
    if (c.output.analysis.dump_columns && c.output.dump_every == 0)
      t->fail("dump_columns", "[output] dump_every > 0: dump_columns adds the analysis to the dumps, and the run writes none");
  }

  const auto stages = root.tables("stage");
  if (stages.empty()) root.fail("stage", "at least one [[stage]] table (what the run does)");
  long long total = 0;
  for (std::size_t k = 0; k < stages.size(); ++k) {
    c.stages.push_back(read_stage(stages[k], k));
    if (c.stages.back().ensemble == "msst" && !c.output.msst_axis) c.output.msst_axis = c.stages.back().msst.axis;
    if (c.stages.back().ensemble == "nphug") c.output.nphug = true;
    total += c.stages.back().steps;  // each <= 10^12: no overflow before the check below
    if (total > kMaxTotalSteps)
      stages[k].fail("steps", fmt::format("the stages up to this one add up to {} steps; expected at "
                                          "most {:.0e} in all", total, kMaxTotalSteps));
  }
  // Frame names dump.<step> with the step zero-padded to the digits of the last step, so that
  // they sort in time order by name too (LAMMPS dump_modify pad).
  if (const auto o = root.optional_table("output"); o && (o->has("dump_pad") || c.output.dump_every > 0))
    c.output.dump_pad = static_cast<int>(o->get_int_or("dump_pad", static_cast<long long>(std::to_string(total).size()),
                                                       Range::closed(0, 19)));
  return c;
}

}  // namespace shockfield::md

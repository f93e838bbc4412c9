#include "file_targets.hpp"

#include "shockfield/core/error.hpp"
#include "shockfield/materials/material_file.hpp"
#include "target_helpers.hpp"

namespace shockfield::fuzz {
namespace {

namespace fs = std::filesystem;

// A bridge that exit 0 must have written a material file without a non-finite value that its
// own reader (materials::MaterialFile::load, what an MPM or PD case calls) accepts.
Outcome check_material_output(Outcome o, const fs::path& file) {
  if (o.kind != Outcome::Kind::accepted) return o;
  const std::string text = read_text(file);
  if (const std::string bad = non_finite_value(text); !bad.empty()) {
    o.kind = Outcome::Kind::non_finite_output, o.message = file.filename().string() + " " + bad;
    return o;
  }
  try {
    materials::MaterialFile::load(file);
  } catch (const InputError& e) {
    o.kind = Outcome::Kind::invalid_output;
    o.message = std::string("the material file the bridge wrote is refused by its reader: ") + e.what();
  }
  return o;
}

// --resume of a copy of a run of `case_file` stopped after `steps` steps, one of whose files
// (`mutated`, relative to the run folder) is the mutant; at most `more` steps more.
Target resume_target(const Context& c, const std::string& name, const fs::path& case_file, int steps,
                     const std::string& mutated, int more) {
  const fs::path base = stopped_run(c, name, case_file, steps);
  return {name,
          {base / "out" / mutated},
          false,
          false,
          "",
          [c, base, more](const fs::path& file, const fs::path& work) {
            fs::copy(base / "out", work / "out", fs::copy_options::recursive);
            fs::copy_file(file, work / "out" / file.filename(), fs::copy_options::overwrite_existing);
            return run_case(c, base / "case.toml", work, {"--resume", "--stop-after", std::to_string(more)});
          }};
}

// A material file (mpm_*.toml: for tests/fixtures/fuzz/cases/material_mpm.toml, else the PD
// crystal bar of material_pd.toml), 5 steps.
Target material_file(const Context& c) {
  const fs::path inputs = c.source / "tests/fixtures/fuzz/inputs/material";
  return {"material_file", {inputs / "mpm_cu.toml", inputs / "pd_cu.toml"}, false, false, "case.toml",
          [c](const fs::path& file, const fs::path& work) {
            const bool mpm = file.filename().string().starts_with("mpm");
            const std::string text =
                read_text(c.source / "tests/fixtures/fuzz/cases" / (mpm ? "material_mpm.toml" : "material_pd.toml"));
            write_text(work / "case.toml", replace_all(text, "@FILE@", file.string()));
            return run_case(c, work / "case.toml", work, {"--stop-after", "5"});
          }};
}

// `shockfield bridge hugoniot-to-eos` on a sweep folder of four MD Hugoniot runs
// (tests/fixtures/fuzz/inputs/bridge_eos/up_*), one file of the first run mutated.
Target bridge_eos(const Context& c) {
  const fs::path sweep = c.source / "tests/fixtures/fuzz/inputs/bridge_eos";
  return {"bridge_eos", {sweep / "up_0.67/hugoniot_shock.toml", sweep / "up_0.67/config.resolved.toml"}, false, false,
          "", [c, sweep](const fs::path& file, const fs::path& work) {
            fs::copy(sweep, work / "sweep", fs::copy_options::recursive);
            fs::copy_file(file, work / "sweep/up_0.67" / file.filename(), fs::copy_options::overwrite_existing);
            fs::create_directories(work / "out");
            const fs::path out = work / "out/cu.toml";
            return check_material_output(run_program({c.shockfield.string(), "bridge", "hugoniot-to-eos",
                                                      (work / "sweep").string(), "-o", out.string()},
                                                     work, c.limits),
                                         out);
          }};
}

// `shockfield bridge elastic --constants FILE --mass 63.546` (the LAMMPS fixture's constants).
Target bridge_elastic(const Context& c) {
  return {"bridge_elastic", {c.source / "tests/fixtures/lammps_elastic/results.toml"}, false, false, "",
          [c](const fs::path& file, const fs::path& work) {
            fs::create_directories(work / "out");
            const fs::path out = work / "out/cu.toml";
            return check_material_output(run_program({c.shockfield.string(), "bridge", "elastic", "--constants",
                                                      file.string(), "--mass", "63.546", "-o", out.string()},
                                                     work, c.limits),
                                         out);
          }};
}

// `shockfield bridge spall` (bridge_spall) or `bridge yield` (bridge_yield) on a small MD tension
// run (256 atoms, 2e10/s) or [111] compression (432 atoms, 1e10/s) of Cu_u3.eam
// (tests/fixtures/fuzz/inputs/bridge_strength/{spall,yield}_run), one of its two files
// (config.resolved.toml, thermo.csv) mutated: the mutant and its linked sibling are the run folder.
Target bridge_strength(const Context& c, const std::string& bridge) {
  const fs::path run = c.source / "tests/fixtures/fuzz/inputs/bridge_strength" / (bridge + "_run");
  return {"bridge_" + bridge, {run / "thermo.csv", run / "config.resolved.toml"}, false, true, "",
          [c, bridge](const fs::path& file, const fs::path& work) {
            fs::create_directories(work / "out");
            const fs::path out = work / "out/cu.toml";
            return check_material_output(run_program({c.shockfield.string(), "bridge", bridge,
                                                      file.parent_path().string(), "-o", out.string()},
                                                     work, c.limits),
                                         out);
          }};
}

// `shockfield bridge domain-growth` on the tracks.csv of a synthetic growing hcp domain (the first
// 11 frames of examples/phasefield_from_md, tests/fixtures/fuzz/inputs/bridge_domain_growth).
Target bridge_domain_growth(const Context& c) {
  return {"bridge_domain_growth", {c.source / "tests/fixtures/fuzz/inputs/bridge_domain_growth/tracks.csv"}, false,
          false, "", [c](const fs::path& file, const fs::path& work) {
            fs::create_directories(work / "out");
            const fs::path out = work / "out/pf.toml";
            return check_material_output(run_program({c.shockfield.string(), "bridge", "domain-growth", file.string(),
                                                      "--interface-width", "2", "-o", out.string()},
                                                     work, c.limits),
                                         out);
          }};
}

}  // namespace

std::vector<Target> file_targets(const Context& c, const std::function<bool(const std::string&)>& wanted) {
  std::vector<Target> t;
  // config.resolved.toml (the input files' hashes) of an MPM run (the case --resume compares with
  // is the checkpoint's `case_input`, mutated by the checkpoint targets); an MD run's H5MD
  // trajectory (frames every 10 steps).
  if (wanted("resume_case"))
    t.push_back(resume_target(c, "resume_case", c.source / "tests/cli/cases/mpm_tiny.toml", 5, "config.resolved.toml", 5));
  if (wanted("resume_h5md"))
    t.push_back(resume_target(c, "resume_h5md", c.source / "tests/fixtures/fuzz/cases/md_h5md.toml", 25,
                              "trajectory.h5md", 10));
  t.push_back(material_file(c));
  t.push_back(bridge_eos(c));
  t.push_back(bridge_elastic(c));
  t.push_back(bridge_strength(c, "spall"));
  t.push_back(bridge_strength(c, "yield"));
  t.push_back(bridge_domain_growth(c));
  return t;
}

}  // namespace shockfield::fuzz

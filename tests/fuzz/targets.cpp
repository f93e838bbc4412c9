#include "targets.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "file_targets.hpp"
#include "in_process.hpp"
#include "target_helpers.hpp"

namespace shockfield::fuzz {
namespace {

namespace fs = std::filesystem;

const fs::path kPotentials = "/usr/share/lammps/potentials";

std::vector<fs::path> sorted_glob(const fs::path& dir, const std::string& file_name) {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir)) {
    const fs::path p = file_name.empty() ? e.path() : e.path() / file_name;
    if (file_name.empty() ? p.extension() == ".toml" : fs::is_regular_file(p)) out.push_back(p);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The MD case of tests/fixtures/fuzz/cases/eam.toml for one potential file (eam* or adp).
struct EamCase {
  std::string style, element, a0;
  bool elements_key;  // eam/alloy and eam/fs name the element
  std::string text(const Context& c, const fs::path& file) const {
    std::string t = read_text(c.source / "tests/fixtures/fuzz/cases/eam.toml");
    t = replace_all(t, "@FILE@", file.string());
    t = replace_all(t, "@STYLE@", style);
    t = replace_all(t, "@ELEMENT@", element);
    t = replace_all(t, "@A0@", a0);
    return replace_all(t, "@ELEMENTS@", elements_key ? fmt::format("elements = [\"{}\"]", element) : "");
  }
};

Target eam_target(const Context& c, const std::string& name, const fs::path& input, EamCase eam) {
  return {name, {input}, false, false, "case.toml", [c, eam](const fs::path& file, const fs::path& work) {
            write_text(work / "case.toml", eam.text(c, file));
            return run_case(c, work / "case.toml", work, {});
          }};
}

// Every mutant of `input` runs the case tests/fixtures/fuzz/cases/<case_template> with @FILE@ its path.
Target template_target(const Context& c, const std::string& name, const std::vector<fs::path>& inputs,
                       const std::string& case_template) {
  return {name, inputs, false, false, "case.toml", [c, case_template](const fs::path& file, const fs::path& work) {
            const std::string text = read_text(c.source / "tests/fixtures/fuzz/cases" / case_template);
            write_text(work / "case.toml", replace_all(text, "@FILE@", file.string()));
            return run_case(c, work / "case.toml", work, {});
          }};
}

// The Morse tables of the pair_style table cross-check (sections M11 with an r column and FPRIME,
// M22 with R, M12 with RSQ).
fs::path pair_table_input(const Context& c) { return c.source / "tests/fixtures/lammps_table/pair.table"; }

// Every mutant of the checkpoint resumes a copy of the stopped run folder.
Target checkpoint_target(const Context& c, const std::string& name, const fs::path& case_file, int steps) {
  const fs::path base = stopped_run(c, name, case_file, steps);
  return {name, {base / "out/checkpoint.h5"}, true, false, "", [c, base](const fs::path& file, const fs::path& work) {
            fs::copy(base / "out", work / "out", fs::copy_options::recursive);
            fs::copy_file(file, work / "out/checkpoint.h5", fs::copy_options::overwrite_existing);
            return run_case(c, base / "case.toml", work, {"--resume"});
          }};
}

// `shockfield analyze geometry FILE`: the point-set reader (CSV, 2D text, XYZ, dump), then the
// Delaunay mesh, clusters and (for the CSV) the rolling-ball surface of what it read.
Outcome analyze_geometry(const Context& c, const fs::path& file, const fs::path& work) {
  std::vector<std::string> argv{c.shockfield.string(), "analyze", "geometry", file.string(), "-o",
                                (work / "out").string(), "-d", "1"};
  if (file.extension() == ".txt") argv.insert(argv.end(), {"--dimension", "2"});
  if (file.extension() == ".csv") argv.insert(argv.end(), {"-r", "5", "--check"});
  return run_program(argv, work, c.limits);
}

// `shockfield analyze atoms`: a dump alone, a dump series (a .lammpstrj input is followed by a
// valid dump), a data file, a .gz dump or an extended XYZ file, with the cutoff analyses and the
// default a-CNA.
Outcome analyze_atoms(const Context& c, const fs::path& file, const fs::path& work) {
  std::vector<std::string> argv{c.shockfield.string(), "analyze", "atoms", file.string()};
  if (file.extension() == ".lammpstrj")
    argv.push_back((c.source / "tests/fixtures/lammps_structure/cu_fcc_perfect.dump").string());
  argv.insert(argv.end(), {"--cna", "3.0858", "--coordination", "3.0858", "--csp", "fcc", "--adaptive-cna", "-j", "1",
                           "-o", (work / "out").string()});
  return run_program(argv, work, c.limits);
}

// `shockfield hugoniot` reusing a finished run: the mutant (hugoniot_shock.toml or
// shock_front_shock.csv) and the other, valid file are the run's; the sweep must not write a
// non-finite number into hugoniot_sweep.csv (but the standard error of a two-point fit).
Outcome hugoniot_reuse(const Context& c, const fs::path& file, const fs::path& work) {
  const fs::path run = work / "sweep/up_1.00";
  fs::create_directories(run);
  for (const auto& e : fs::directory_iterator(file.parent_path())) fs::copy_file(e.path(), run / e.path().filename());
  Outcome o = run_program({c.shockfield.string(), "hugoniot", (c.source / "examples/md_shock_piston/case.toml").string(),
                           "--speeds", "1.0", "--output", (work / "sweep").string(), "-q"},
                          work, c.limits);
  if (o.kind == Outcome::Kind::accepted) {
    // Row 2 of the sweep: every value finite, but us_stderr_km_s (column 4), which a fit of two
    // front positions does not have (nan).
    const std::string csv = read_text(work / "sweep/hugoniot_sweep.csv");
    std::stringstream row(csv.substr(csv.find('\n') + 1));
    std::string cell;
    for (int column = 1; std::getline(row, cell, ','); ++column)
      if (cell.find("inf") != std::string::npos || (column != 4 && cell.find("nan") != std::string::npos))
        o.kind = Outcome::Kind::non_finite_output, o.message = "hugoniot_sweep.csv:\n" + csv;
  }
  return o;
}

// Method, case of tests/cli/cases, steps before the stop whose checkpoint is fuzzed.
struct CheckpointCase {
  const char* method;
  const char* file;
  int steps;
};
constexpr CheckpointCase kCheckpointCases[] = {{"mpm", "mpm_tiny.toml", 5},
                                               {"pd", "pd_tiny.toml", 5},
                                               {"dbm", "dbm_sod.toml", 5},
                                               {"granular", "granular_tiny.toml", 5},
                                               {"phasefield", "phasefield_tiny.toml", 5},
                                               {"phasefield_sharp_front", "phasefield_sharp_front_tiny.toml", 5}};

// A target whose inputs go through a parser in a fork of the fuzzer.
Target in_process(const Context& c, const std::string& name, std::vector<fs::path> inputs,
                  void (*parse)(const fs::path&), bool binary = false, bool with_siblings = false) {
  return {name, std::move(inputs), binary, with_siblings, "", [c, parse](const fs::path& file, const fs::path& work) {
            return run_function([&] { parse(file); }, work, c.limits);
          }};
}

std::vector<fs::path> case_inputs(const Context& c) {
  std::vector<fs::path> cases = sorted_glob(c.source / "tests/cli/cases", "");
  for (const auto& p : sorted_glob(c.source / "examples", "case.toml")) cases.push_back(p);
  return cases;
}

// The examples' other case files (PD bars and crystals, granular chains, macroparticle rods, ...):
// every examples/*/*.toml but case.toml with a `method = ` line.
std::vector<fs::path> example_case_inputs(const Context& c) {
  std::vector<fs::path> cases;
  for (const auto& dir : fs::directory_iterator(c.source / "examples"))
    if (dir.is_directory())
      for (const auto& p : sorted_glob(dir.path(), ""))
        if (p.filename() != "case.toml" && read_text(p).find("\nmethod = ") != std::string::npos) cases.push_back(p);
  std::sort(cases.begin(), cases.end());
  return cases;
}

std::vector<fs::path> field_inputs(const Context& c) {
  std::vector<fs::path> fields;
  for (const char* f : {"grid.csv", "two_disks.csv", "ascii.vti", "binary.vti", "raw.vti",
                        "appended_base64.vti", "vtk_zlib_binary.vti", "vtk_zlib_appended.vti", "points.vtk",
                        "cells.vtk"})
    fields.push_back(c.source / "tests/fixtures/analysis/fields" / f);
  return fields;
}

// A parallel image (.pvti): the summary is mutated, its piece folder linked next to the mutant.
std::vector<fs::path> pvti_inputs(const Context& c) { return {c.source / "tests/fixtures/fuzz/inputs/pvti/grid.pvti"}; }

// Particle frames (.vtp) written by the output layer (ascii, zlib Float32), and a .pvtp of two
// pieces (its piece folder linked next to the mutant).
std::vector<fs::path> vtp_inputs(const Context& c) {
  const fs::path dir = c.source / "tests/fixtures/fuzz/inputs/vtp";
  return {dir / "grains_ascii.vtp", dir / "grains_zlib.vtp", dir / "grains.pvtp"};
}

std::vector<fs::path> point_inputs(const Context& c) {
  std::vector<fs::path> points;
  for (const char* f : {"cube.csv", "pairs.txt", "tet.xyz", "atoms.dump"})
    points.push_back(c.source / "tests/fixtures/fuzz/inputs/points" / f);
  return points;
}

std::vector<fs::path> pd_cloud_inputs(const Context& c) {
  const fs::path dir = c.source / "tests/fixtures/fuzz/inputs/pd_cloud";
  return {dir / "cloud_1d.txt", dir / "cloud_2d.txt", dir / "cloud_3d.txt"};
}

std::vector<fs::path> formula_inputs(const Context& c) {
  return {c.source / "tests/fixtures/fuzz/inputs/formula/formulas.txt"};
}

std::vector<fs::path> pd_velocity_inputs(const Context& c) {
  return {c.source / "tests/fixtures/fuzz/inputs/pd_velocity/velocities_2d.csv"};
}

std::vector<fs::path> material_inputs(const Context& c) {
  const fs::path dir = c.source / "tests/fixtures/fuzz/inputs/material";
  return {dir / "mpm_cu.toml", dir / "pd_cu.toml"};
}

// Extended XYZ: the LAMMPS fixture fe_bcc_perfect written by ASE (ids from the file order), and
// a sheared fcc in a triclinic cell (Lattice with tilts).
std::vector<fs::path> extxyz_inputs(const Context& c) {
  return {c.source / "tests/fixtures/fuzz/inputs/atoms/fe_bcc_perfect.xyz",
          c.source / "tests/fixtures/fuzz/inputs/atoms/cu_fcc_tilted.xyz"};
}

// LAMMPS dumps and data files, orthogonal and triclinic (xy xz yz).
std::vector<fs::path> dump_inputs(const Context& c) {
  return {c.source / "tests/fixtures/io/dump_fcc.lammpstrj", c.source / "tests/fixtures/lammps/cu_u3_thermal.dump",
          c.source / "tests/fixtures/io/dump_triclinic.lammpstrj"};
}

std::vector<fs::path> data_inputs(const Context& c) {
  return {c.source / "tests/fixtures/io/data_fcc.data", c.source / "tests/fixtures/io/data_triclinic.data"};
}

// The parser-only driver (no --shockfield): every parser it links, in-process. The case target
// is `case_parse`, not `case_check`: the mpm, pd and dbm case readers are not linked (they build
// the simulation), so the case_check corpus is not its to replay.
std::vector<Target> parser_targets(const Context& c) {
  return {in_process(c, "case_parse", case_inputs(c), parse_case),
          in_process(c, "eam_funcfl", {kPotentials / "Cu_u3.eam"}, parse_eam),
          in_process(c, "eam_setfl", {kPotentials / "CuNi.eam.alloy"}, parse_eam),
          in_process(c, "eam_fs", {kPotentials / "NiAlH_jea.eam.fs"}, parse_eam),
          in_process(c, "adp", {kPotentials / "Ni.adp"}, parse_eam),
          in_process(c, "pair_table", {pair_table_input(c)}, parse_pair_table),
          in_process(c, "data", data_inputs(c), parse_data),
          in_process(c, "dump", dump_inputs(c), parse_dump),
          in_process(c, "extxyz", extxyz_inputs(c), parse_extxyz),
          in_process(c, "field", field_inputs(c), parse_field),
          in_process(c, "pvti", pvti_inputs(c), parse_field, false, true),
          in_process(c, "points", point_inputs(c), parse_points),
          in_process(c, "vtp", vtp_inputs(c), parse_point_frame, false, true),
          in_process(c, "checkpoint", {c.source / "tests/fixtures/fuzz/inputs/checkpoint/checkpoint.h5"},
                     parse_checkpoint, true),
          in_process(c, "pd_cloud", pd_cloud_inputs(c), parse_pd_cloud),
          in_process(c, "formula", formula_inputs(c), parse_formulas),
          in_process(c, "pd_velocity", pd_velocity_inputs(c), parse_pd_velocities),
          in_process(c, "material_parse", material_inputs(c), parse_material)};
}

std::vector<Target> all_targets(const Context& c, const std::vector<std::string>& names) {
  if (c.shockfield.empty()) return parser_targets(c);
  const auto wanted = [&](const std::string& n) {
    return names.empty() || std::find(names.begin(), names.end(), n) != names.end();
  };
  std::vector<Target> t;
  // Case files of every method: validation only (examples can be large runs).
  const auto check = [c](const fs::path& file, const fs::path& work) {
    return run_program({c.shockfield.string(), "run", file.string(), "--check", "--output", (work / "out").string(), "-q"},
                       work, c.limits);
  };
  t.push_back({"case_check", case_inputs(c), false, true, "", check});
  t.push_back({"case_check_examples", example_case_inputs(c), false, true, "", check});
  // The small cases of the command-line tests, run for five steps: the MD one (case_run_md),
  // and those of every method (case_run).
  const auto run_five = [c](const fs::path& file, const fs::path& work) {
    return run_case(c, file, work, {"--stop-after", "5"});
  };
  t.push_back({"case_run_md", {c.source / "tests/cli/cases/tiny_cu.toml"}, false, true, "", run_five});
  t.push_back({"case_run", sorted_glob(c.source / "tests/cli/cases", ""), false, true, "", run_five});
  t.push_back(eam_target(c, "eam_funcfl", kPotentials / "Cu_u3.eam", {"eam", "Cu", "3.615", false}));
  t.push_back(eam_target(c, "eam_setfl", kPotentials / "CuNi.eam.alloy", {"eam/alloy", "Cu", "3.615", true}));
  t.push_back(eam_target(c, "eam_fs", kPotentials / "NiAlH_jea.eam.fs", {"eam/fs", "Ni", "3.52", true}));
  t.push_back(eam_target(c, "adp", kPotentials / "Ni.adp", {"adp", "Ni", "3.52", true}));
  t.push_back(template_target(c, "pair_table", {pair_table_input(c)}, "pair_table.toml"));
  t.push_back(template_target(c, "data", data_inputs(c), "data.toml"));
  t.push_back(in_process(c, "dump", dump_inputs(c), parse_dump));
  t.push_back(in_process(c, "extxyz", extxyz_inputs(c), parse_extxyz));
  t.push_back(in_process(c, "field", field_inputs(c), parse_field));
  t.push_back(in_process(c, "pvti", pvti_inputs(c), parse_field, false, true));
  t.push_back(in_process(c, "vtp", vtp_inputs(c), parse_point_frame, false, true));
  t.push_back({"points", point_inputs(c), false, false, "",
               [c](const fs::path& file, const fs::path& work) { return analyze_geometry(c, file, work); }});
  const auto atoms = [c](const fs::path& file, const fs::path& work) { return analyze_atoms(c, file, work); };
  t.push_back({"atoms",
               {c.source / "tests/fixtures/lammps_structure/fe_bcc_perfect.dump",
                c.source / "tests/fixtures/io/dump_fcc.lammpstrj", c.source / "tests/fixtures/io/data_fcc.data"},
               false, false, "", atoms});
  const fs::path inputs = c.source / "tests/fixtures/fuzz/inputs";
  t.push_back({"atoms_gz", {inputs / "atoms/fe_bcc_perfect.dump.gz"}, true, false, "", atoms});
  t.push_back({"atoms_xyz", extxyz_inputs(c), false, false, "", atoms});
  t.push_back({"hugoniot", {inputs / "hugoniot/hugoniot_shock.toml", inputs / "hugoniot/shock_front_shock.csv"}, false,
               true, "", [c](const fs::path& file, const fs::path& work) { return hugoniot_reuse(c, file, work); }});
  // Checkpoints of every method: the Cu EAM run (checkpoint), then the small command-line cases.
  if (wanted("checkpoint")) {
    const fs::path base = c.work / "checkpoint_case";
    fs::create_directories(base);
    write_text(base / "case.toml", EamCase{"eam", "Cu", "3.615", false}.text(c, kPotentials / "Cu_u3.eam"));
    t.push_back(checkpoint_target(c, "checkpoint", base / "case.toml", 10));
  }
  const fs::path cli_cases = c.source / "tests/cli/cases";
  for (const auto& [method, file, steps] : kCheckpointCases)
    if (wanted("checkpoint_" + std::string(method)))
      t.push_back(checkpoint_target(c, "checkpoint_" + std::string(method), cli_cases / file, steps));
  t.push_back(in_process(c, "pd_cloud", pd_cloud_inputs(c), parse_pd_cloud));
  t.push_back(in_process(c, "formula", formula_inputs(c), parse_formulas));
  t.push_back(in_process(c, "pd_velocity", pd_velocity_inputs(c), parse_pd_velocities));
  for (Target& x : file_targets(c, wanted)) t.push_back(std::move(x));
  return t;
}

}  // namespace

std::vector<Target> make_targets(const Context& context, const std::vector<std::string>& names, bool skip_unknown) {
  auto targets = all_targets(context, names);
  std::string known;
  for (const auto& t : targets) known += " " + t.name;
  for (const auto& n : names)
    if (!skip_unknown && std::none_of(targets.begin(), targets.end(), [&](const Target& t) { return t.name == n; }))
      throw std::runtime_error(fmt::format("unknown fuzz target '{}' (known:{})", n, known));
  std::erase_if(targets, [&](const Target& x) {
    return !names.empty() && std::find(names.begin(), names.end(), x.name) == names.end();
  });
  for (const auto& t : targets)
    for (const auto& p : t.inputs)
      if (!fs::is_regular_file(p))
        throw std::runtime_error(fmt::format("fuzz target {}: input {} not found", t.name, p.string()));
  return targets;
}

}  // namespace shockfield::fuzz

#include "targets.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "shockfield/analysis/field_reader.hpp"
#include "shockfield/io/lammps_dump.hpp"

namespace shockfield::fuzz {
namespace {

namespace fs = std::filesystem;

const fs::path kPotentials = "/usr/share/lammps/potentials";

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot read a fuzz input", file.string()));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (auto p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) s.replace(p, from.size(), to);
  return s;
}

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

// The MD case of tests/fixtures/fuzz/cases/eam.toml for one potential file.
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

Outcome run_case(const Context& c, const fs::path& case_file, const fs::path& work,
                 std::vector<std::string> extra) {
  std::vector<std::string> argv{c.shockfield.string(), "run", case_file.string(), "--output",
                                (work / "out").string(), "-q", "-j", "1"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  return run_program(argv, work, c.limits);
}

Target eam_target(const Context& c, const std::string& name, const fs::path& input, EamCase eam) {
  return {name, {input}, false, false, "case.toml", [c, eam](const fs::path& file, const fs::path& work) {
            write_text(work / "case.toml", eam.text(c, file));
            return run_case(c, work / "case.toml", work, {});
          }};
}

// A run folder stopped at step 10 of 20 (Cu_u3.eam): its checkpoint is the checkpoint target's
// input, and every mutant resumes a copy of the folder.
fs::path checkpoint_base(const Context& c) {
  const fs::path base = c.work / "checkpoint_base";
  fs::remove_all(base);  // made anew by every fuzz run: the binary (and its format) may have changed
  fs::create_directories(base);
  write_text(base / "case.toml", EamCase{"eam", "Cu", "3.615", false}.text(c, kPotentials / "Cu_u3.eam"));
  const Outcome o = run_case(c, base / "case.toml", base, {"--stop-after", "10"});
  if (!fs::exists(base / "out/checkpoint.h5"))
    throw std::runtime_error(fmt::format("the checkpoint fuzz target's base run wrote no checkpoint "
                                         "({}): {}", kind_name(o.kind), o.message));
  return base;
}

std::vector<Target> all_targets(const Context& c, const std::vector<std::string>& names) {
  const auto wanted = [&](const std::string& n) {
    return names.empty() || std::find(names.begin(), names.end(), n) != names.end();
  };
  std::vector<Target> t;
  // Case files of every method: validation only (examples can be large runs).
  std::vector<fs::path> cases = sorted_glob(c.source / "tests/cli/cases", "");
  for (const auto& p : sorted_glob(c.source / "examples", "case.toml")) cases.push_back(p);
  t.push_back({"case_check", cases, false, true, "", [c](const fs::path& file, const fs::path& work) {
                 return run_program({c.shockfield.string(), "run", file.string(), "--check", "--output",
                                     (work / "out").string(), "-q"}, work, c.limits);
               }});
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
  t.push_back({"data", {c.source / "tests/fixtures/io/data_fcc.data"}, false, false, "case.toml",
               [c](const fs::path& file, const fs::path& work) {
                 const std::string text = read_text(c.source / "tests/fixtures/fuzz/cases/data.toml");
                 write_text(work / "case.toml", replace_all(text, "@FILE@", file.string()));
                 return run_case(c, work / "case.toml", work, {});
               }});
  t.push_back({"dump",
               {c.source / "tests/fixtures/io/dump_fcc.lammpstrj", c.source / "tests/fixtures/lammps/cu_u3_thermal.dump"},
               false, false, "", [c](const fs::path& file, const fs::path& work) {
                 return run_function([&] {
                   for (const auto& frame : io::read_dump(file)) {
                     if (frame.has("id")) frame.ids();
                     if (frame.has("type")) frame.types();
                     frame.positions();
                   }
                 }, work, c.limits);
               }});
  std::vector<fs::path> fields;
  for (const char* f : {"grid.csv", "two_disks.csv", "ascii.vti", "binary.vti", "raw.vti",
                        "appended_base64.vti", "points.vtk", "cells.vtk"})
    fields.push_back(c.source / "tests/fixtures/analysis/fields" / f);
  t.push_back({"field", fields, false, false, "", [c](const fs::path& file, const fs::path& work) {
                 return run_function([&] { analysis::read_grid_field(file.string()); }, work, c.limits);
               }});
  if (wanted("checkpoint")) {
    const fs::path base = checkpoint_base(c);
    t.push_back({"checkpoint", {base / "out/checkpoint.h5"}, true, false, "",
                 [c, base](const fs::path& file, const fs::path& work) {
                   fs::copy(base / "out", work / "out", fs::copy_options::recursive);
                   fs::copy_file(file, work / "out/checkpoint.h5", fs::copy_options::overwrite_existing);
                   return run_case(c, base / "case.toml", work, {"--resume"});
                 }});
  }
  std::erase_if(t, [&](const Target& x) { return !wanted(x.name); });
  return t;
}

}  // namespace

std::vector<Target> make_targets(const Context& context, const std::vector<std::string>& names) {
  auto targets = all_targets(context, names);
  for (const auto& n : names)
    if (std::none_of(targets.begin(), targets.end(), [&](const Target& t) { return t.name == n; }))
      throw std::runtime_error(fmt::format("unknown fuzz target '{}' (known: case_check case_run_md "
                                           "case_run eam_funcfl eam_setfl eam_fs data dump field checkpoint)", n));
  for (const auto& t : targets)
    for (const auto& p : t.inputs)
      if (!fs::is_regular_file(p))
        throw std::runtime_error(fmt::format("fuzz target {}: input {} not found", t.name, p.string()));
  return targets;
}

}  // namespace shockfield::fuzz

// shockfield_fuzz: the mutation fuzzer of the test suite (docs/robustness.md). For each target
// (targets.hpp) it makes `--mutants` mutants of the target's valid inputs (mutator.hpp, mutant i
// of seed s is always the same), puts each through shockfield in a child process (sandbox.hpp)
// and requires of every one: accepted, or refused with an input error (exit 2) whose message
// names the file, or stopped by a run-time diagnosis (exit 3); no signal, no sanitizer report,
// finished within the time bound, output within the size bound. --replay DIR puts every file of
// DIR/<target>/ (the corpus of invalid inputs that once crashed, hung or were accepted) through
// its target unmutated: each must be refused (exit 2) or diagnosed (exit 3).
// Without --shockfield (shockfield_fuzz_parsers: the parsers alone under ASan + UBSan, for CI)
// only the in-process parser targets exist. A failing mutant is saved to <work>/failures/ with
// its description; exit status 1.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "mutator.hpp"
#include "targets.hpp"

namespace fs = std::filesystem;
using shockfield::fuzz::Outcome;

namespace {

struct Options {
  shockfield::fuzz::Context context;
  std::vector<std::string> targets;
  std::size_t mutants = 200;
  std::uint64_t seed = 1;
  std::optional<std::size_t> only;  // run mutant i alone
  std::optional<fs::path> replay;
};

[[noreturn]] void usage(const std::string& problem) {
  fmt::print(stderr,
             "{}\nusage: shockfield_fuzz [--shockfield BIN] --source DIR --work DIR [--target NAME]... "
             "[--mutants N] [--seed S] [--only I] [--replay CORPUS] [--timeout SECONDS] [--memory-limit GB (0: none)]\n",
             problem);
  std::exit(64);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) usage("missing value after " + a);
    const std::string v = argv[++i];
    if (a == "--shockfield") o.context.shockfield = fs::absolute(v);
    else if (a == "--source") o.context.source = fs::absolute(v);
    else if (a == "--work") o.context.work = fs::absolute(v);
    else if (a == "--target") o.targets.push_back(v);
    else if (a == "--mutants") o.mutants = std::stoul(v);
    else if (a == "--seed") o.seed = std::stoull(v);
    else if (a == "--only") o.only = std::stoul(v);
    else if (a == "--replay") o.replay = fs::absolute(v);
    else if (a == "--timeout") o.context.limits.seconds = std::stod(v);
    else if (a == "--memory-limit") o.context.limits.memory_bytes = static_cast<std::uintmax_t>(std::stod(v) * (1 << 30));
    else usage("unknown option " + a);
  }
  if (o.context.source.empty() || o.context.work.empty()) usage("--source and --work are required");
  return o;
}

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// What is wrong with an outcome, or nothing.
std::optional<std::string> problem(const Outcome& o, const std::string& file_name, const std::string& carrier) {
  using K = Outcome::Kind;
  if (o.sanitizer_report) return "sanitizer report";
  switch (o.kind) {
    case K::accepted: case K::stopped: return std::nullopt;
    case K::run_error:  // every input is small: running out of memory means a count trusted too far
      if (o.message.find("out of memory") != std::string::npos)
        return std::string("out of memory under the fuzzer's memory bound (a count trusted too far)");
      return std::nullopt;
    case K::input_error:
      if (o.message.find(file_name) == std::string::npos &&
          (carrier.empty() || o.message.find(carrier) == std::string::npos))
        return fmt::format("the message does not name {}", file_name);
      return std::nullopt;
    case K::crashed: return fmt::format("killed by signal {}", o.detail);
    case K::other_error: return fmt::format("exit code {} (expected 0, 2 or 3)", o.detail);
    default: return std::string(shockfield::fuzz::kind_name(o.kind));
  }
}

struct Tally {
  std::map<std::string, std::size_t> kinds;
  std::size_t failures = 0, total = 0;
  double slowest = 0;
  std::string slowest_label;
};

// Puts one file through a target in a fresh work folder; reports and saves a failure.
// `must_refuse`: a corpus input (each is invalid) must end in an input error or a diagnosis.
void run_one(const shockfield::fuzz::Target& t, const fs::path& original, const std::string& bytes,
             const std::string& label, const Options& o, Tally& tally, bool must_refuse) {
  const fs::path work = o.context.work / t.name / "m";
  fs::remove_all(work);
  fs::create_directories(work / "in");
  const fs::path file = work / "in" / original.filename();
  if (t.with_siblings)
    for (const auto& e : fs::directory_iterator(original.parent_path()))
      if (e.path().filename() != original.filename()) fs::create_symlink(e.path(), work / "in" / e.path().filename());
  std::ofstream(file, std::ios::binary) << bytes;
  const Outcome out = t.run(file, work);
  ++tally.total;
  ++tally.kinds[shockfield::fuzz::kind_name(out.kind)];
  if (out.seconds > tally.slowest) tally.slowest = out.seconds, tally.slowest_label = label;
  auto p = problem(out, original.filename().string(), t.carrier);
  if (!p && must_refuse && out.kind != Outcome::Kind::input_error && out.kind != Outcome::Kind::run_error)
    p = fmt::format("{}: a corpus input must be refused (exit 2) or diagnosed (exit 3)",
                    shockfield::fuzz::kind_name(out.kind));
  if (p) {
    ++tally.failures;
    const fs::path saved = o.context.work / "failures" / t.name;
    fs::create_directories(saved);
    const std::string stem = fmt::format("{}_{}", tally.total - 1, original.filename().string());
    std::ofstream(saved / stem, std::ios::binary) << bytes;
    std::ofstream(saved / (stem + ".txt")) << label << "\n" << *p << "\n" << out.message << "\n";
    fmt::print("FAIL {} {}: {} ({:.2f} s)\n  {}\n  saved as {}\n", t.name, label, *p, out.seconds,
               out.message.substr(0, 600), (saved / stem).string());
  }
}

void print_tally(const std::string& name, const Tally& t, const std::string& what) {
  std::string kinds;
  for (const auto& [k, n] : t.kinds) kinds += fmt::format("{}{} {}", kinds.empty() ? "" : ", ", n, k);
  fmt::print("fuzz {}: {} {}: {}; {} failures; slowest {:.2f} s ({})\n", name, t.total, what, kinds,
             t.failures, t.slowest, t.slowest_label.substr(0, 160));
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  std::vector<shockfield::fuzz::Target> targets;
  std::vector<std::string> names = o.targets;
  if (o.replay && names.empty())  // the targets that have corpus files (not the case templates or inputs)
    for (const auto& e : fs::directory_iterator(*o.replay))
      if (e.is_directory() && e.path().filename() != "cases" && e.path().filename() != "inputs")
        names.push_back(e.path().filename().string());
  try {
    targets = shockfield::fuzz::make_targets(o.context, names, o.replay.has_value());
  } catch (const std::exception& e) {
    fmt::print(stderr, "shockfield_fuzz: {}\n", e.what());
    return 64;
  }
  std::size_t failures = 0;
  for (const auto& t : targets) {
    Tally tally;
    if (o.replay) {
      const fs::path dir = *o.replay / t.name;
      if (!fs::is_directory(dir)) continue;
      std::vector<fs::path> files;
      for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() != ".md") files.push_back(e.path());
      std::sort(files.begin(), files.end());
      for (const auto& f : files) run_one(t, f, read_bytes(f), f.filename().string(), o, tally, true);
      print_tally(t.name, tally, "corpus files");
    } else {
      std::vector<std::string> texts;
      for (const auto& p : t.inputs) texts.push_back(read_bytes(p));
      for (std::size_t i = o.only.value_or(0); i < (o.only ? *o.only + 1 : o.mutants); ++i) {
        const std::size_t k = i % t.inputs.size();
        shockfield::fuzz::Mutator m(shockfield::fuzz::mutant_seed(o.seed, i), t.binary);
        const std::string mutant = m.mutate(texts[k]);
        run_one(t, t.inputs[k], mutant,
                fmt::format("mutant {} (--seed {} --only {}) of {}: {}", i, o.seed, i, t.inputs[k].string(), m.description()),
                o, tally, false);
      }
      print_tally(t.name, tally, fmt::format("mutants (seed {})", o.seed));
    }
    failures += tally.failures;
  }
  return failures == 0 ? 0 : 1;
}

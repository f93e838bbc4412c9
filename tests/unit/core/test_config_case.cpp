// A case loaded for a run: --set overrides refused like the file's values (wrong key, wrong type,
// bad syntax) and naming --set; a resolved configuration fed back with its [derived] checked;
// input files resolved, recorded and refused when missing; provenance carried by the resolved
// configuration.
#include <gtest/gtest.h>

#include "support/scratch_path.hpp"

#include <fstream>

#include "shockfield/core/config.hpp"
#include "shockfield/core/error.hpp"

using shockfield::Config;
using shockfield::InputError;
using shockfield::Range;

namespace {

class ConfigCase : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = shockfield::testing::scratch_path("shockfield_config_case");
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  Config load(const std::string& text, const std::vector<std::string>& overrides = {}) {
    return Config::load(write("case.toml", text), overrides);
  }

  std::filesystem::path dir_;
};

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Reads the keys of a small case the way a method would.
void read_case(const Config& c) {
  c.get_double("dt", Range::positive());
  c.table("output").get_int_or("every", 10);
  for (const auto& stage : c.tables("stage")) stage.get_int("steps");
  c.check_unknown_keys();
}

const std::string kCase = "dt = 0.5\n[output]\nevery = 5\n[[stage]]\nsteps = 10\n[[stage]]\nsteps = 20\n";

}  // namespace

TEST_F(ConfigCase, SetEqualsEditingTheFile) {
  const Config edited = load("dt = 0.25\n[output]\nevery = 7\n[[stage]]\nsteps = 10\n[[stage]]\nsteps = 30\n");
  const Config set = load(kCase, {"dt=0.25", "output.every = 7", "stage[1].steps=30"});
  read_case(edited);
  read_case(set);
  EXPECT_DOUBLE_EQ(set.get_double("dt"), 0.25);
  EXPECT_EQ(set.tables("stage")[1].get_int("steps"), 30);
  EXPECT_EQ(set.case_toml(), edited.case_toml());
  // The resolved configuration holds the same values and says which came from --set.
  const std::string resolved = set.resolved_toml();
  EXPECT_NE(resolved.find("# --set dt=0.25\n"), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("# --set stage[1].steps=30\n"), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("dt = 0.25"), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("steps = 30"), std::string::npos) << resolved;
}

TEST_F(ConfigCase, SetOfAnOptionalKeyAddsIt) {
  const Config set = load("dt = 0.5\n[output]\n", {"output.every=3"});
  EXPECT_EQ(set.table("output").get_int_or("every", 10), 3);
}

TEST_F(ConfigCase, WrongKeyFromSetIsRefusedNamingSet) {
  const Config typo = load(kCase, {"output.evry=3"});
  const std::string msg = error_of([&] { read_case(typo); });
  EXPECT_NE(msg.find("unknown key 'output.evry' (from --set output.evry=3)"), std::string::npos) << msg;
  // A misspelt table: the table --set created is the unknown key.
  const Config table = load(kCase, {"outptu.every=3"});
  const std::string msg2 = error_of([&] { read_case(table); });
  EXPECT_NE(msg2.find("'outptu' (from --set outptu.every=3)"), std::string::npos) << msg2;
}

TEST_F(ConfigCase, WrongTypeOrRangeFromSetIsRefusedNamingSet) {
  const Config text = load(kCase, {"dt=\"fast\""});
  const std::string msg = error_of([&] { read_case(text); });
  EXPECT_NE(msg.find("case.toml (from --set dt=\"fast\"): key 'dt': expected a number"), std::string::npos) << msg;
  const Config negative = load(kCase, {"dt=-1"});
  EXPECT_NE(error_of([&] { read_case(negative); }).find("(from --set dt=-1): key 'dt': expected a number > 0"),
            std::string::npos);
  const Config fractional = load(kCase, {"stage[0].steps=1.5"});
  EXPECT_NE(error_of([&] { read_case(fractional); })
                .find("(from --set stage[0].steps=1.5): key 'stage[0].steps': expected an integer"),
            std::string::npos);
  // An inline table replacing a table: its keys are refused as coming from --set too.
  const Config inline_table = load(kCase, {"output={ every = \"x\" }"});
  EXPECT_NE(error_of([&] { read_case(inline_table); }).find("(from --set output={ every = \"x\" })"),
            std::string::npos);
}

TEST_F(ConfigCase, MalformedSetIsRefusedBeforeReading) {
  EXPECT_NE(error_of([&] { load(kCase, {"dt"}); }).find("--set 'dt': expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(error_of([&] { load(kCase, {"=1"}); }).find("expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(error_of([&] { load(kCase, {"a..b=1"}); }).find("expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(error_of([&] { load(kCase, {"stage[x].steps=1"}); }).find("expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(error_of([&] { load(kCase, {"name=fcc"}); }).find("--set 'name=fcc': the value is not TOML"),
            std::string::npos);
  EXPECT_NE(error_of([&] { load(kCase, {"dt=1\nextra = 2"}); }).find("more than one TOML value"), std::string::npos);
  EXPECT_NE(error_of([&] { load(kCase, {"dt.x=1"}); }).find("'dt' in " + (dir_ / "case.toml").string() + " is not a table"),
            std::string::npos);
  EXPECT_NE(error_of([&] { load(kCase, {"stage[2].steps=1"}); }).find("has no [[stage]] table number 2"),
            std::string::npos);
}

TEST_F(ConfigCase, ResolvedConfigurationReplays) {
  const auto derive = [](const Config& c) {
    read_case(c);
    c.derive("total_steps", 30LL);
    c.derive("courant", c.get_double("dt") / 3.0);
    c.derive("verdict", std::string("stable"));
  };
  const Config first = load(kCase);
  derive(first);
  first.set_provenance(toml::table{{"host", "box"}});
  const std::string resolved = first.resolved_toml();
  EXPECT_NE(resolved.find("[provenance]"), std::string::npos) << resolved;
  // Untouched: accepted, every stored value checked, and [provenance] is no unknown key.
  const Config replay = Config::load(write("resolved.toml", resolved), {});
  EXPECT_NO_THROW(derive(replay));
  EXPECT_NO_THROW(replay.check_replayed_derived());
  EXPECT_EQ(replay.case_toml().find("derived"), std::string::npos);
  EXPECT_EQ(replay.case_toml().find("provenance"), std::string::npos);
  // A [derived] value tampered with: refused naming the key, both values and the file.
  std::string tampered = resolved;
  tampered.replace(tampered.find("total_steps = 30"), 16, "total_steps = 31");
  const Config bad = Config::load(write("tampered.toml", tampered), {});
  const std::string msg = error_of([&] { derive(bad); });
  EXPECT_NE(msg.find("tampered.toml:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("[derived] total_steps = 31 in the file, but this case derives total_steps = 30"),
            std::string::npos) << msg;
  // A value changed since resolving (here with --set) changes a derived double: refused.
  const Config changed = Config::load(write("resolved.toml", resolved), {"dt=0.6"});
  EXPECT_NE(error_of([&] { derive(changed); }).find("[derived] courant = 0.16666"), std::string::npos);
  // A stored key this case never derives: refused by check_replayed_derived.
  std::string extra = resolved;
  extra.insert(extra.find("total_steps"), "gone = 1\n");
  const Config stale = Config::load(write("extra.toml", extra), {});
  derive(stale);
  const std::string never = error_of([&] { stale.check_replayed_derived(); });
  EXPECT_NE(never.find("extra.toml: [derived] has a key that this case does not derive: gone"), std::string::npos)
      << never;
}

TEST_F(ConfigCase, ReplayedDoublesAgreeToOnePartIn1e12) {
  const Config near = load("dt = 1.0\n[derived]\nx = 0.3333333333333\ny = 2.0\n");
  EXPECT_NO_THROW(near.derive("x", 0.3333333333333 * (1 + 5e-13)));
  EXPECT_NO_THROW(near.derive("y", 2.0));
  const Config far = load("dt = 1.0\n[derived]\nx = 0.3333333333333\n");
  EXPECT_THROW(far.derive("x", 0.3333333333333 * (1 + 5e-12)), InputError);
  const Config types = load("dt = 1.0\n[derived]\nn = 2.0\ns = 'a'\n");
  EXPECT_THROW(types.derive("n", 2LL), InputError);  // an integer must be stored as one
  EXPECT_THROW(types.derive("s", std::string("b")), InputError);
}

TEST_F(ConfigCase, InputFilesAreResolvedRecordedAndRefusedWhenMissing) {
  write("pot.eam", "potential");
  std::filesystem::create_directories(dir_ / "sub");
  write("sub/data.txt", "data");
  const Config c = load("pot = \"pot.eam\"\ndata = \"sub/../sub/data.txt\"\nagain = \"pot.eam\"\n"
                        "missing = \"nope.eam\"\nfolder = \"sub\"\nnumber = 3\n");
  EXPECT_EQ(c.get_input_file("pot"), dir_ / "pot.eam");
  EXPECT_EQ(c.get_input_file("data"), dir_ / "sub" / "data.txt");
  EXPECT_EQ(c.get_input_file("again"), dir_ / "pot.eam");
  EXPECT_EQ(c.input_files(), (std::vector<std::filesystem::path>{dir_ / "pot.eam", dir_ / "sub" / "data.txt"}));
  EXPECT_NE(c.resolved_toml().find("data = '" + (dir_ / "sub" / "data.txt").string() + "'"), std::string::npos)
      << c.resolved_toml();
  const std::string missing = error_of([&] { c.get_input_file("missing"); });
  EXPECT_NE(missing.find("case.toml:4: key 'missing': file 'nope.eam' not found; tried " +
                         (dir_ / "nope.eam").string() + ": cannot open (no such file)"),
            std::string::npos) << missing;
  EXPECT_NE(error_of([&] { c.get_input_file("folder"); }).find("cannot open (not a regular file)"), std::string::npos);
  EXPECT_NE(error_of([&] { c.get_input_file("number"); }).find("key 'number': expected a string"), std::string::npos);
  EXPECT_NE(error_of([&] { c.get_input_file("absent"); }).find("key 'absent': missing required value"),
            std::string::npos);
  // Extra folders are tried in order and all listed when none has the file.
  const std::string listed = error_of([&] { c.get_input_file("missing", {dir_ / "sub", "/nonexistent"}); });
  EXPECT_NE(listed.find((dir_ / "sub" / "nope.eam").string() + ": cannot open (no such file), /nonexistent/nope.eam"),
            std::string::npos) << listed;
  EXPECT_EQ(c.get_input_file("data", {"/nonexistent", dir_}), dir_ / "sub" / "data.txt");
}

TEST_F(ConfigCase, PlainLoadStillRefusesDerivedAsUnknown) {
  // Config::load(file) without overrides is plain reading (material and Hugoniot files).
  const Config c = Config::load(write("plain.toml", "dt = 1.0\n[derived]\nx = 1\n"));
  c.get_double("dt");
  EXPECT_NE(error_of([&] { c.check_unknown_keys(); }).find("'derived' (line 2)"), std::string::npos);
}

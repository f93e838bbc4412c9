// Material files (materials/material_file.hpp): the Voigt, Reuss and Hill averages against values
// computed by hand, a written file read back to the same numbers, and a bridge's update keeping
// the other sections and provenance entries of the file it writes into.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "shockfield/core/error.hpp"
#include "shockfield/materials/material_file.hpp"
#include "support/scratch_path.hpp"

using namespace shockfield;
using namespace shockfield::materials;

// Copper of Foiles, Baskes & Daw (1986) Table I: C11 = 167, C12 = 124, C44 = 76 GPa. By hand:
// K = (167 + 2·124)/3 = 138.3333 GPa; G_V = (43 + 3·76)/5 = 54.2 GPa;
// G_R = 5·43·76/(4·76 + 3·43) = 16340/433 = 37.73672 GPa; G_H = (54.2 + 37.73672)/2 = 45.96836 GPa.
// Tolerance 1e-6 relative: the hand values are rounded to 7 digits.
TEST(MaterialFile, CubicAveragesOfCopper) {
  const auto rel = [](double a, double b) { return std::abs(a - b) / b; };
  const IsotropicModuli v = cubic_average(167e9, 124e9, 76e9, "voigt");
  const IsotropicModuli r = cubic_average(167e9, 124e9, 76e9, "reuss");
  const IsotropicModuli h = cubic_average(167e9, 124e9, 76e9, "hill");
  EXPECT_LT(rel(v.bulk, 138.3333e9), 1e-6);
  EXPECT_EQ(v.bulk, r.bulk);
  EXPECT_EQ(v.bulk, h.bulk);
  EXPECT_LT(rel(v.shear, 54.2e9), 1e-6);
  EXPECT_LT(rel(r.shear, 37.73672e9), 1e-6);
  EXPECT_LT(rel(h.shear, 45.96836e9), 1e-6);
  EXPECT_THROW(cubic_average(167e9, 124e9, 76e9, "mean"), InputError);
  // An isotropic crystal (C44 = (C11 − C12)/2) has G_V = G_R = C44.
  const IsotropicModuli iso = cubic_average(200e9, 100e9, 50e9, "reuss");
  EXPECT_NEAR(iso.shear, 50e9, 1e-3);
  EXPECT_NEAR(cubic_average(200e9, 100e9, 50e9, "voigt").shear, 50e9, 1e-3);
}

TEST(MaterialFile, WrittenFileReadsBack) {
  const auto file = shockfield::testing::scratch_path("material_file_round_trip.toml");
  toml::table entry{{"command", "test"}, {"fit", toml::table{{"c0_m_s", 3900.5}, {"c0_stderr_m_s", 12.25}}}};
  const std::map<std::string, double> values{{"eos.rho0", 8930.0},  {"eos.c0", 3900.123456789},
                                             {"eos.s", 1.51},       {"eos.gamma0", 2.0},
                                             {"elasticity.c11", 170e9}, {"elasticity.c12", 123e9},
                                             {"elasticity.c44", 76e9}};
  write_bridged_material(file, false, "cu", "test_bridge", values, {{"eos.note", "gamma0 from \"the library\""}}, entry);
  const MaterialFile m = MaterialFile::load(file);
  for (const auto& [key, v] : values) EXPECT_EQ(*m.get(key), v) << key;  // written to round-trip exactly
  EXPECT_FALSE(m.get("eos.s2"));
  EXPECT_EQ(m.provenance().at_path("test_bridge.fit.c0_stderr_m_s").value_or(0.0), 12.25);
  EXPECT_EQ(m.sha256().size(), 64u);

  // A second bridge updates the file: its section replaces [elasticity] whole, [eos], the note
  // and the first entry stay.
  write_bridged_material(file, true, "cu", "elastic", {{"elasticity.shear", 46e9}}, {}, toml::table{{"command", "b"}});
  const MaterialFile u = MaterialFile::load(file);
  EXPECT_DOUBLE_EQ(*u.get("eos.c0"), 3900.123456789);
  EXPECT_DOUBLE_EQ(*u.get("elasticity.shear"), 46e9);
  EXPECT_FALSE(u.get("elasticity.c11"));
  EXPECT_TRUE(u.provenance().contains("test_bridge"));
  EXPECT_TRUE(u.provenance().contains("elastic"));
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("note = 'gamma0 from \"the library\"'"), std::string::npos) << text;
  EXPECT_NE(text.find("c0 = 3900.123456789  # m/s"), std::string::npos) << text;
}

TEST(MaterialFile, BadFilesNameFileAndKey) {
  const auto file = shockfield::testing::scratch_path("material_file_bad.toml");
  const auto refused = [&](const std::string& text, const std::string& expected) {
    std::ofstream(file) << text;
    try {
      MaterialFile::load(file);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
  };
  refused("[eos]\nc0 = 0.0\n", "key 'eos.c0': expected a number > 0");
  refused("[eos]\nc0 = inf\n", "key 'eos.c0'");
  refused("[eos]\nc0 = \"fast\"\n", "key 'eos.c0'");
  refused("[eos]\nmodel = \"tillotson\"\n", "key 'eos.model'");
  refused("[elastic]\nc11 = 1e11\n", "unknown key 'elastic'");
  refused("provenance = 3\n", "expected a table [provenance]");
  refused("[eos]\nc0 = \n", "TOML syntax error");
}

// A material file's value used as a case default is checked against the case key's range, which
// may be narrower than the file's own (PD's yield_stress must be > 0, strength.yield_stress may
// be 0): refused naming the material file, its key, the case key and the range (issue 14).
TEST(MaterialFile, FileDefaultOutsideTheCaseKeysRangeIsRefused) {
  const auto file = shockfield::testing::scratch_path("material_file_range.toml");
  std::ofstream(file) << "[eos]\nrho0 = 8930.0\n[strength]\nyield_stress = 0.0\n";
  const MaterialFile m = MaterialFile::load(file);
  const Config root = Config::parse("[material]\nmodel = \"j2\"\n", "case.toml");
  const Config t = root.table("material");
  EXPECT_EQ(case_or_file(t, "density", &m, {"eos.rho0"}, {}, Range::positive(), "test"), 8930.0);
  try {
    case_or_file(t, "yield_stress", &m, {"strength.yield_stress"}, {}, Range::positive(), "test");
    ADD_FAILURE() << "a yield stress of 0 accepted for a key that must be > 0";
  } catch (const InputError& e) {
    const std::string what = e.what();
    for (const std::string& part : {file.string(), std::string("key 'strength.yield_stress' = 0"),
                                    std::string("material.yield_stress"), std::string("expected > 0"),
                                    std::string("case.toml")})
      EXPECT_NE(what.find(part), std::string::npos) << part << " not in: " << what;
  }
  // The macroparticle path (a scaled value, [atoms] in J against the case's eV) shares the check.
  EXPECT_THROW(file_default(t, "rho", m, "eos.rho0", 8930.0, Range::closed(1.0, 10.0), 1e4), InputError);  // 0.893
  EXPECT_DOUBLE_EQ(file_default(t, "rho", m, "eos.rho0", 8930.0, Range::closed(1.0, 10.0), 1e3), 8.93);
}

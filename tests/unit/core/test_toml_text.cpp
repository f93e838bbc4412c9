// TOML text with shortest floats (comments, strings, keys and headers untouched) (core/toml_text): toml++ as packaged prints 17 significant
// digits; every float of config.resolved.toml must read back to the same double in the fewest digits.
#include <gtest/gtest.h>

#include <sstream>

#include "shockfield/core/toml_text.hpp"

namespace shockfield {
namespace {

TEST(TomlText, FloatsAreShortestOutsideStringsKeysAndHeaders) {
  const std::string printed =
      "# --set it's = 0.33000000000000002\n"
      "a = 0.33000000000000002 # 0.33000000000000002\n"
      "b = [ 1.0000000000000001e-05, 2, -0.29999999999999999 ]\n"
      "s = \"x = 0.33000000000000002\"\n"
      "q = 'y = [0.10000000000000001'\n"
      "e = \"\\\" 0.20000000000000001\"\n"
      "[t.u2]\n"
      "c = 70000000000.0\n"
      "n = 3\n"
      "d = 1979-05-27\n"
      "v = { w = 0.69999999999999996, z = 1.5 }\n";
  const std::string expected =
      "# --set it's = 0.33000000000000002\n"
      "a = 0.33 # 0.33000000000000002\n"
      "b = [ 1e-05, 2, -0.3 ]\n"
      "s = \"x = 0.33000000000000002\"\n"
      "q = 'y = [0.10000000000000001'\n"
      "e = \"\\\" 0.20000000000000001\"\n"
      "[t.u2]\n"
      "c = 7e+10\n"
      "n = 3\n"
      "d = 1979-05-27\n"
      "v = { w = 0.7, z = 1.5 }\n";
  EXPECT_EQ(shortest_floats(printed), expected);
}

TEST(TomlText, EveryValueReadsBackToTheSameDoubleAndStaysAFloat) {
  toml::table t;
  const double values[] = {0.1 + 0.2, 0.33, 1.0 / 3.0, 2.0, 1e300, 5e-324, -7.25e-12, 70000000000.0};
  toml::array a;
  for (double v : values) a.push_back(v);
  t.insert("values", a);
  std::ostringstream out;
  out << t;
  const std::string text = shortest_floats(out.str());
  EXPECT_LT(text.size(), out.str().size());
  const toml::table back = toml::parse(text);
  const toml::array& got = *back["values"].as_array();
  ASSERT_EQ(got.size(), std::size(values));
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_TRUE(got[i].is_floating_point()) << text;  // 2.0 stays "2.0", not the integer 2
    EXPECT_EQ(got[i].value<double>().value(), values[i]) << text;
  }
  EXPECT_NE(text.find("0.30000000000000004"), std::string::npos) << text;  // noise of the value, kept
  EXPECT_EQ(toml_text(*t["values"][3].node()), "2.0");
}

}  // namespace
}  // namespace shockfield

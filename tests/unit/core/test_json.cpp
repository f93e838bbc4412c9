// The JSON writer: exact text for nested values (key order kept, indentation), RFC 8259 string
// escapes, non-finite doubles as null, doubles that read back to the same value.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "shockfield/core/json.hpp"

using namespace shockfield;

TEST(Json, NestedValuesKeepInsertionOrderAndIndent) {
  Json j;
  j.set("method", "md").set("steps", 1200).set("time", 2.5);
  j.set("results", Json::Object{{"ok", true}, {"none", nullptr}});
  j.set("rates", Json::Array{1, 2.0, Json::array(), Json::object()});
  j.set("method", "mpm");  // replaced in place, not moved to the end
  EXPECT_EQ(to_json_text(j),
            "{\n"
            "  \"method\": \"mpm\",\n"
            "  \"steps\": 1200,\n"
            "  \"time\": 2.5,\n"
            "  \"results\": {\n"
            "    \"ok\": true,\n"
            "    \"none\": null\n"
            "  },\n"
            "  \"rates\": [\n"
            "    1,\n"
            "    2.0,\n"
            "    [],\n"
            "    {}\n"
            "  ]\n"
            "}\n");
  EXPECT_EQ(to_json_text(j, 0),
            R"({"method": "mpm", "steps": 1200, "time": 2.5, "results": {"ok": true, "none": null}, )"
            R"("rates": [1, 2.0, [], {}]})");
  ASSERT_NE(j.find("steps"), nullptr);
  EXPECT_EQ(std::get<long long>(j.find("steps")->value), 1200);
  EXPECT_EQ(j.find("absent"), nullptr);
}

TEST(Json, StringsAreEscapedPerRfc8259) {
  const std::string s = std::string("quote\" back\\ nl\n tab\t cr\r bs\b ff\f nul") + '\0' +
                        "\x1f end é";
  EXPECT_EQ(to_json_text(Json(s), 0),
            "\"quote\\\" back\\\\ nl\\n tab\\t cr\\r bs\\b ff\\f nul\\u0000\\u001f end é\"");
  EXPECT_EQ(to_json_text(Json("/"), 0), "\"/\"");  // solidus may stay unescaped
}

TEST(Json, NonFiniteDoublesAreNullAndFiniteOnesReadBack) {
  EXPECT_EQ(to_json_text(Json(std::nan("")), 0), "null");
  EXPECT_EQ(to_json_text(Json(std::numeric_limits<double>::infinity()), 0), "null");
  EXPECT_EQ(to_json_text(Json(-std::numeric_limits<double>::infinity()), 0), "null");
  EXPECT_EQ(to_json_text(Json(0.1), 0), "0.1");
  EXPECT_EQ(to_json_text(Json(-3.0), 0), "-3.0");
  EXPECT_EQ(to_json_text(Json(1e300), 0), "1e+300");
  EXPECT_EQ(to_json_text(Json(6.02214076e23), 0), "6.02214076e+23");
  const double third = 1.0 / 3.0;  // shortest round-trip form: 17 significant digits here
  EXPECT_EQ(std::stod(to_json_text(Json(third), 0)), third);
  EXPECT_EQ(to_json_text(Json(static_cast<std::size_t>(7)), 0), "7");
  EXPECT_EQ(to_json_text(Json(-5LL), 0), "-5");
}

TEST(Json, SetAndPushRefuseTheWrongKind) {
  Json number(1.0);
  EXPECT_THROW(number.set("a", 1), std::logic_error);
  EXPECT_THROW(number.push(1), std::logic_error);
  Json list;
  list.push(1).push("two");
  EXPECT_EQ(to_json_text(list, 0), R"([1, "two"])");
}

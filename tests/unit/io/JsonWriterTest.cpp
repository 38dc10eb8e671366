#include "MpiTestUtils.hpp"
#include "TestMeshes.hpp"

#include "core/io/JsonWriter.hpp"

#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <sstream>

namespace contactlab {
namespace {

TEST(JsonWriter, ScalarsAndSpecialNumbers) {
  EXPECT_EQ(JsonValue().dump(), "null");
  EXPECT_EQ(JsonValue(nullptr).dump(), "null");
  EXPECT_EQ(JsonValue(true).dump(), "true");
  EXPECT_EQ(JsonValue(false).dump(), "false");
  EXPECT_EQ(JsonValue(42).dump(), "42");
  EXPECT_EQ(JsonValue(std::int64_t{9007199254740993}).dump(), "9007199254740993");
  EXPECT_EQ(JsonValue(std::size_t{7}).dump(), "7");
  EXPECT_EQ(JsonValue(0.1).dump(), "0.10000000000000001");
  EXPECT_EQ(JsonValue(2.0).dump(), "2");
  EXPECT_EQ(JsonValue(-1.5e-300).dump(), "-1.5000000000000001e-300");
  EXPECT_EQ(JsonValue(std::numeric_limits<double>::quiet_NaN()).dump(), "null");
  EXPECT_EQ(JsonValue(std::numeric_limits<double>::infinity()).dump(), "null");
  EXPECT_EQ(JsonValue(-std::numeric_limits<double>::infinity()).dump(), "null");
  const double third = 1.0 / 3.0;
  EXPECT_EQ(std::strtod(JsonValue(third).dump().c_str(), nullptr), third);
}

TEST(JsonWriter, EscapesStrings) {
  EXPECT_EQ(JsonValue("a\"b\\c\n\t\r\b\f").dump(), R"("a\"b\\c\n\t\r\b\f")");
  EXPECT_EQ(JsonValue(std::string("x\x01y\x1f", 4)).dump(), R"("x\u0001y\u001f")");
  EXPECT_EQ(JsonValue("µm /").dump(), "\"µm /\"");
  JsonValue o = JsonValue::object();
  o.set("key \"q\"", 1);
  EXPECT_EQ(o.dump(-1), R"({"key \"q\"":1})");
}

TEST(JsonWriter, KeepsInsertionOrderAndReplacesInPlace) {
  JsonValue o;
  o.set("zeta", 1).set("alpha", 2).set("mid", 3);
  o.set("alpha", "two");
  EXPECT_EQ(o.dump(-1), R"({"zeta":1,"alpha":"two","mid":3})");
  EXPECT_EQ(o.size(), 3u);
}

TEST(JsonWriter, NestedPrettyPrint) {
  JsonValue summary = JsonValue::object();
  summary.set("scene", "hertz");
  summary.set("converged", true);
  summary.set("failure", nullptr);
  summary["solver"].set("name", "mumps").set("tolerance", 1e-10);
  summary.set("iterations", JsonValue::array(std::vector<int>{3, 4}));
  summary.set("empty_list", JsonValue::array());
  summary.set("empty_object", JsonValue::object());
  JsonValue probes;
  probes.push(JsonValue::object().set("name", "tip").set("u", -0.5));
  summary.set("probes", probes);
  EXPECT_EQ(summary.dump(),
            "{\n"
            "  \"scene\": \"hertz\",\n"
            "  \"converged\": true,\n"
            "  \"failure\": null,\n"
            "  \"solver\": {\n"
            "    \"name\": \"mumps\",\n"
            "    \"tolerance\": 1e-10\n"
            "  },\n"
            "  \"iterations\": [\n"
            "    3,\n"
            "    4\n"
            "  ],\n"
            "  \"empty_list\": [],\n"
            "  \"empty_object\": {},\n"
            "  \"probes\": [\n"
            "    {\n"
            "      \"name\": \"tip\",\n"
            "      \"u\": -0.5\n"
            "    }\n"
            "  ]\n"
            "}");
  EXPECT_EQ(summary["solver"].dump(-1), R"({"name":"mumps","tolerance":1e-10})");
}

TEST(JsonWriter, MisuseIsALogicError) {
  JsonValue number(1.0);
  EXPECT_THROW(number.push(1), std::logic_error);
  EXPECT_THROW(number.set("a", 1), std::logic_error);
  JsonValue list = JsonValue::array();
  EXPECT_THROW(list["a"], std::logic_error);
}

TEST(JsonWriter, WritesFile) {
  const std::string path = test::testOutputDir("json", test::commSize()) + "/rank" +
                           std::to_string(test::commRank()) + "/summary.json";
  JsonValue::object().set("converged", false).write(path);
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_EQ(s.str(), "{\n  \"converged\": false\n}\n");
}

}  // namespace
}  // namespace contactlab

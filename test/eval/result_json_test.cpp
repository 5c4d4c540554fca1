#include "result_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace doorplate_localization {
namespace {

TEST(ResultJsonText, KeepsTheMembersInOrderWithTwoSpaceIndentationAndAFinalNewline) {
  Json json;
  json["name"] = "ward";
  json["passes"] = 3;
  json["ok"] = true;
  json["list"] = {1.5, -2, nullptr};
  json["empty"] = Json::object();
  EXPECT_EQ(ResultJsonText(json),
            "{\n  \"name\": \"ward\",\n  \"passes\": 3,\n  \"ok\": true,\n  \"list\": [\n    1.5,\n    -2,\n    null\n"
            "  ],\n  \"empty\": {}\n}\n");
}

TEST(ResultJsonText, WritesNumbersToTenSignificantDigitsAndWholeOnesWithoutAFraction) {
  const Json json = {1.0 / 3.0, 6.0, -0.5, 2.5e-12, 1e20, std::uint64_t{18446744073709551615u}};
  EXPECT_EQ(ResultJsonText(json),
            "[\n  0.3333333333,\n  6,\n  -0.5,\n  2.5e-12,\n  1e+20,\n  18446744073709551615\n]\n");
}

TEST(ResultJsonText, WritesNonFiniteNumbersAsNullAtAnyDepth) {
  Json json;
  json["trial"] = {{"error_m", std::numeric_limits<double>::infinity()}, {"travel_m", std::nan("")}};
  EXPECT_EQ(ResultJsonText(json), "{\n  \"trial\": {\n    \"error_m\": null,\n    \"travel_m\": null\n  }\n}\n");
}

TEST(ResultJsonText, EscapesControlCharactersKeepsUtf8AndReplacesBrokenUtf8) {
  EXPECT_EQ(ResultJsonText("a\"b\\c\nd\x01"), "\"a\\\"b\\\\c\\nd\\u0001\"\n");
  EXPECT_EQ(ResultJsonText("Zimmer 2\xC3\xBC"), "\"Zimmer 2\xC3\xBC\"\n");
  EXPECT_EQ(ResultJsonText("E1\xC3"), "\"E1\xEF\xBF\xBD\"\n");  // a reading cut inside a character: U+FFFD
}

TEST(ResultJsonLine, WritesTheSameRoundedValuesOnOneLine) {
  Json json;
  json["noise_m"] = 1.0 / 3.0;
  json["n"] = 4.0;
  json["ci95"] = {std::nan(""), 0.5};
  EXPECT_EQ(ResultJsonLine(json), "{\"noise_m\":0.3333333333,\"n\":4,\"ci95\":[null,0.5]}");
}

}  // namespace
}  // namespace doorplate_localization

#include "json_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace doorplate_localization {
namespace {

TEST(JsonWriter, WritesNestedObjectsAndArraysWithIndentation) {
  std::ostringstream out;
  JsonWriter json(&out);
  json.BeginObject().Field("name", "ward").Field("passes", 3).Field("ok", true);
  json.Key("list").BeginArray().Value(1.5).Value(std::int64_t{-2}).Null().EndArray();
  json.Key("empty").BeginObject().EndObject();
  json.EndObject();
  EXPECT_TRUE(json.complete());
  EXPECT_EQ(out.str(),
            "{\n  \"name\": \"ward\",\n  \"passes\": 3,\n  \"ok\": true,\n  \"list\": [\n    1.5,\n    -2,\n    null\n"
            "  ],\n  \"empty\": {}\n}\n");
}

TEST(JsonWriter, EscapesQuotesBackslashesAndControlCharacters) {
  EXPECT_EQ(JsonWriter::Quote("a\"b\\c\nd\x01"), "\"a\\\"b\\\\c\\nd\\u0001\"");
  EXPECT_EQ(JsonWriter::Quote("Zimmer 2\xC3\xBC"), "\"Zimmer 2\xC3\xBC\"");  // UTF-8 passes through
}

TEST(JsonWriter, WritesNonFiniteNumbersAsNull) {
  std::ostringstream out;
  JsonWriter json(&out);
  json.BeginArray().Value(std::numeric_limits<double>::infinity()).Value(std::nan("")).Value(0.1).EndArray();
  EXPECT_EQ(out.str(), "[\n  null,\n  null,\n  0.1\n]\n");
}

TEST(JsonWriter, RejectsValuesWithoutKeysAndUnbalancedEnds) {
  std::ostringstream out;
  JsonWriter json(&out);
  json.BeginObject();
  EXPECT_THROW(json.Value(1), std::logic_error);
  EXPECT_THROW(json.EndArray(), std::logic_error);
  json.Key("a");
  EXPECT_THROW(json.Key("b"), std::logic_error);
  EXPECT_THROW(json.EndObject(), std::logic_error);  // dangling key
  json.Value(1).EndObject();
  EXPECT_TRUE(json.complete());
  EXPECT_THROW(json.BeginObject(), std::logic_error);  // a second document
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/common/yaml_reader.h"

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const YamlFieldError& e) {
    return e.what();
  }
  return "";
}

TEST(YamlField, SyntaxErrorsNameTheSourceAndLine) {
  const std::string error = ErrorOf([] { YamlField::Parse("a: 1\nb: [1, 2\n", "f.yaml"); });
  EXPECT_NE(error.find("f.yaml: line"), std::string::npos) << error;
}

TEST(YamlField, MissingFieldsAreNamedWithTheirPath) {
  const YamlField root = YamlField::Parse("robot: {start: {x_m: 1}}", "w.yaml");
  const std::string error = ErrorOf([&] { root.Child("robot").Child("start").Child("y_m"); });
  EXPECT_EQ(error, "w.yaml: robot.start.y_m: required field is missing");
}

TEST(YamlField, UnknownKeysAreRejectedSoTyposNeverPassSilently) {
  const YamlField root = YamlField::Parse("widht_m: 2", "w.yaml");
  const std::string error = ErrorOf([&] { root.RequireOnlyKeys({"width_m"}); });
  EXPECT_NE(error.find("unknown field 'widht_m'"), std::string::npos) << error;
}

TEST(YamlField, NumbersAreCheckedForTypeAndRange) {
  const YamlField root = YamlField::Parse("a: abc\nb: -1\nc: [1, 2]\nd: .nan", "w.yaml");
  EXPECT_NE(ErrorOf([&] { root.Child("a").AsDouble(); }).find("a: must be a number"), std::string::npos);
  EXPECT_NE(ErrorOf([&] { root.Positive("b", 1.0); }).find("b: must be > 0"), std::string::npos);
  EXPECT_NE(ErrorOf([&] { root.Child("c").AsDoubles(3); }).find("list of 3 numbers"), std::string::npos);
  EXPECT_NE(ErrorOf([&] { root.Child("d").AsDouble(); }).find("finite"), std::string::npos);
  EXPECT_DOUBLE_EQ(root.Positive("absent", 4.0), 4.0);
}

TEST(YamlField, ListItemsCarryTheirIndexInErrors) {
  const YamlField root = YamlField::Parse("walls: [{id: a}, {id: [1]}]", "w.yaml");
  const auto items = root.Child("walls").Items();
  EXPECT_EQ(ErrorOf([&] { items[1].Child("id").AsString(); }), "w.yaml: walls[1].id: must be a string");
}

TEST(YamlField, ColoursMustBeIntegerTriplets) {
  const YamlField root = YamlField::Parse("good: [1, 2, 255]\nbad: [1, 2, 300]", "w.yaml");
  std::array<unsigned char, 3> rgb{};
  root.GetColor("good", &rgb);
  EXPECT_EQ(rgb[2], 255);
  EXPECT_NE(ErrorOf([&] { root.GetColor("bad", &rgb); }).find("0..255"), std::string::npos);
}

// Found by fuzz/world_loader_fuzz (corpus: fuzz/corpus/world_loader/regression_list_as_key.yaml): a list used
// as a key (`{id: a, from, [1, 2]}`) used to escape as yaml-cpp's BadConversion instead of a field error.
TEST(YamlField, ListOrMappingKeysAreRejectedAsFieldErrors) {
  const YamlField root = YamlField::Parse("walls: [{id: a, from, [1, 2]: 3}]\n{x: 1}: 2", "w.yaml");
  const auto items = root.Child("walls").Items();
  EXPECT_NE(ErrorOf([&] { items[0].RequireOnlyKeys({"id", "from"}); }).find("w.yaml: walls[0]: field names"),
            std::string::npos);
  EXPECT_NE(ErrorOf([&] { root.RequireOnlyKeys({"walls"}); }).find("w.yaml: (top level): field names"),
            std::string::npos);
}

}  // namespace
}  // namespace doorplate_localization

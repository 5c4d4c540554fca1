#include "doorplate_localization/text/character_grouping.h"

#include <stdexcept>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

CharacterCandidate Dark(int x, int y, int w = 12, int h = 22, double ink = 30.0) {
  return CharacterCandidate{cv::Rect(x, y, w, h), ink, true};
}

TEST(GroupCharactersIntoLines, GroupsThreeDigitsIntoOneLineBox) {
  const auto lines = GroupCharactersIntoLines({Dark(100, 50), Dark(116, 51), Dark(132, 50)}, {});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].box_px, cv::Rect(100, 50, 44, 23));
  EXPECT_EQ(lines[0].num_chars, 3);
}

TEST(GroupCharactersIntoLines, KeepsLinesAtDifferentHeightsApart) {
  const auto lines = GroupCharactersIntoLines(
      {Dark(100, 50), Dark(116, 50), Dark(100, 120), Dark(116, 120), Dark(132, 120)}, {});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].num_chars + lines[1].num_chars, 5);
}

TEST(GroupCharactersIntoLines, DropsHolesNestedInsideGlyphs) {
  // The inside of a "0" is a bright MSER region inside the dark glyph's box.
  const auto lines = GroupCharactersIntoLines(
      {Dark(100, 50), Dark(116, 50), CharacterCandidate{cv::Rect(119, 55, 6, 12), 240.0, false}}, {});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].num_chars, 2);
}

TEST(GroupCharactersIntoLines, NeverLinksDarkAndBrightGlyphs) {
  const auto lines = GroupCharactersIntoLines(
      {Dark(100, 50), CharacterCandidate{cv::Rect(116, 50, 12, 22), 35.0, false}}, {});
  EXPECT_TRUE(lines.empty());
}

TEST(GroupCharactersIntoLines, DropsASingleCharacterAndSplitsAtWideGaps) {
  const auto lines = GroupCharactersIntoLines({Dark(100, 50), Dark(116, 50), Dark(300, 50)}, {});
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].box_px.x, 100);
  EXPECT_EQ(lines[0].num_chars, 2);
}

TEST(GroupCharactersIntoLines, DoesNotLinkGlyphsOfVeryDifferentHeight) {
  EXPECT_TRUE(GroupCharactersIntoLines({Dark(100, 50), Dark(116, 40, 20, 44)}, {}).empty());
}

TEST(GroupCharactersIntoLines, RejectsOptionsOutOfRangeNamingTheField) {
  LineGroupingOptions options;
  options.max_height_ratio = 0.5;
  try {
    GroupCharactersIntoLines({}, options);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_height_ratio"), std::string::npos);
  }
}

}  // namespace
}  // namespace doorplate_localization

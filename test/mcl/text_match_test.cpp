#include "doorplate_localization/mcl/text_match.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace doorplate_localization {
namespace {

TEST(TextMatcher, IdenticalTextsMatchWithTheReadersConfidence) {
  const TextMatcher m({});
  EXPECT_DOUBLE_EQ(m.Similarity("214", "214"), 1.0);
  EXPECT_DOUBLE_EQ(m.Similarity("b-12", "B12"), 1.0);  // canonical forms
  EXPECT_DOUBLE_EQ(m.MatchProbability("214", 0.9, "214"), 0.9);
}

TEST(TextMatcher, ConfusedDigitsCostTheConfusionProbabilityEach) {
  const TextMatcher m({});  // 0.3 per confused character
  EXPECT_DOUBLE_EQ(m.Similarity("107", "101"), 0.3);   // 7 read for 1
  EXPECT_DOUBLE_EQ(m.Similarity("101", "107"), 0.3);   // symmetric
  EXPECT_DOUBLE_EQ(m.Similarity("138", "133"), 0.3);   // 8 for 3
  EXPECT_DOUBLE_EQ(m.Similarity("177", "111"), 0.09);  // two
  EXPECT_NEAR(m.MatchProbability("107", 0.9, "101"), 0.1 * 0.3, 1e-12);
}

TEST(TextMatcher, OneOtherEditIsUnlikelyAndTwoAreIncompatible) {
  const TextMatcher m({});  // 0.05 for one other edit
  EXPECT_DOUBLE_EQ(m.Similarity("219", "214"), 0.05);   // 9 for 4: not a listed confusion
  EXPECT_DOUBLE_EQ(m.Similarity("2145", "214"), 0.05);  // an extra character
  EXPECT_DOUBLE_EQ(m.Similarity("14", "214"), 0.05);    // a dropped one
  EXPECT_DOUBLE_EQ(m.Similarity("21", "214"), 0.05);
  EXPECT_DOUBLE_EQ(m.Similarity("299", "214"), 0.0);    // two other substitutions
  EXPECT_DOUBLE_EQ(m.Similarity("2", "214"), 0.0);      // two characters dropped
  EXPECT_NEAR(m.Similarity("777", "111"), 0.3 * 0.3 * 0.05, 1e-12);  // third confusion counts as the other edit
  EXPECT_NEAR(m.Similarity("1077", "101"), 0.05 * 0.3, 1e-12);       // extra 7 plus 7-for-1
}

TEST(TextMatcher, ConfusablePairsAreConfigurable) {
  TextMatchOptions o;
  o.confusable_pairs = "b8";  // letters compare upper-cased
  const TextMatcher m(o);
  EXPECT_DOUBLE_EQ(m.Similarity("B12", "812"), 0.3);
  EXPECT_DOUBLE_EQ(m.Similarity("107", "101"), 0.05);  // 1/7 is no longer listed: an ordinary edit
}

TEST(TextMatcher, CompatibleListsEveryPlateThatCouldHaveProducedTheReading) {
  TextMap map;
  for (const char* t : {"105", "106", "105", "305", "999"}) {
    TextLandmark l;
    l.text = t;
    map.landmarks.push_back(l);
  }
  const TextMatcher m({});
  const auto matches = m.Compatible(map, "105", 0.8);
  ASSERT_EQ(matches.size(), 4u);  // both 105s, 106 (5/6 confusion), 305 (one other edit); not 999
  EXPECT_EQ(matches[0].landmark_index, 0);
  EXPECT_DOUBLE_EQ(matches[0].probability, 0.8);
  EXPECT_EQ(matches[1].landmark_index, 1);
  EXPECT_NEAR(matches[1].probability, 0.2 * 0.3, 1e-12);
  EXPECT_EQ(matches[2].landmark_index, 2);
  EXPECT_EQ(matches[3].landmark_index, 3);
  EXPECT_NEAR(matches[3].probability, 0.2 * 0.05, 1e-12);
}

TEST(TextMatcher, SeparatorsDoNotCountInRealBuildingFormats) {
  const TextMatcher m({});
  EXPECT_DOUBLE_EQ(m.Similarity("E14295", "E14-295"), 1.0);
  EXPECT_DOUBLE_EQ(m.Similarity("B1404", "B/1404"), 1.0);
  EXPECT_DOUBLE_EQ(m.Similarity("3:21", "3.21"), 1.0);                // OCR read the dot as a colon
  EXPECT_DOUBLE_EQ(m.Similarity("76100SC", "76\xC2\xB7" "100SC"), 1.0);  // raised dot
  EXPECT_DOUBLE_EQ(m.MatchProbability("21 52", 0.9, "21/52"), 0.9);
  EXPECT_DOUBLE_EQ(m.Similarity("E14-795", "E14-295"), 0.05);  // the separator is no edit; 7-for-2 is one
}

TEST(TextMatcher, LookAlikesStayApart) {
  const TextMatcher m({});
  EXPECT_DOUBLE_EQ(m.Similarity("312A", "312B"), 0.05);      // one other substitution, not the same room
  EXPECT_NEAR(m.MatchProbability("312A", 0.9, "312B"), 0.1 * 0.05, 1e-12);
  EXPECT_DOUBLE_EQ(m.Similarity("32-076", "32-069T"), 0.0);  // three edits
  EXPECT_DOUBLE_EQ(m.Similarity("-", "-"), 0.0);             // separators alone name no room
  EXPECT_DOUBLE_EQ(m.MatchProbability("", 0.9, ""), 0.0);
}

TEST(TextMatcher, CompatibleFindsAPlateWhateverSeparatorsWereRead) {
  TextMap map;
  for (const char* t : {"E14-295", "32-069T", "32-076", "312A", "312B"}) {
    TextLandmark l;
    l.text = t;
    map.landmarks.push_back(l);
  }
  const TextMatcher m({});
  const auto e14 = m.Compatible(map, "e14 295", 0.8);
  ASSERT_EQ(e14.size(), 1u);
  EXPECT_EQ(e14[0].landmark_index, 0);
  EXPECT_DOUBLE_EQ(e14[0].probability, 0.8);
  const auto t = m.Compatible(map, "32069T", 0.8);
  ASSERT_EQ(t.size(), 1u);  // 32-076 is three edits away
  EXPECT_EQ(t[0].landmark_index, 1);
  EXPECT_DOUBLE_EQ(t[0].probability, 0.8);
  const auto a = m.Compatible(map, "312A", 0.8);
  ASSERT_EQ(a.size(), 2u);  // 312A itself, and 312B only as a misreading
  EXPECT_EQ(a[0].landmark_index, 3);
  EXPECT_DOUBLE_EQ(a[0].probability, 0.8);
  EXPECT_EQ(a[1].landmark_index, 4);
  EXPECT_NEAR(a[1].probability, 0.2 * 0.05, 1e-12);
}

TEST(TextMatcher, RejectsBadProbabilitiesAndMalformedPairs) {
  TextMatchOptions o;
  o.other_edit_probability = 1.5;
  EXPECT_THROW(TextMatcher{o}, std::invalid_argument);
  o = TextMatchOptions();
  o.confusable_pairs = "17 4";
  try {
    TextMatcher m(o);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("confusable_pairs"), std::string::npos);
  }
}

}  // namespace
}  // namespace doorplate_localization

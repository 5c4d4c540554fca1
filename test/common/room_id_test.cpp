#include "doorplate_localization/common/room_id.h"

#include <stdexcept>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

TEST(CanonicalRoomId, UppercasesAndRemovesThePrintedSeparators) {
  EXPECT_EQ(CanonicalRoomId("e14-295"), "E14295");
  EXPECT_EQ(CanonicalRoomId("B/1404"), "B1404");
  EXPECT_EQ(CanonicalRoomId("39.A"), "39A");
  EXPECT_EQ(CanonicalRoomId("76\xC2\xB7" "100SC"), "76100SC");  // raised dot
  EXPECT_EQ(CanonicalRoomId(" 21 / 52\n"), "2152");
  EXPECT_EQ(CanonicalRoomId("E14\xC2\xA0" "295"), "E14295");    // no-break space
}

TEST(CanonicalRoomId, RemovesTheOcrVariantsOfDotsAndHyphens) {
  EXPECT_EQ(CanonicalRoomId("3:21"), "321");
  EXPECT_EQ(CanonicalRoomId("3,21"), "321");
  EXPECT_EQ(CanonicalRoomId("16\xE2\x80\x93" "186"), "16186");  // en dash
  EXPECT_EQ(CanonicalRoomId("16\xE2\x80\x94" "186"), "16186");  // em dash
  EXPECT_EQ(CanonicalRoomId("16\xE2\x88\x92" "186"), "16186");  // minus sign
  EXPECT_EQ(CanonicalRoomId("76\xE2\x80\xA2" "100"), "76100");  // bullet
}

TEST(CanonicalRoomId, KeepsOtherCharactersSoAGrammarCanRefuseThem) {
  EXPECT_EQ(CanonicalRoomId("21#4"), "21#4");
  EXPECT_EQ(CanonicalRoomId("\xC3\xA9" "12"), "\xC3\xA9" "12");  // é stays, not upper-cased
  EXPECT_EQ(CanonicalRoomId(" - . / "), "");
}

TEST(SameRoom, E14Dash295AndE14295AreTheSameRoom) {
  EXPECT_TRUE(SameRoom("E14-295", "E14295"));
  EXPECT_TRUE(SameRoom("e14 295", "E14-295"));
  EXPECT_TRUE(SameRoom("B/1404", "b1404"));
  EXPECT_TRUE(SameRoom("3.21", "3:21"));
}

TEST(SameRoom, LookAlikesStayApart) {
  EXPECT_FALSE(SameRoom("312A", "312B"));
  EXPECT_FALSE(SameRoom("32-076", "32-069T"));
  EXPECT_FALSE(SameRoom("32-069", "32-069T"));
  EXPECT_FALSE(SameRoom("5", "5D"));
}

TEST(SameRoom, TextsWithoutCharactersBesidesSeparatorsNameNoRoom) {
  EXPECT_FALSE(SameRoom("", ""));
  EXPECT_FALSE(SameRoom("-", "."));
}

TEST(RoomIdGrammar, TheDefaultAcceptsTheFormatsOfRealBuildings) {
  const RoomIdGrammar grammar;
  for (const char* room : {"16-186", "E14-295", "32-069T", "B/1404", "39.A", "3.21", "B2.114",
                           "76\xC2\xB7" "100SC", "21/52", "5", "5D", "20", "2B", "102A", "3103B", "214"}) {
    EXPECT_TRUE(grammar.Accepts(room)) << room;
  }
}

TEST(RoomIdGrammar, TheDefaultRefusesWordsWithoutDigits) {
  const RoomIdGrammar grammar;
  for (const char* word : {"EXIT", "WC", "lobby", "A", "", "-"}) {
    EXPECT_FALSE(grammar.Accepts(word)) << word;
  }
}

TEST(RoomIdGrammar, TheDefaultRefusesLettersBetweenDigitsAndForeignCharacters) {
  const RoomIdGrammar grammar;
  for (const char* junk : {"2l4", "21#4", "1234567", "ABC123", "123ABC", "\xC3\xA9" "12"}) {
    EXPECT_FALSE(grammar.Accepts(junk)) << junk;
  }
}

TEST(RoomIdGrammar, TheDefaultRefusesALetterBeforeASingleDigitAsAFragmentOfOtherText) {
  const RoomIdGrammar grammar;
  for (const char* junk : {"N5", "NO5PI", "A1", "B2C"}) {
    EXPECT_FALSE(grammar.Accepts(junk)) << junk;
  }
}

TEST(RoomIdGrammar, ABuildingPatternReplacesTheDefault) {
  const RoomIdGrammar grammar("[0-9]{3}|WC");
  EXPECT_TRUE(grammar.Accepts("214"));
  EXPECT_TRUE(grammar.Accepts("wc"));
  EXPECT_FALSE(grammar.Accepts("5"));
  EXPECT_FALSE(grammar.Accepts("E14-295"));
  EXPECT_EQ(grammar.pattern(), "[0-9]{3}|WC");
}

TEST(RoomIdGrammar, RefusesAnEmptyOrInvalidPattern) {
  EXPECT_THROW(RoomIdGrammar(""), std::invalid_argument);
  try {
    RoomIdGrammar bad("[0-9");
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("[0-9"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace doorplate_localization

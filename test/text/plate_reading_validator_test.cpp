#include "doorplate_localization/text/plate_reading_validator.h"

#include <stdexcept>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

PlateReadingValidator WithRooms(std::vector<std::string> rooms) {
  PlateReadingValidatorOptions options;
  options.known_rooms = std::move(rooms);
  return PlateReadingValidator(options);
}

TEST(EditDistance, CountsSubstitutionsInsertionsAndDeletions) {
  EXPECT_EQ(EditDistance("214", "214"), 0);
  EXPECT_EQ(EditDistance("214", "274"), 1);
  EXPECT_EQ(EditDistance("214", "2144"), 1);
  EXPECT_EQ(EditDistance("214", "24"), 1);
  EXPECT_EQ(EditDistance("214", "301"), 3);
  EXPECT_EQ(EditDistance("", "301"), 3);
}

TEST(PlateReadingValidator, KeepsReadingsMatchingThePatternAfterNormalization) {
  const PlateReadingValidator validator({});
  EXPECT_EQ(validator.Validate("214"), "214");
  EXPECT_EQ(validator.Validate("2140"), "2140");
  EXPECT_EQ(validator.Validate(" 21 4a\n"), "214A");
}

TEST(PlateReadingValidator, DropsGarbageWithoutAKnownList) {
  PlateReadingValidatorOptions three_or_four_digits;  // a building that only has 3-4 digit numbers
  three_or_four_digits.pattern = "[0-9]{3,4}[A-Z]?";
  const PlateReadingValidator validator(three_or_four_digits);
  for (const char* garbage : {"", "21", "21400", "2l4", "EXIT", "#$%", "A214"}) {
    EXPECT_EQ(validator.Validate(garbage), std::nullopt) << garbage;
  }
}

TEST(PlateReadingValidator, TheDefaultPatternKeepsRealBuildingFormatsAsPrinted) {
  const PlateReadingValidator validator({});
  EXPECT_EQ(validator.Validate("e14-295"), "E14-295");
  EXPECT_EQ(validator.Validate(" 16-186 "), "16-186");
  EXPECT_EQ(validator.Validate("32-069t"), "32-069T");
  EXPECT_EQ(validator.Validate("B/1404"), "B/1404");
  EXPECT_EQ(validator.Validate("39.A"), "39.A");
  EXPECT_EQ(validator.Validate("B2.114"), "B2.114");
  EXPECT_EQ(validator.Validate("76\xC2\xB7" "100sc"), "76\xC2\xB7" "100SC");
  EXPECT_EQ(validator.Validate("21/52"), "21/52");
  EXPECT_EQ(validator.Validate("5"), "5");
  EXPECT_EQ(validator.Validate("5d"), "5D");
  EXPECT_EQ(validator.Validate("3103B"), "3103B");
}

TEST(PlateReadingValidator, TheDefaultPatternDropsWordsAndLettersBetweenDigits) {
  const PlateReadingValidator validator({});
  for (const char* garbage : {"", "-", "EXIT", "WC", "2l4", "#$%", "1234567"}) {
    EXPECT_EQ(validator.Validate(garbage), std::nullopt) << garbage;
  }
}

TEST(PlateReadingValidator, AKnownRoomAcceptsItsNumberWithOrWithoutSeparators) {
  const PlateReadingValidator validator = WithRooms({"E14-295", "B/1404", "3.21"});
  EXPECT_EQ(validator.Validate("E14295"), "E14-295");
  EXPECT_EQ(validator.Validate("e14 - 295"), "E14-295");
  EXPECT_EQ(validator.Validate("E14:295"), "E14-295");  // OCR read the hyphen as a colon
  EXPECT_EQ(validator.Validate("B1404"), "B/1404");
  EXPECT_EQ(validator.Validate("3,21"), "3.21");
  EXPECT_EQ(validator.Validate("E14-795"), "E14-295");   // one confused digit, separators ignored
}

TEST(PlateReadingValidator, LookAlikeKnownRoomsStayApart) {
  const PlateReadingValidator validator = WithRooms({"312A", "312B", "32-076", "32-069T"});
  EXPECT_EQ(validator.Validate("312A"), "312A");
  EXPECT_EQ(validator.Validate("312B"), "312B");
  EXPECT_EQ(validator.Validate("312"), std::nullopt);     // one edit from both
  EXPECT_EQ(validator.Validate("32076"), "32-076");
  EXPECT_EQ(validator.Validate("32-069"), "32-069T");     // lost suffix: the only room one edit away
  EXPECT_EQ(validator.Validate("32-079T"), "32-069T");
}

TEST(PlateReadingValidator, KnownRoomsWrittenTwoWaysAreOneRoom) {
  const PlateReadingValidator validator = WithRooms({"E14-295", "E14295", "E14-296"});
  EXPECT_EQ(validator.Validate("E14-295"), "E14-295");
  EXPECT_EQ(validator.Validate("E14-29"), std::nullopt);  // 295 or 296: ambiguous, not 3 rooms
}

TEST(PlateReadingValidator, MapsSingleOcrConfusionsToTheUniqueKnownRoom) {
  const PlateReadingValidator validator = WithRooms({"214", "215", "301", "318"});
  EXPECT_EQ(validator.Validate("214"), "214");
  EXPECT_EQ(validator.Validate("274"), "214");   // 1 read as 7
  EXPECT_EQ(validator.Validate("2l4"), "214");   // 1 read as l
  EXPECT_EQ(validator.Validate("2144"), "214");  // doubled glyph
  EXPECT_EQ(validator.Validate("3O1"), "301");   // 0 read as O
  EXPECT_EQ(validator.Validate("313"), "318");   // 8 read as 3
}

TEST(PlateReadingValidator, DropsReadingsCloseToSeveralRoomsOrToNone) {
  const PlateReadingValidator validator = WithRooms({"214", "215", "301"});
  EXPECT_EQ(validator.Validate("21"), std::nullopt);   // 214 or 215
  EXPECT_EQ(validator.Validate("216"), std::nullopt);  // 214 or 215
  EXPECT_EQ(validator.Validate("999"), std::nullopt);
  EXPECT_EQ(validator.Validate("EXIT"), std::nullopt);
}

TEST(PlateReadingValidator, ExactDistanceZeroAllowsOnlyKnownRooms) {
  PlateReadingValidatorOptions options;
  options.known_rooms = {"214"};
  options.max_edit_distance = 0;
  const PlateReadingValidator validator(options);
  EXPECT_EQ(validator.Validate("214"), "214");
  EXPECT_EQ(validator.Validate("274"), std::nullopt);
}

TEST(PlateReadingValidator, RejectsBadOptionsNamingTheField) {
  PlateReadingValidatorOptions bad_regex;
  bad_regex.pattern = "[0-9";
  EXPECT_THROW(PlateReadingValidator{bad_regex}, std::invalid_argument);
  try {
    WithRooms({"214", "lobby"});
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("known_rooms"), std::string::npos) << e.what();
  }
  PlateReadingValidatorOptions negative;
  negative.max_edit_distance = -1;
  EXPECT_THROW(PlateReadingValidator{negative}, std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

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
  const PlateReadingValidator validator({});
  for (const char* garbage : {"", "21", "21400", "2l4", "EXIT", "#$%", "A214"}) {
    EXPECT_EQ(validator.Validate(garbage), std::nullopt) << garbage;
  }
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

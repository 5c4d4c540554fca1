#include "doorplate_localization/mcl/plate_reading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace doorplate_localization {
namespace {

PlateReading Good() {
  PlateReading r;
  r.text = "214";
  r.confidence = 0.8;
  r.bearing_rad = 1.5;
  r.range_m = 1.2;
  r.camera_side = CameraSide::kLeft;
  return r;
}

TEST(ValidatePlateReading, AcceptsAPlausibleReading) { EXPECT_EQ(ValidatePlateReading(Good()), ""); }

TEST(ValidatePlateReading, NamesTheBadField) {
  const auto error_of = [](auto mutate) {
    PlateReading r = Good();
    mutate(r);
    return ValidatePlateReading(r);
  };
  EXPECT_NE(error_of([](PlateReading& r) { r.text = " - "; }).find("PlateReading.text"), std::string::npos);
  EXPECT_NE(error_of([](PlateReading& r) { r.confidence = 1.5; }).find("PlateReading.confidence"), std::string::npos);
  EXPECT_NE(error_of([](PlateReading& r) { r.confidence = std::nan(""); }).find("confidence"), std::string::npos);
  EXPECT_NE(error_of([](PlateReading& r) { r.bearing_rad = INFINITY; }).find("bearing_rad"), std::string::npos);
  EXPECT_NE(error_of([](PlateReading& r) { r.range_m = -1.0; }).find("PlateReading.range_m"), std::string::npos);
  // A left camera cannot see a plate on the robot's right.
  EXPECT_NE(error_of([](PlateReading& r) { r.bearing_rad = -1.5; }).find("left camera"), std::string::npos);
  EXPECT_EQ(error_of([](PlateReading& r) { r.bearing_rad = -1.5, r.camera_side = CameraSide::kRight; }), "");
  EXPECT_EQ(error_of([](PlateReading& r) { r.range_m.reset(); }), "");
}

// Issue 18: a 1 MB text is refused by its length, before any matching, and the message never quotes it.
TEST(ValidatePlateReading, RefusesATextLongerThanTheLimitWithoutQuotingIt) {
  PlateReading r = Good();
  r.text.assign(1 << 20, '7');
  const std::string error = ValidatePlateReading(r);
  EXPECT_EQ(error, "PlateReading.text: 1048576 bytes, more than the limit of 64 (limits::kMaxPlateTextBytes)");
  r.text.assign(64, '7');  // at the limit: a (strange) text, but not refused for its length
  EXPECT_EQ(ValidatePlateReading(r), "");
}

TEST(CanonicalPlateText, UppercasesAndDropsSpacesAndDashes) {
  EXPECT_EQ(CanonicalPlateText(" b-12 "), "B12");
  EXPECT_EQ(CanonicalPlateText("214"), "214");
}

}  // namespace
}  // namespace doorplate_localization

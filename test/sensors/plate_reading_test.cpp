#include "doorplate_localization/sensors/plate_reading.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
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

TEST(PlateReadingFromCamera, ComposesTheBearingWrapsItAndLeavesRangeAndCameraSideUnknown) {
  const PlateReading left = PlateReadingFromCamera("214", 0.8, CameraAxis{M_PI / 2.0, 1.0}, 0.1);
  EXPECT_EQ(left.text, "214");
  EXPECT_EQ(left.confidence, 0.8);
  EXPECT_NEAR(left.bearing_rad, M_PI / 2.0 + 0.1, 1e-12);  // towards the image's left: further forward
  EXPECT_FALSE(left.range_m.has_value());
  EXPECT_EQ(left.camera_side, CameraSide::kUnknown);
  EXPECT_EQ(ValidatePlateReading(left), "");
  // Upside down: the image's left is the other way round; and the sum is wrapped into (-pi, pi].
  EXPECT_NEAR(PlateReadingFromCamera("214", 0.8, CameraAxis{M_PI / 2.0, -1.0}, 0.1).bearing_rad, M_PI / 2.0 - 0.1,
              1e-12);
  EXPECT_NEAR(BearingInBase(CameraAxis{M_PI - 0.05, 1.0}, 0.1), -M_PI + 0.05, 1e-12);
}

TEST(PlateReadingFromCamera, KeepsANonFiniteBearingForTheValidationToName) {
  const PlateReading bad =
      PlateReadingFromCamera("214", 0.8, CameraAxis{}, std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(std::isnan(bad.bearing_rad));
  EXPECT_NE(ValidatePlateReading(bad).find("PlateReading.bearing_rad"), std::string::npos);
  EXPECT_TRUE(std::isinf(BearingInBase(CameraAxis{}, std::numeric_limits<double>::infinity())));
}

}  // namespace
}  // namespace doorplate_localization

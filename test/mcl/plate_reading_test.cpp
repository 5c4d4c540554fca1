#include "doorplate_localization/mcl/plate_reading.h"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(CanonicalPlateText, UppercasesAndDropsSpacesAndDashes) {
  EXPECT_EQ(CanonicalPlateText(" b-12 "), "B12");
  EXPECT_EQ(CanonicalPlateText("214"), "214");
}

}  // namespace
}  // namespace doorplate_localization

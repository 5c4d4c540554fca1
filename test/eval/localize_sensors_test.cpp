// The experiment's conversions from the simulator and the text extractor to the filter's inputs.
#include "localize_sensors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace doorplate_localization {
namespace {

TEST(ToPlateReading, ComposesTheCameraYawWithTheReportBearing) {
  PlateReport report;
  report.text = "214";
  report.confidence = 0.8;
  report.bearing_rad = 0.1;  // towards the image's left: further forward for a left camera
  const PlateReading left = ToPlateReading(report, M_PI / 2.0);
  EXPECT_EQ(left.text, "214");
  EXPECT_EQ(left.confidence, 0.8);
  EXPECT_NEAR(left.bearing_rad, M_PI / 2.0 + 0.1, 1e-12);
  EXPECT_FALSE(left.range_m.has_value());  // TextAmclSession measures it
  EXPECT_EQ(left.camera_side, CameraSide::kLeft);
  EXPECT_EQ(ValidatePlateReading(left), "");
  const PlateReading right = ToPlateReading(report, -M_PI / 2.0);
  EXPECT_NEAR(right.bearing_rad, -M_PI / 2.0 + 0.1, 1e-12);
  EXPECT_EQ(right.camera_side, CameraSide::kRight);
  EXPECT_EQ(ValidatePlateReading(right), "");
}

}  // namespace
}  // namespace doorplate_localization

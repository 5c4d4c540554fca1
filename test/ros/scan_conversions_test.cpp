#include "doorplate_localization/ros/scan_conversions.h"

#include <gtest/gtest.h>

#include <limits>

namespace doorplate_localization {
namespace {

sensor_msgs::LaserScan GoodScan() {
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = "laser";
  scan.angle_min = -M_PI;
  scan.angle_increment = 2 * M_PI / 360;
  scan.range_min = 0.15f;
  scan.range_max = 16.0f;
  scan.ranges.assign(360, 1.0f);
  return scan;
}

TEST(ValidateScan, AcceptsAScanWithNonFiniteBeams) {
  sensor_msgs::LaserScan scan = GoodScan();
  scan.ranges[0] = std::numeric_limits<float>::infinity();
  scan.ranges[1] = -std::numeric_limits<float>::infinity();
  scan.ranges[2] = std::numeric_limits<float>::quiet_NaN();
  scan.ranges[3] = -1.0f;
  EXPECT_EQ(ValidateScan(scan), "");
  EXPECT_FALSE(IsValidRange(scan, scan.ranges[0]));
  EXPECT_FALSE(IsValidRange(scan, scan.ranges[2]));
  EXPECT_FALSE(IsValidRange(scan, scan.ranges[3]));
  EXPECT_TRUE(IsValidRange(scan, scan.ranges[4]));
}

TEST(ValidateScan, NamesWhatIsWrongWithABrokenScan) {
  sensor_msgs::LaserScan scan = GoodScan();
  scan.ranges.clear();
  EXPECT_EQ(ValidateScan(scan), "no ranges");
  scan = GoodScan();
  scan.angle_increment = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(ValidateScan(scan).find("angle_increment must be finite"), std::string::npos);
  scan = GoodScan();
  scan.angle_increment = 0.1f;  // 360 beams of 0.1 rad = 36 rad
  EXPECT_NE(ValidateScan(scan).find("more than a full turn"), std::string::npos);
  scan = GoodScan();
  scan.range_max = std::numeric_limits<float>::infinity();
  EXPECT_NE(ValidateScan(scan).find("range_max"), std::string::npos);
  scan = GoodScan();
  scan.header.frame_id = "";
  EXPECT_EQ(ValidateScan(scan), "header.frame_id is empty");
}

}  // namespace
}  // namespace doorplate_localization

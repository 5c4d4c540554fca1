#include "doorplate_localization/ros/scan_conversions.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <utility>

namespace doorplate_localization {
namespace {

sensor_msgs::LaserScan GoodScan() {
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = "laser";
  scan.angle_min = -M_PI;
  scan.angle_increment = 2 * M_PI / 360;
  scan.angle_max = scan.angle_min + 359 * scan.angle_increment;  // the last beam's angle
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
  scan.angle_max = scan.angle_min + 359 * scan.angle_increment;
  EXPECT_NE(ValidateScan(scan).find("more than a full turn"), std::string::npos);
  scan = GoodScan();
  scan.range_max = std::numeric_limits<float>::infinity();
  EXPECT_NE(ValidateScan(scan).find("range_max"), std::string::npos);
  scan = GoodScan();
  scan.header.frame_id = "";
  EXPECT_EQ(ValidateScan(scan), "header.frame_id is empty");
}

TEST(ValidateScan, RefusesAScanWhoseAnglesDisagreeWithItsRangesOrThatIsTooLong) {
  sensor_msgs::LaserScan scan = GoodScan();
  scan.ranges.resize(10);  // 10 ranges, but the angles say a full turn of 1-degree beams
  EXPECT_EQ(ValidateScan(scan), "10 ranges, but angle_min -3.14159 .. angle_max 3.12414 at increment 0.0174533 make 360 beams");
  scan = GoodScan();
  scan.angle_max = 0.0f;  // left unset
  EXPECT_NE(ValidateScan(scan).find("make 181 beams"), std::string::npos) << ValidateScan(scan);
  // Drivers whose angle_max is one increment past the last beam, or one short of it, are accepted.
  scan = GoodScan();
  scan.angle_max += scan.angle_increment;
  EXPECT_EQ(ValidateScan(scan), "");
  scan.angle_max -= 2 * scan.angle_increment;
  EXPECT_EQ(ValidateScan(scan), "");
  // A scan that sweeps clockwise (negative increment) is consistent too.
  scan = GoodScan();
  std::swap(scan.angle_min, scan.angle_max);
  scan.angle_increment = -scan.angle_increment;
  EXPECT_EQ(ValidateScan(scan), "");
  // More ranges than limits::kMaxScanBeams, whatever the angles say.
  scan = GoodScan();
  scan.ranges.assign(100001, 1.0f);
  scan.angle_increment = static_cast<float>(2 * M_PI / 100001 / 2);
  scan.angle_max = static_cast<float>(scan.angle_min + 100000 * static_cast<double>(scan.angle_increment));
  EXPECT_EQ(ValidateScan(scan), "100001 ranges, more than the limit of 100000 (limits::kMaxScanBeams)");
}

}  // namespace
}  // namespace doorplate_localization

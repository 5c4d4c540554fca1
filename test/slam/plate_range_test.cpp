#include "doorplate_localization/slam/plate_range.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "doorplate_localization/slam/text_slam.h"
#include "slam_test_worlds.h"

namespace doorplate_localization {
namespace {

// A 2.05 m corridor (walls at y = ±1.025) with a person (a 0.5 m × 0.3 m box) standing 0.3 m before the
// robot on its right, between it and the south wall.
std::vector<Segment> CorridorWithPersonOnTheRight() {
  std::vector<Segment> walls = test::Corridor();
  const std::vector<Segment> person = {{{-0.25, -0.3}, {0.25, -0.3}}, {{0.25, -0.3}, {0.25, -0.6}},
                                       {{0.25, -0.6}, {-0.25, -0.6}}, {{-0.25, -0.6}, {-0.25, -0.3}}};
  walls.insert(walls.end(), person.begin(), person.end());
  return walls;
}

TEST(WallRangeAlongBearing, FindsTheWallBehindSomethingStandingBeforeThePlate) {
  const RangeScan scan = test::Scan(CorridorWithPersonOnTheRight(), {0, 0, 0});
  EXPECT_NEAR(*PlateRangeAlongBearing(scan, -M_PI / 2, 0.03), 0.3, 0.01);  // the echoes along it: the person
  EXPECT_NEAR(*WallRangeAlongBearing(scan, -M_PI / 2, WallRangeOptions{}), 1.025, 0.01);
}

TEST(WallRangeAlongBearing, MeasuresFromBaseLinkWhateverTheLaserMount) {
  RangeScan mounted = test::Scan(test::Corridor(), {0.3, 0, 0.4});
  mounted.laser_pose = {0.3, 0, 0.4};
  EXPECT_NEAR(*WallRangeAlongBearing(mounted, M_PI / 2, WallRangeOptions{}), 1.025, 0.01);
}

TEST(WallRangeAlongBearing, MeetsASlantedWallWhereTheBearingCrossesIt) {
  // The robot turned 0.3 rad to the left: the bearing -pi/2 meets the south wall 1.025 / cos(0.3) away.
  const RangeScan scan = test::Scan(test::Corridor(), {0, 0, 0.3});
  EXPECT_NEAR(*WallRangeAlongBearing(scan, -M_PI / 2, WallRangeOptions{}), 1.025 / std::cos(0.3), 0.01);
}

TEST(WallRangeAlongBearing, NoWallAcrossTheBearingGivesNoRange) {
  // Along the corridor: only the side walls, parallel to the bearing.
  EXPECT_FALSE(WallRangeAlongBearing(test::Scan(test::Corridor(), {0, 0, 0}), 0.0, WallRangeOptions{}).has_value());
  // A 0.6 m wide post 1 m away: 33 echoes on a line, but no wall's length.
  const RangeScan post = test::Scan({{{-0.3, -1.0}, {0.3, -1.0}}}, {0, 0, 0});
  EXPECT_FALSE(WallRangeAlongBearing(post, -M_PI / 2, WallRangeOptions{}).has_value());
}

TEST(WallRangeOptions, BadOptionsThrowNamingTheField) {
  const auto message = [](WallRangeOptions o) {
    try {
      ValidateWallRangeOptions(o);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  WallRangeOptions o;
  EXPECT_EQ(message(o), "");
  o.window_rad = 0;
  EXPECT_NE(message(o).find("WallRangeOptions.window_rad"), std::string::npos);
  o = WallRangeOptions{};
  o.inlier_m = NAN;
  EXPECT_NE(message(o).find("WallRangeOptions.inlier_m"), std::string::npos);
  o = WallRangeOptions{};
  o.min_inliers = 2;
  EXPECT_NE(message(o).find("WallRangeOptions.min_inliers"), std::string::npos);
  o = WallRangeOptions{};
  o.max_incidence_rad = M_PI / 2;
  EXPECT_NE(message(o).find("WallRangeOptions.max_incidence_rad"), std::string::npos);
  o = WallRangeOptions{};
  o.min_span_m = -1;
  EXPECT_NE(message(o).find("WallRangeOptions.min_span_m"), std::string::npos);
}

}  // namespace
}  // namespace doorplate_localization

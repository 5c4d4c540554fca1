#include "doorplate_localization/sensors/plate_range.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../slam/slam_test_worlds.h"

namespace doorplate_localization {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// A scan of the test worlds (slam_test_worlds.h: an exact 360-beam laser at `pose`, laser at base_link's
// origin unless `mount` is given) as ranges and geometry.
struct Beams {
  std::vector<float> ranges_m;
  BeamGeometry geometry;
};
Beams ScanOf(const std::vector<Segment>& walls, const Pose2D& pose, const Pose2D& mount = {}) {
  const LaserScan scan = test::Scan(walls, pose);
  Beams b{scan.ranges_m, BeamGeometryOf(scan)};
  b.geometry.laser_pose = mount;
  return b;
}

// 8 beams over a full turn (45° apart, from -pi) with ranges 1..8 m, max range 16 m.
Beams EightBeams() {
  Beams b;
  b.geometry.angle_min_rad = -M_PI;
  b.geometry.angle_increment_rad = M_PI / 4.0;
  b.geometry.min_range_m = 0.15;
  b.geometry.max_range_m = 16.0;
  b.ranges_m = {1, 2, 3, 4, 5, 6, 7, 8};
  return b;
}

// 360 beams over a full turn, every range `range_m`, laser at `mount` in base_link.
Beams Ring(float range_m, const Pose2D& mount = {}) {
  Beams b;
  b.geometry.angle_min_rad = -M_PI;
  b.geometry.angle_increment_rad = 2 * M_PI / 360;
  b.geometry.min_range_m = 0.15;
  b.geometry.max_range_m = 12.0;
  b.geometry.laser_pose = mount;
  b.ranges_m.assign(360, range_m);
  return b;
}

// A 2.05 m corridor (walls at y = ±1.025) with a person (a 0.5 m × 0.3 m box) standing 0.3 m before the
// robot on its right, between it and the south wall.
std::vector<Segment> CorridorWithPersonOnTheRight() {
  std::vector<Segment> walls = test::Corridor();
  const std::vector<Segment> person = {{{-0.25, -0.3}, {0.25, -0.3}}, {{0.25, -0.3}, {0.25, -0.6}},
                                       {{0.25, -0.6}, {-0.25, -0.6}}, {{-0.25, -0.6}, {-0.25, -0.3}}};
  walls.insert(walls.end(), person.begin(), person.end());
  return walls;
}

TEST(EchoRangeAlongBearing, TakesTheEchoesAlongTheBearing) {
  const Beams b = EightBeams();
  EXPECT_EQ(EchoRangeAlongBearing(b.ranges_m, b.geometry, M_PI / 2.0, 0.1), 7.0);  // beam 6 at +90°: the left
  EXPECT_EQ(EchoRangeAlongBearing(b.ranges_m, b.geometry, M_PI / 2.0 + 0.05, 0.1), 7.0);
  EXPECT_EQ(EchoRangeAlongBearing(b.ranges_m, b.geometry, 0.0, 0.1), 5.0);
  EXPECT_EQ(EchoRangeAlongBearing(b.ranges_m, b.geometry, M_PI - 0.01, 0.1), 1.0);  // wraps to beam 0 at -180°
  // Several echoes in the window: their median (a stray short echo does not decide).
  Beams ring = Ring(2.0f);
  ring.ranges_m[90] = 0.5f;  // the beam at -90°
  EXPECT_NEAR(*EchoRangeAlongBearing(ring.ranges_m, ring.geometry, -M_PI / 2, 0.03), 2.0, 1e-6);
}

TEST(EchoRangeAlongBearing, AccountsForTheLaserMountingYaw) {
  Beams b = EightBeams();
  b.geometry.laser_pose.theta_rad = M_PI / 4.0;  // beam 6 (+90° in the laser) points at +135° in base_link
  EXPECT_NEAR(*EchoRangeAlongBearing(b.ranges_m, b.geometry, 3.0 * M_PI / 4.0, 0.1), 7.0, 1e-9);
}

TEST(EchoRangeAlongBearing, MeasuresFromBaseLinkThroughAnOffsetLaser) {
  const Beams centred = Ring(2.0f);
  EXPECT_NEAR(*EchoRangeAlongBearing(centred.ranges_m, centred.geometry, M_PI / 2, 0.02), 2.0, 1e-6);
  // Laser 0.3 m ahead of base_link: the wall point seen at 90° from base_link is a beam at ~98.6° of
  // the laser, sqrt(2² - 0.3²) = 1.977 m from base_link.
  const Beams ahead = Ring(2.0f, Pose2D{0.3, 0.0, 0.0});
  EXPECT_NEAR(*EchoRangeAlongBearing(ahead.ranges_m, ahead.geometry, M_PI / 2, 0.02), std::sqrt(4.0 - 0.09), 0.02);
}

TEST(EchoRangeAlongBearing, GivesNothingWithoutAnEchoNearTheBearing) {
  Beams b = EightBeams();
  EXPECT_FALSE(EchoRangeAlongBearing(b.ranges_m, b.geometry, M_PI / 8.0, 0.1).has_value());  // between beams
  for (const float no_echo : {kInf, std::nanf(""), 0.1f /* below min range */, 16.0f /* max range */}) {
    b.ranges_m[6] = no_echo;
    EXPECT_FALSE(EchoRangeAlongBearing(b.ranges_m, b.geometry, M_PI / 2.0, 0.1).has_value()) << no_echo;
  }
  EXPECT_FALSE(EchoRangeAlongBearing(b.ranges_m, b.geometry, std::nan(""), 0.1).has_value());
  EXPECT_FALSE(EchoRangeAlongBearing({}, BeamGeometry{}, 0.0, 0.1).has_value());
  Beams open = Ring(kInf);
  open.ranges_m[180] = 3.0f;  // the beam at 0 rad
  EXPECT_TRUE(EchoRangeAlongBearing(open.ranges_m, open.geometry, 0.0, 0.05).has_value());
  EXPECT_FALSE(EchoRangeAlongBearing(open.ranges_m, open.geometry, 0.2, 0.05).has_value());  // off that beam
}

TEST(WallRangeAlongBearing, FindsTheWallBehindSomethingStandingBeforeThePlate) {
  const Beams b = ScanOf(CorridorWithPersonOnTheRight(), {0, 0, 0});
  EXPECT_NEAR(*EchoRangeAlongBearing(b.ranges_m, b.geometry, -M_PI / 2, 0.03), 0.3, 0.01);  // the person
  EXPECT_NEAR(*WallRangeAlongBearing(b.ranges_m, b.geometry, -M_PI / 2, WallRangeOptions{}), 1.025, 0.01);
}

TEST(WallRangeAlongBearing, MeasuresFromBaseLinkWhateverTheLaserMount) {
  const Beams b = ScanOf(test::Corridor(), {0.3, 0, 0.4}, {0.3, 0, 0.4});
  EXPECT_NEAR(*WallRangeAlongBearing(b.ranges_m, b.geometry, M_PI / 2, WallRangeOptions{}), 1.025, 0.01);
}

TEST(WallRangeAlongBearing, MeetsASlantedWallWhereTheBearingCrossesIt) {
  // The robot turned 0.3 rad to the left: the bearing -pi/2 meets the south wall 1.025 / cos(0.3) away.
  const Beams b = ScanOf(test::Corridor(), {0, 0, 0.3});
  EXPECT_NEAR(*WallRangeAlongBearing(b.ranges_m, b.geometry, -M_PI / 2, WallRangeOptions{}), 1.025 / std::cos(0.3),
              0.01);
}

TEST(WallRangeAlongBearing, NoWallAcrossTheBearingGivesNoRange) {
  // Along the corridor: only the side walls, parallel to the bearing.
  const Beams along = ScanOf(test::Corridor(), {0, 0, 0});
  EXPECT_FALSE(WallRangeAlongBearing(along.ranges_m, along.geometry, 0.0, WallRangeOptions{}).has_value());
  // A 0.6 m wide post 1 m away: 33 echoes on a line, but no wall's length.
  const Beams post = ScanOf({{{-0.3, -1.0}, {0.3, -1.0}}}, {0, 0, 0});
  EXPECT_FALSE(WallRangeAlongBearing(post.ranges_m, post.geometry, -M_PI / 2, WallRangeOptions{}).has_value());
}

TEST(PlateRangeAlongBearing, TakesTheWallOnlyWhenSomethingStoodBeforeThePlate) {
  const Beams blocked = ScanOf(CorridorWithPersonOnTheRight(), {0, 0, 0});
  const std::optional<PlateRange> wall = PlateRangeAlongBearing(blocked.ranges_m, blocked.geometry, -M_PI / 2, {});
  ASSERT_TRUE(wall.has_value());
  EXPECT_NEAR(wall->range_m, 1.025, 0.01);
  EXPECT_TRUE(wall->from_wall);
  PlateRangeOptions off;
  off.occluded_margin_m = 0.0;
  const std::optional<PlateRange> echo = PlateRangeAlongBearing(blocked.ranges_m, blocked.geometry, -M_PI / 2, off);
  EXPECT_NEAR(echo->range_m, 0.3, 0.01);
  EXPECT_FALSE(echo->from_wall);
  const Beams clear = ScanOf(test::Corridor(), {0, 0, 0});
  const std::optional<PlateRange> plain = PlateRangeAlongBearing(clear.ranges_m, clear.geometry, M_PI / 2, {});
  EXPECT_NEAR(plain->range_m, 1.025, 0.01);
  EXPECT_FALSE(plain->from_wall);
  // No echo along the bearing: no range, whatever the wall.
  Beams open = ScanOf(test::Corridor(), {0, 0, 0});
  for (std::size_t i = 85; i <= 95; ++i) open.ranges_m[i] = kInf;  // beams around -90°
  EXPECT_FALSE(PlateRangeAlongBearing(open.ranges_m, open.geometry, -M_PI / 2, {}).has_value());
}

TEST(PlateRangeOptions, BadOptionsThrowNamingTheField) {
  const auto message = [](const PlateRangeOptions& o) {
    try {
      ValidatePlateRangeOptions(o);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  PlateRangeOptions o;
  EXPECT_EQ(message(o), "");
  o.beam_window_rad = -0.1;
  EXPECT_NE(message(o).find("PlateRangeOptions.beam_window_rad"), std::string::npos);
  o = PlateRangeOptions{};
  o.occluded_margin_m = NAN;
  EXPECT_NE(message(o).find("PlateRangeOptions.occluded_margin_m"), std::string::npos);
  o = PlateRangeOptions{};
  o.wall.window_rad = 0;
  EXPECT_NE(message(o).find("WallRangeOptions.window_rad"), std::string::npos);
  o = PlateRangeOptions{};
  o.wall.inlier_m = NAN;
  EXPECT_NE(message(o).find("WallRangeOptions.inlier_m"), std::string::npos);
  o = PlateRangeOptions{};
  o.wall.min_inliers = 2;
  EXPECT_NE(message(o).find("WallRangeOptions.min_inliers"), std::string::npos);
  o = PlateRangeOptions{};
  o.wall.max_incidence_rad = M_PI / 2;
  EXPECT_NE(message(o).find("WallRangeOptions.max_incidence_rad"), std::string::npos);
  o = PlateRangeOptions{};
  o.wall.min_length_m = -1;
  EXPECT_NE(message(o).find("WallRangeOptions.min_length_m"), std::string::npos);
}

}  // namespace
}  // namespace doorplate_localization

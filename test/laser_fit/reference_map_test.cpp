#include "doorplate_localization/laser_fit/reference_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace doorplate_localization {
namespace {

constexpr double kDeg = M_PI / 180.0;

// A 360-beam scan of `walls` from `laser` (map frame), exact or with Gaussian noise; +inf where no wall.
LaserScan ScanOf(const std::vector<Segment>& walls, const Pose2D& laser, double noise_m, std::mt19937_64& rng) {
  LaserScan scan;
  scan.angle_min_rad = -M_PI;
  scan.angle_increment_rad = 2 * M_PI / 360;
  scan.min_range_m = 0.01;
  std::normal_distribution<double> noise(0.0, noise_m > 0 ? noise_m : 1.0);
  for (int i = 0; i < 360; ++i) {
    const double a = laser.theta_rad + scan.BeamAngle(i);
    double best = std::numeric_limits<double>::infinity();
    for (const Segment& w : walls) {
      if (const auto t = RaySegmentDistance(laser.Position(), {std::cos(a), std::sin(a)}, w); t && *t < best) best = *t;
    }
    const double n = noise(rng);
    scan.ranges_m.push_back(static_cast<float>(best + (noise_m > 0 ? n : 0.0)));
  }
  return scan;
}

// A room [0, 4.07] × [0, 3] (the east wall inside a 0.1 m cell, not on its edge), optionally without its
// north wall, drawn from a few poses.
ReferenceMap Room(double resolution_m, double noise_m, bool north_wall = true) {
  std::vector<Segment> walls = {{{0, 0}, {4.07, 0}}, {{4.07, 0}, {4.07, 3}}, {{0, 0}, {0, 3}}};
  if (north_wall) walls.push_back({{0, 3}, {4.07, 3}});
  ReferenceMapOptions options;
  options.resolution_m = resolution_m;
  options.surface_radius_m = 0.2;
  ReferenceMap map(options);
  std::mt19937_64 rng(1);
  for (const Pose2D& p : {Pose2D{1, 1, 0}, Pose2D{2, 2, 1}, Pose2D{3, 1.2, 2}, Pose2D{1.5, 2.2, -1}}) {
    for (int k = 0; k < 5; ++k) map.AddScan(p, ScanOf(walls, p, noise_m, rng));
  }
  map.Finish();
  return map;
}

TEST(ReferenceMap, ExpectsTheWallAndItsIncidenceAngle) {
  const ReferenceMap map = Room(0.05, 0.0);
  const ExpectedBeam ahead = map.Expect({2.0, 1.5}, 0.0, 40.0);
  ASSERT_EQ(ahead.kind, ExpectedKind::kHit);
  ASSERT_TRUE(ahead.surface_fit);
  EXPECT_NEAR(ahead.range_m, 2.07, 0.005);
  EXPECT_NEAR(ahead.incidence_rad, 0.0, 1.0 * kDeg);
  const ExpectedBeam slanted = map.Expect({2.0, 1.5}, 30 * kDeg, 40.0);
  ASSERT_EQ(slanted.kind, ExpectedKind::kHit);
  ASSERT_TRUE(slanted.surface_fit);
  EXPECT_NEAR(slanted.range_m, 2.07 / std::cos(30 * kDeg), 0.01);
  EXPECT_NEAR(slanted.incidence_rad, 30 * kDeg, 1.0 * kDeg);
}

TEST(ReferenceMap, RefinesTheRangeBelowTheCellSize) {
  const ReferenceMap map = Room(0.1, 0.01);  // 10 cm cells, 1 cm noise on the drawing scans
  const ExpectedBeam ahead = map.Expect({2.0, 1.5}, 0.0, 40.0);
  ASSERT_EQ(ahead.kind, ExpectedKind::kHit);
  ASSERT_TRUE(ahead.surface_fit);
  EXPECT_NEAR(ahead.range_m, 2.07, 0.005);  // the grid alone says 2.0 (the cell's edge at x = 4.0)
}

TEST(ReferenceMap, KnowsFreeSpaceUnseenSpaceAndOutside) {
  const ReferenceMap open_room = Room(0.05, 0.0, false);
  EXPECT_EQ(open_room.Expect({2.0, 1.5}, 0.0, 1.0).kind, ExpectedKind::kNothing);  // 1 m of free cells
  EXPECT_EQ(open_room.Expect({2.0, 1.5}, M_PI / 2, 40.0).kind, ExpectedKind::kUnknown);  // out of the open side
  EXPECT_EQ(open_room.Expect({-3.0, 1.5}, 0.0, 40.0).kind, ExpectedKind::kUnknown);  // from outside the map
}

TEST(ReferenceMap, NeedsFinishBetweenDrawingAndExpecting) {
  ReferenceMap map(ReferenceMapOptions{});
  EXPECT_THROW(map.Expect({0, 0}, 0.0, 1.0), std::logic_error);
  map.Finish();
  EXPECT_THROW(map.AddScan({}, LaserScan{}), std::logic_error);
}

TEST(ReferenceMap, BadOptionsAreNamed) {
  ReferenceMapOptions options;
  options.resolution_m = 0.0;
  try {
    ReferenceMap map(options);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ReferenceMapOptions.resolution_m"), std::string::npos);
  }
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/mcl/grid_ray_caster.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mcl_fixtures.h"

namespace doorplate_localization {
namespace {

TEST(CastRay, StopsAtTheFirstOccupiedCell) {
  const LocalizationGrid room(test::AsymmetricRoom());
  // From (1, 2) east: the room's inner box spans x 2.0..2.6 at y 1.0..1.4 — not on this ray; the wall
  // is at x = 6, the cupboard starts at x = 4.8 for y >= 3.2 — also not. Distance to the wall: 5 m.
  EXPECT_NEAR(CastRay(room, {1.0, 2.0}, 0.0, 20.0), 5.0, 0.05);
  // From (1, 1.2) east: the inner box at x = 2.0.
  EXPECT_NEAR(CastRay(room, {1.0, 1.2}, 0.0, 20.0), 1.0, 0.05);
  // Diagonal towards the south-west corner from (1, 1): sqrt(2) m.
  EXPECT_NEAR(CastRay(room, {1.0, 1.0}, -3 * M_PI / 4, 20.0), std::sqrt(2.0), 0.08);
}

TEST(CastRay, ReturnsMaxRangeWhenNothingIsHitAndZeroInsideAWall) {
  const LocalizationGrid room(test::AsymmetricRoom());
  EXPECT_DOUBLE_EQ(CastRay(room, {1.0, 2.0}, 0.0, 3.0), 3.0);
  EXPECT_EQ(CastRay(room, {2.3, 1.2}, 0.0, 3.0), 0.0);    // inside the inner box
  EXPECT_EQ(CastRay(room, {100.0, 0.0}, 0.0, 3.0), 0.0);  // outside the grid
}

TEST(CastRay, UnknownCellsBlockOnlyWhenAsked) {
  OccupancyGrid g = test::MakeGrid(0, 0, 4.0, 1.0, 0.1, 0);
  test::FillRect(&g, 1.0, 0.0, 1.5, 1.0, OccupancyGrid::kUnknown);
  const LocalizationGrid grid(g);
  EXPECT_NEAR(CastRay(grid, {0.2, 0.5}, 0.0, 10.0, true), 0.8, 1e-9);
  EXPECT_NEAR(CastRay(grid, {0.2, 0.5}, 0.0, 10.0, false), 3.8, 1e-9);  // then the grid's edge (as amcl)
}

TEST(CastRay, GivesTheSameRangesOnARotatedGrid) {
  OccupancyGrid g = test::AsymmetricRoom();
  OccupancyGrid turned = g;
  turned.origin = {0.0, 0.0, 0.7};
  const LocalizationGrid a(g), b(turned);
  const Pose2D shift = turned.origin.Compose(g.origin.Inverse());  // maps a's frame onto b's
  for (double angle : {0.0, 1.0, 2.5, -2.0}) {
    const Vec2 p{1.0, 2.2};
    EXPECT_NEAR(CastRay(a, p, angle, 20.0), CastRay(b, shift.TransformPoint(p), angle + 0.7, 20.0), 1e-6);
  }
}

TEST(HasLineOfSight, IsBlockedByTheBoxButNotByTheTargetWall) {
  const LocalizationGrid room(test::AsymmetricRoom());
  EXPECT_FALSE(HasLineOfSight(room, {1.0, 1.2}, {3.0, 1.2}, 0.15));
  EXPECT_TRUE(HasLineOfSight(room, {1.0, 2.0}, {6.0, 2.0}, 0.15));  // target on the wall surface
}

TEST(CastScan, MarksBeamsWithoutEchoAsInfinity) {
  const LocalizationGrid room(test::AsymmetricRoom());
  const LaserScan s = CastScan(room, {1.0, 2.0, 0.0}, test::ScanGeometry(2.0), 360);
  ASSERT_EQ(s.ranges_m.size(), 360u);
  EXPECT_TRUE(std::isinf(s.ranges_m[180]));       // straight ahead: the wall is 4.9 m from the laser
  EXPECT_NEAR(s.ranges_m[0], 1.1, 0.05);          // straight back: the west wall, 1 m + 0.1 m mount
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/common/geometry2d.h"

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

TEST(NormalizeAngle, WrapsIntoHalfOpenInterval) {
  EXPECT_NEAR(NormalizeAngle(3 * M_PI), M_PI, 1e-12);
  EXPECT_NEAR(NormalizeAngle(-M_PI), M_PI, 1e-12);
  EXPECT_NEAR(NormalizeAngle(2 * M_PI + 0.1), 0.1, 1e-12);
  EXPECT_NEAR(NormalizeAngle(-0.1), -0.1, 1e-12);
}

TEST(Pose2D, ComposeThenBetweenRecoversTheRelativePose) {
  const Pose2D a{1.0, 2.0, 0.7};
  const Pose2D rel{0.5, -0.3, -1.2};
  const Pose2D b = a.Compose(rel);
  const Pose2D back = a.Between(b);
  EXPECT_NEAR(back.x_m, rel.x_m, 1e-12);
  EXPECT_NEAR(back.y_m, rel.y_m, 1e-12);
  EXPECT_NEAR(back.theta_rad, rel.theta_rad, 1e-12);
}

TEST(Pose2D, TransformPointRotatesCounterClockwise) {
  const Pose2D facing_left{0.0, 0.0, M_PI / 2};
  const Vec2 p = facing_left.TransformPoint({1.0, 0.0});
  EXPECT_NEAR(p.x, 0.0, 1e-12);
  EXPECT_NEAR(p.y, 1.0, 1e-12);
}

TEST(RaySegmentDistance, HitsAWallAheadAndReportsWhereOnIt) {
  const Segment wall{{2.0, -1.0}, {2.0, 3.0}};
  double u = -1;
  const auto t = RaySegmentDistance({0.0, 0.0}, {1.0, 0.0}, wall, &u);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 2.0, 1e-12);
  EXPECT_NEAR(u, 0.25, 1e-12);
}

TEST(RaySegmentDistance, ARayAimedAtTheJointOfTwoWallsHitsOneOfThem) {
  // Two walls meeting at a corner, as in any closed world; rays from many places aimed exactly at the joint.
  const Vec2 corner{42.0, 26.0};
  const Segment east{{42.0, 0.0}, corner}, north{corner, {0.0, 26.0}};
  int misses = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec2 origin{40.0 + 0.0013 * i, 24.1 + 0.00071 * i};
    const Vec2 d = corner - origin;
    const Vec2 dir = (1.0 / Norm(d)) * d;
    if (!RaySegmentDistance(origin, dir, east) && !RaySegmentDistance(origin, dir, north)) ++misses;
  }
  EXPECT_EQ(misses, 0);
}

TEST(RaySegmentDistance, MissesBehindBesideAndParallel) {
  const Segment wall{{2.0, -1.0}, {2.0, 1.0}};
  EXPECT_FALSE(RaySegmentDistance({0.0, 0.0}, {-1.0, 0.0}, wall));       // behind
  EXPECT_FALSE(RaySegmentDistance({0.0, 5.0}, {1.0, 0.0}, wall));        // beside
  EXPECT_FALSE(RaySegmentDistance({0.0, 0.0}, {0.0, 1.0}, wall));        // parallel
}

TEST(PointSegmentDistance, UsesTheNearestEndpointOutsideTheSegment) {
  const Segment s{{0.0, 0.0}, {1.0, 0.0}};
  EXPECT_NEAR(PointSegmentDistance({0.5, 2.0}, s), 2.0, 1e-12);
  EXPECT_NEAR(PointSegmentDistance({4.0, 4.0}, s), 5.0, 1e-12);
}

}  // namespace
}  // namespace doorplate_localization

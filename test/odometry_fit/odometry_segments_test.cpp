#include "doorplate_localization/odometry_fit/odometry_segments.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace doorplate_localization {
namespace {

// A step forward `reference_m` (turning `turn_rad`) that the odometry reads as (1 + scale) times as long.
OdometryStep Step(double reference_m, double scale, double turn_rad = 0.0) {
  OdometryStep s;
  s.reference = {reference_m, 0.0, turn_rad};
  s.odometry = {reference_m * (1.0 + scale), 0.0, turn_rad};
  s.dt_s = 0.5;
  return s;
}

TEST(OdometrySegments, CutsAStraightDriveIntoSegmentsOfTheReferenceLength) {
  std::vector<OdometryStep> steps(10, Step(0.25, 0.04));
  const std::vector<OdometrySegment> segments = SplitIntoSegments(steps, {1.0});
  ASSERT_EQ(segments.size(), 2u);  // 2.5 m: two full metres, the last half metre is dropped
  EXPECT_EQ(segments[0].first_step, 0);
  EXPECT_EQ(segments[1].first_step, 4);
  EXPECT_EQ(segments[1].num_steps, 4);
  EXPECT_NEAR(segments[1].start_arc_m, 1.0, 1e-12);
  EXPECT_NEAR(segments[1].start_position.x, 1.0, 1e-12);
  EXPECT_NEAR(segments[0].ScaleError(), 0.04, 1e-12);
  EXPECT_NEAR(segments[0].duration_s, 2.0, 1e-12);
}

TEST(OdometrySegments, LeavesOutStepsWithoutAnAlongConstrainedReference) {
  std::vector<OdometryStep> steps(12, Step(0.25, 0.0));
  steps[2].along_constrained = false;  // breaks the first metre: steps 0-1 are dropped
  steps[7].reference_valid = false;    // steps 3-6 made a full metre before it
  const std::vector<OdometrySegment> segments = SplitIntoSegments(steps, {1.0});
  ASSERT_EQ(segments.size(), 2u);
  EXPECT_EQ(segments[0].first_step, 3);
  EXPECT_EQ(segments[1].first_step, 8);
  EXPECT_NEAR(segments[1].start_arc_m, 2.0, 1e-12);  // the path still advances over left-out steps
}

TEST(OdometrySegments, SumsRotationWithoutWrappingAndMeasuresTurnRatePerMetre) {
  // A quarter circle of radius 1 m in 30 steps, the wheels over-reading the turn by 10 %.
  std::vector<OdometryStep> steps;
  const int n = 30;
  const double dtheta = M_PI / 2 / n, chord = 2 * std::sin(dtheta / 2);
  for (int i = 0; i < 3 * n; ++i) {  // three quarter circles: 3π/2 in one segment of > 1 m chord
    OdometryStep s;
    s.reference = {chord * std::cos(dtheta / 2), chord * std::sin(dtheta / 2), dtheta};
    s.odometry = s.reference;
    s.odometry.theta_rad *= 1.1;
    steps.push_back(s);
  }
  const std::vector<OdometrySegment> segments = SplitIntoSegments(steps, {1.4});
  ASSERT_GE(segments.size(), 1u);
  EXPECT_NEAR(segments[0].reference_distance_m, std::sqrt(2.0), 0.05);  // ends after a quarter circle
  EXPECT_NEAR(segments[0].odometry_rotation_rad / segments[0].reference_rotation_rad, 1.1, 1e-9);
  EXPECT_NEAR(segments[0].TurnRateRadPerM(), segments[0].reference_rotation_rad / segments[0].reference_distance_m,
              1e-12);
  EXPECT_EQ(segments[0].duration_s, 0.0);  // dt_s unknown
}

TEST(OdometrySegments, RefusesANonPositiveSegmentLength) {
  EXPECT_THROW(SplitIntoSegments({Step(1.0, 0.0)}, {0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

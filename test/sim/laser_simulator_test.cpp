#include "doorplate_localization/sim/laser_simulator.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_worlds.h"

namespace doorplate_localization {
namespace {

// Index of the beam pointing at `angle_rad` in the laser frame.
int BeamAt(const LaserScan& scan, double angle_rad) {
  const double from_first = std::fmod(angle_rad - scan.angle_min_rad + 4 * M_PI, 2 * M_PI);
  return static_cast<int>(std::lround(from_first / scan.angle_increment_rad)) % static_cast<int>(scan.ranges_m.size());
}

TEST(LaserSimulator, ExactScanMatchesTheCorridorGeometry) {
  const World world = test::RectangleCorridor(10.0, 2.0);
  LaserOptions options;
  const LaserSimulator laser(options);
  const LaserScan scan = laser.CastExact(world, {3.0, 0.5, 0.0});
  ASSERT_EQ(scan.ranges_m.size(), 360u);
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, 0.0)], 7.0, 1e-4);          // east wall ahead
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, M_PI / 2)], 1.5, 1e-4);     // north wall left
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, -M_PI / 2)], 0.5, 1e-4);    // south wall right
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, M_PI)], 3.0, 1e-4);         // west wall behind
  // A beam at 45° left hits the north wall at 1.5 / sin(45°).
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, M_PI / 4)], 1.5 * std::sqrt(2.0), 1e-4);
}

TEST(LaserSimulator, CorridorWidthIsTheSumOfLeftAndRightMinima) {
  const World world = test::RectangleCorridor(40.0, 1.85);
  const LaserScan scan = LaserSimulator(LaserOptions{}).CastExact(world, {20.0, 0.6, 0.1});
  float left = INFINITY, right = INFINITY;
  for (size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double a = scan.angle_min_rad + i * scan.angle_increment_rad;
    (std::sin(a) > 0 ? left : right) = std::min(std::sin(a) > 0 ? left : right, scan.ranges_m[i]);
  }
  EXPECT_NEAR(left + right, 1.85, 0.01);
}

TEST(LaserSimulator, BeyondMaxRangeIsPositiveInfinityPerRep117) {
  const World world = test::RectangleCorridor(40.0, 2.0);
  const LaserScan scan = LaserSimulator(LaserOptions{}).CastExact(world, {1.0, 1.0, 0.0});
  EXPECT_TRUE(std::isinf(scan.ranges_m[BeamAt(scan, 0.0)]));      // east wall is 39 m away, max 16 m
  EXPECT_GT(scan.ranges_m[BeamAt(scan, 0.0)], 0.0f);
}

TEST(LaserSimulator, MountPoseShiftsTheOrigin) {
  const World world = test::RectangleCorridor(10.0, 2.0);
  LaserOptions options;
  options.mount_x_m = 0.5;
  const LaserScan scan = LaserSimulator(options).CastExact(world, {3.0, 1.0, 0.0});
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, 0.0)], 6.5, 1e-4);
}

TEST(LaserSimulator, ScanCarriesTheMountingPoseAndTheDevicesMaxRange) {
  const World world = test::RectangleCorridor(10.0, 2.0);
  LaserOptions options;
  options.mount_x_m = 0.1;
  options.mount_y_m = -0.05;
  options.mount_yaw_rad = 0.2;
  options.max_range_m = 12.0;
  std::mt19937_64 rng(1);
  const LaserScan scan = LaserSimulator(options).Simulate(world, {5.0, 1.0, 0.0}, rng);
  EXPECT_EQ(scan.laser_pose.x_m, 0.1);
  EXPECT_EQ(scan.laser_pose.y_m, -0.05);
  EXPECT_EQ(scan.laser_pose.theta_rad, 0.2);
  EXPECT_EQ(scan.max_range_m, 12.0);
  EXPECT_EQ(BeamGeometryOf(scan).max_range_m, 12.0);
}

TEST(LaserSimulator, NoiseHasTheConfiguredSpreadAndDropoutsRate) {
  const World world = test::RectangleCorridor(10.0, 2.0);
  LaserOptions options;
  options.range_noise_stddev_m = 0.02;
  options.dropout_probability = 0.1;
  const LaserSimulator laser(options);
  std::mt19937_64 rng(7);
  const Pose2D pose{5.0, 1.0, 0.0};
  const LaserScan exact = laser.CastExact(world, pose);
  double sum2 = 0.0;
  int n = 0, dropped = 0, total = 0;
  for (int k = 0; k < 50; ++k) {
    const LaserScan noisy = laser.Simulate(world, pose, rng);
    for (size_t i = 0; i < exact.ranges_m.size(); ++i, ++total) {
      if (std::isinf(noisy.ranges_m[i])) {
        ++dropped;
        continue;
      }
      const double e = noisy.ranges_m[i] - exact.ranges_m[i];
      sum2 += e * e;
      ++n;
    }
  }
  EXPECT_NEAR(std::sqrt(sum2 / n), 0.02, 0.002);
  EXPECT_NEAR(static_cast<double>(dropped) / total, 0.1, 0.01);
}

TEST(LaserSimulator, LintelsAboveTheScanPlaneAreNotSeen) {
  World world = test::RectangleCorridor(10.0, 2.0);
  Door door;
  door.wall_index = 1;
  door.offset_m = 5.0;
  door.open = true;
  door.room_depth_m = 3.0;
  world.doors.push_back(door);
  BuildSurfaces(world);
  const LaserScan scan = LaserSimulator(LaserOptions{}).CastExact(world, {5.0, 1.0, 0.0});
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, M_PI / 2)], 1.0 + 3.0, 1e-4);  // through the door to the room's back
}

TEST(LaserSimulator, CastExactGivesEachBeamsIncidenceAngle) {
  const World world = test::RectangleCorridor(10.0, 2.0);
  const LaserSimulator laser(LaserOptions{});
  std::vector<float> incidence;
  const LaserScan scan = laser.CastExact(world, {3.0, 1.0, 0.0}, &incidence);
  ASSERT_EQ(incidence.size(), scan.ranges_m.size());
  EXPECT_NEAR(incidence[BeamAt(scan, M_PI / 2)], 0.0, 1e-4);        // straight at the north wall
  EXPECT_NEAR(incidence[BeamAt(scan, M_PI / 4)], M_PI / 4, 1e-4);   // 45° to it
  EXPECT_NEAR(incidence[BeamAt(scan, 80 * M_PI / 180)], 10 * M_PI / 180, 1e-4);
  LaserOptions short_range;
  short_range.max_range_m = 2.0;
  LaserSimulator(short_range).CastExact(world, {3.0, 1.0, 0.0}, &incidence);
  EXPECT_TRUE(std::isnan(incidence[BeamAt(scan, 0.0)]));            // the east wall is 7 m away
}

TEST(LaserSimulator, TheFittedModelIsSelectedByName) {
  const World world = test::RectangleCorridor(10.0, 2.0);
  LaserOptions options;
  options.error_model = "fitted";
  options.fitted.short_probability = 1.0;  // something just beyond the minimum range on every beam
  options.fitted.short_mean_m = 0.02;
  options.fitted.dropout_probability = options.fitted.dropout_near_probability = 0.0;
  options.fitted.dropout_grazing_probability = 0.0;
  const LaserSimulator laser(options);
  std::mt19937_64 rng(1);
  const Pose2D pose{5.0, 1.0, 0.0};
  const LaserScan exact = laser.CastExact(world, pose);
  const LaserScan scan = laser.Simulate(world, pose, rng);
  for (size_t i = 0; i < scan.ranges_m.size(); ++i) {
    EXPECT_GE(scan.ranges_m[i], options.min_range_m) << i;
    EXPECT_LT(scan.ranges_m[i], exact.ranges_m[i]) << i;
  }
}

TEST(LaserSimulator, DefaultOptionsKeepTheGaussianModel) {
  EXPECT_EQ(LaserOptions{}.error_model, "gaussian");
  EXPECT_FALSE(LaserSimulator(LaserOptions{}).error_model().NeedsIncidence());
}

}  // namespace
}  // namespace doorplate_localization

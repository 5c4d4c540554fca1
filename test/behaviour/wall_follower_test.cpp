#include "doorplate_localization/behaviour/wall_follower.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <stdexcept>

#include "../sim/test_worlds.h"
#include "doorplate_localization/sim/laser_simulator.h"

namespace doorplate_localization {
namespace {

// Closed loop on ground truth: the laser sees the corridor, the follower drives, a unicycle integrates.
Pose2D DriveUntilStopped(const World& world, const WallFollower& follower, Pose2D pose, WallFollowState* state,
                         double* width_m, int max_steps = 4000) {
  const LaserSimulator laser(LaserOptions{});
  std::mt19937_64 rng(5);
  for (int i = 0; i < max_steps; ++i) {
    const LaserScan scan = laser.Simulate(world, pose, rng);
    const CorridorObservation obs = follower.Observe(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad);
    *width_m = obs.width_m;
    const VelocityCommand cmd = follower.Command(obs, state);
    if (*state == WallFollowState::kEndReached) return pose;
    const double dt = 0.05;
    pose.x_m += cmd.linear_mps * dt * std::cos(pose.theta_rad);
    pose.y_m += cmd.linear_mps * dt * std::sin(pose.theta_rad);
    pose.theta_rad = NormalizeAngle(pose.theta_rad + cmd.angular_rps * dt);
  }
  return pose;
}

TEST(WallFollower, ObservesDistanceAngleAndCorridorWidth) {
  const World world = test::RectangleCorridor(20.0, 1.85);
  const WallFollower follower(WallFollowerOptions{});
  const LaserScan scan = LaserSimulator(LaserOptions{}).CastExact(world, {5.0, 0.5, 0.1});
  const CorridorObservation obs = follower.Observe(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad);
  ASSERT_TRUE(obs.wall_found);
  EXPECT_NEAR(obs.wall_distance_m, 0.5, 0.01);
  EXPECT_NEAR(obs.wall_angle_rad, -0.1, 0.01);  // the wall runs 0.1 rad to the robot's right
  EXPECT_NEAR(obs.width_m, 1.85, 0.02);
  // Heading 0.1 rad towards the north wall (1.35 m left): the robot's 0.6 m wide path meets it after
  // (1.35 ∓ 0.3) / sin(0.1) m, 10.5-13.5 m ahead, seen so obliquely that its beams are 2 m apart in range:
  // isolated returns, ignored; the end wall 15 m ahead is what the robot sees ahead.
  EXPECT_NEAR(obs.front_distance_m, 15.0, 0.1);
  // Heading 0.3 rad: the wall is met 3.5-4.4 m ahead and seen well enough.
  const LaserScan steep = LaserSimulator(LaserOptions{}).CastExact(world, {5.0, 0.5, 0.3});
  const CorridorObservation towards = follower.Observe(steep.ranges_m, steep.angle_min_rad, steep.angle_increment_rad);
  EXPECT_GT(towards.front_distance_m, (1.35 - 0.3) / std::sin(0.3) - 0.1);
  EXPECT_LT(towards.front_distance_m, 1.35 / std::sin(0.3));
}

TEST(WallFollower, ConvergesToTheWallDistanceAndStopsAtTheCorridorEnd) {
  const World world = test::RectangleCorridor(15.5, 2.0);
  WallFollowerOptions options;
  options.wall_distance_m = 0.6;
  const WallFollower follower(options);
  WallFollowState state;
  double width = 0;
  const Pose2D end = DriveUntilStopped(world, follower, {1.0, 1.2, 0.3}, &state, &width);
  EXPECT_EQ(state, WallFollowState::kEndReached);
  EXPECT_NEAR(end.y_m, 0.6, 0.05);
  EXPECT_NEAR(end.theta_rad, 0.0, 0.05);
  EXPECT_GT(end.x_m, 15.5 - 0.7 - 0.2);
  EXPECT_NEAR(width, 2.0, 0.05);
}

TEST(WallFollower, FollowsTheLeftWallWhenAsked) {
  const World world = test::RectangleCorridor(12.0, 2.0);
  WallFollowerOptions options;
  options.wall_side = "left";
  options.wall_distance_m = 0.5;
  WallFollowState state;
  double width = 0;
  const Pose2D end = DriveUntilStopped(world, WallFollower(options), {1.0, 1.0, 0.0}, &state, &width);
  EXPECT_EQ(state, WallFollowState::kEndReached);
  EXPECT_NEAR(end.y_m, 2.0 - 0.5, 0.05);
}

TEST(WallFollower, IgnoresNonFiniteRangesAndReportsNoWall) {
  const WallFollower follower(WallFollowerOptions{});
  const std::vector<float> ranges(360, std::numeric_limits<float>::quiet_NaN());
  const CorridorObservation obs = follower.Observe(ranges, -M_PI, 2 * M_PI / 360);
  EXPECT_FALSE(obs.wall_found);
  WallFollowState state;
  const VelocityCommand cmd = follower.Command(obs, &state);
  EXPECT_EQ(state, WallFollowState::kNoWall);
  EXPECT_DOUBLE_EQ(cmd.angular_rps, 0.0);
}

TEST(WallFollower, ASpuriousReturnStraightAheadIsNotTheCorridorsEnd) {
  const World world = test::RectangleCorridor(20.0, 1.85);
  const WallFollower follower(WallFollowerOptions{});
  LaserScan scan = LaserSimulator(LaserOptions{}).CastExact(world, {5.0, 0.6, 0.0});
  const std::size_t ahead = static_cast<std::size_t>(std::lround(-scan.angle_min_rad / scan.angle_increment_rad));
  scan.ranges_m[ahead] = 0.5f;  // one beam: dust, a reflection
  CorridorObservation obs = follower.Observe(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad);
  EXPECT_GT(obs.front_distance_m, 10.0);
  scan.ranges_m[ahead + 1] = 0.52f;  // three neighbouring beams at one range: an object
  scan.ranges_m[ahead + 2] = 0.53f;
  obs = follower.Observe(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad);
  EXPECT_NEAR(obs.front_distance_m, 0.5, 0.01);
}

TEST(WallFollower, InvalidOptionsNameTheField) {
  WallFollowerOptions options;
  options.wall_side = "up";
  try {
    WallFollower follower(options);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("WallFollowerOptions.wall_side"), std::string::npos);
  }
}

}  // namespace
}  // namespace doorplate_localization

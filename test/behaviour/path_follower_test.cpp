#include "doorplate_localization/behaviour/path_follower.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "../sim/test_worlds.h"
#include "doorplate_localization/behaviour/grid_path_planner.h"
#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/simulator.h"

namespace doorplate_localization {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// A scan with no returns (360 beams), or one return straight ahead at `ahead_m`.
struct Scan {
  std::vector<float> ranges = std::vector<float>(360, kInf);
  double angle_min = -M_PI;
  double increment = 2 * M_PI / 360;
};
Scan EmptyScan() { return Scan{}; }
Scan ScanWithReturnAhead(float ahead_m) {
  Scan scan;
  for (int i = 176; i <= 184; ++i) scan.ranges[i] = ahead_m;  // an object ahead (angle 0), several beams wide
  return scan;
}

std::vector<Vec2> StraightPath(Vec2 from, Vec2 to, double spacing_m = 0.1) {
  const double length = Norm(to - from);
  const int n = static_cast<int>(std::ceil(length / spacing_m));
  std::vector<Vec2> path;
  for (int i = 0; i <= n; ++i) path.push_back(from + (static_cast<double>(i) / n) * (to - from));
  return path;
}

VelocityCommand StepAt(PathFollower* follower, const Pose2D& pose, const Scan& scan = EmptyScan()) {
  return follower->Step(scan.ranges, scan.angle_min, scan.increment, pose);
}

// Steps at poses 0.04 m apart (0.4 m/s at 10 Hz) along y = 0, heading +x, from x_from to x_to.
VelocityCommand StepAlongX(PathFollower* follower, double x_from, double x_to) {
  VelocityCommand cmd;
  for (double x = x_from; x <= x_to + 1e-9; x += 0.04) cmd = StepAt(follower, {x, 0.0, 0.0});
  return cmd;
}

TEST(PathFollower, DrivesStraightAlongAStraightPathAtCruiseSpeed) {
  PathFollower follower(PathFollowerOptions{});
  follower.Start(StraightPath({0, 0}, {5, 0}), M_PI / 2);
  const VelocityCommand cmd = StepAt(&follower, {0.0, 0.0, 0.0});
  EXPECT_EQ(follower.state(), PathFollowState::kDriving);
  EXPECT_NEAR(cmd.linear_mps, 0.4, 1e-9);
  EXPECT_NEAR(cmd.angular_rps, 0.0, 1e-9);
  EXPECT_NEAR(follower.remaining_m(), 5.0, 1e-6);
}

TEST(PathFollower, SteersBackTowardsThePathWhenBesideIt) {
  PathFollower follower(PathFollowerOptions{});
  follower.Start(StraightPath({0, 0}, {5, 0}), 0.0);
  EXPECT_LT(StepAt(&follower, {1.0, 0.3, 0.0}).angular_rps, -0.1);  // left of it: turn right
  EXPECT_NEAR(follower.cross_track_m(), 0.3, 1e-6);
}

TEST(PathFollower, TurnsInPlaceFirstWhenThePathStartsBehind) {
  PathFollower follower(PathFollowerOptions{});
  follower.Start(StraightPath({0, 0}, {5, 0}), 0.0);
  const VelocityCommand cmd = StepAt(&follower, {0.0, 0.0, M_PI - 0.2});
  EXPECT_EQ(follower.state(), PathFollowState::kTurning);
  EXPECT_EQ(cmd.linear_mps, 0.0);
  EXPECT_NEAR(std::fabs(cmd.angular_rps), 0.6, 1e-9);
}

TEST(PathFollower, SlowsDownNearTheEndStopsThereAndTurnsToTheGoalHeading) {
  PathFollower follower(PathFollowerOptions{});
  follower.Start(StraightPath({0, 0}, {5, 0}), M_PI / 2);
  StepAlongX(&follower, 0.0, 4.76);
  const VelocityCommand near = StepAt(&follower, {4.8, 0.0, 0.0});
  EXPECT_NEAR(near.linear_mps, 0.8 * 0.2, 1e-6);
  const VelocityCommand at_end = StepAt(&follower, {4.97, 0.0, 0.0});
  EXPECT_EQ(follower.state(), PathFollowState::kFacing);
  EXPECT_EQ(at_end.linear_mps, 0.0);
  EXPECT_GT(at_end.angular_rps, 0.0);  // counter-clockwise to +pi/2
  StepAt(&follower, {4.97, 0.0, M_PI / 2 - 0.02});
  EXPECT_EQ(follower.state(), PathFollowState::kArrived);
  EXPECT_FALSE(follower.active());
  EXPECT_EQ(StepAt(&follower, {4.97, 0.0, M_PI / 2}).linear_mps, 0.0);
}

TEST(PathFollower, AnEndJustBehindTheRobotCountsAsReached) {
  PathFollower follower(PathFollowerOptions{});
  follower.Start(StraightPath({0, 0}, {5, 0}), 0.0);
  StepAlongX(&follower, 0.0, 4.92);
  StepAt(&follower, {5.1, 0.05, 0.0});  // overshot by 0.1 m
  EXPECT_EQ(follower.state(), PathFollowState::kArrived);  // heading already right
}

TEST(PathFollower, StopsForAnObstacleAheadAndDrivesOnOnceItIsGone) {
  PathFollower follower(PathFollowerOptions{});
  follower.Start(StraightPath({0, 0}, {5, 0}), 0.0);
  StepAlongX(&follower, 0.0, 1.0);
  const VelocityCommand blocked = StepAt(&follower, {1.0, 0.0, 0.0}, ScanWithReturnAhead(0.3f));
  EXPECT_EQ(follower.state(), PathFollowState::kBlocked);
  EXPECT_EQ(blocked.linear_mps, 0.0);
  EXPECT_EQ(blocked.angular_rps, 0.0);
  EXPECT_TRUE(follower.active());
  EXPECT_GT(StepAt(&follower, {1.0, 0.0, 0.0}, ScanWithReturnAhead(0.5f)).linear_mps, 0.0);
  EXPECT_EQ(follower.state(), PathFollowState::kDriving);
}

TEST(PathFollower, NeverGoesBackAlongThePathAfterAJumpOfThePose) {
  PathFollower follower(PathFollowerOptions{});
  follower.Start(StraightPath({0, 0}, {5, 0}), 0.0);
  StepAlongX(&follower, 0.0, 3.0);
  StepAt(&follower, {2.5, 0.0, 0.0});  // the estimate jumped back 0.5 m
  EXPECT_NEAR(follower.remaining_m(), 2.0, 1e-6);
}

TEST(PathFollower, ANonFinitePoseStopsWithoutEndingAndBadInputsThrow) {
  PathFollower follower(PathFollowerOptions{});
  follower.Start(StraightPath({0, 0}, {5, 0}), 0.0);
  const VelocityCommand cmd = StepAt(&follower, {std::nan(""), 0.0, 0.0});
  EXPECT_EQ(cmd.linear_mps, 0.0);
  EXPECT_TRUE(follower.active());
  EXPECT_THROW(follower.Start({}, 0.0), std::invalid_argument);
  PathFollowerOptions o;
  o.resume_driving_rad = 1.5;  // > rotate_in_place_rad
  try {
    PathFollower bad(o);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("resume_driving_rad"), std::string::npos);
  }
  o = {};
  o.min_approach_speed_mps = 1.0;
  EXPECT_THROW(PathFollower{o}, std::invalid_argument);
}

// An L of 2 m corridors: along x from 0 to 8 (y in [0, 2]), then up along y (x in [6, 8]) to y = 8.
World LCorridorWorld() { return test::LCorridor(8.0, 8.0); }

TEST(PathFollower, InTheSimulatorDrivesRoundTheCornerOfAnLCorridorToTheGoal) {
  const World world = LCorridorWorld();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  const GridPathPlanner planner(GridPathPlannerOptions{}, grid);
  const Pose2D goal{7.4, 6.5, 0.0};  // facing the east wall, 0.6 m from it
  const GridPath path = planner.Plan({1.0, 1.0}, goal.Position());
  ASSERT_TRUE(path.found) << path.failure;

  Simulator sim(world, SimulatorOptions{});
  sim.Teleport({1.0, 1.0, 0.1});
  PathFollower follower(PathFollowerOptions{});
  follower.Start(path.waypoints, goal.theta_rad);
  bool bumped = false;
  double closest_to_corner_m = 1e9;
  for (int step = 0; sim.time_s() < 120.0; ++step) {
    if (step % 10 == 0) {
      const LaserScan scan = sim.Scan();
      const VelocityCommand cmd = follower.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad,
                                                sim.true_pose());
      if (!follower.active()) break;
      sim.SetCommand(cmd.linear_mps, cmd.angular_rps);
    }
    sim.Step();
    bumped = bumped || sim.bumped();
    closest_to_corner_m = std::min(closest_to_corner_m, Norm(sim.true_pose().Position() - Vec2{6, 2}));
  }
  EXPECT_EQ(follower.state(), PathFollowState::kArrived);
  EXPECT_FALSE(bumped);
  EXPECT_GT(closest_to_corner_m, 0.5);
  EXPECT_LT(Norm(sim.true_pose().Position() - goal.Position()), 0.1);
  EXPECT_LT(std::fabs(NormalizeAngle(sim.true_pose().theta_rad - goal.theta_rad)), 0.08);
  EXPECT_LT(sim.time_s(), 60.0);
}

}  // namespace
}  // namespace doorplate_localization

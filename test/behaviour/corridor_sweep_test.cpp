#include "doorplate_localization/behaviour/corridor_sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "../sim/test_worlds.h"
#include "doorplate_localization/sim/laser_simulator.h"
#include "doorplate_localization/sim/simulator.h"

namespace doorplate_localization {
namespace {

// An 8 m × 2 m corridor with one plate in the middle of each long wall.
World CorridorWithTwoPlates() {
  World world = test::RectangleCorridor(8.0, 2.0);
  for (const int wall : {0, 1}) {  // south (corridor on its left), north (corridor on its right)
    TextSign plate;
    plate.text = wall == 0 ? "101" : "102";
    plate.wall_index = wall;
    plate.offset_m = 4.0;
    plate.corridor_side_left = world.walls[wall].corridor_side_left;
    world.signs.push_back(plate);
  }
  BuildSurfaces(world);
  return world;
}

struct SweepRun {
  std::vector<SweepPhase> phases;  // each phase once, in the order entered
  Pose2D end_pose;
  Pose2D pose_at_turn_end;
  Pose2D pose_at_turn_start;
  bool bumped = false;
  // Per plate (world.signs order): seen inside the image during kFollowOut / kFollowBack.
  std::vector<bool> seen_out, seen_back;
};

// Closed loop in the Simulator: physics at 100 Hz, laser and sweep at 10 Hz, odometry from the simulator.
SweepRun RunSweep(const World& world, const CorridorSweepOptions& options, double max_time_s = 200.0) {
  Simulator sim(world, SimulatorOptions{});
  CorridorSweep sweep(options);
  SweepRun run;
  run.seen_out.assign(world.signs.size(), false);
  run.seen_back.assign(world.signs.size(), false);
  run.phases.push_back(sweep.phase());
  const CameraIntrinsics& k = sim.camera().intrinsics();
  for (int step = 0; sim.time_s() < max_time_s; ++step) {
    if (step % 10 == 0) {
      const SimulatedScan scan = sim.Scan();
      const VelocityCommand cmd = sweep.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, sim.odom_pose());
      if (sweep.phase() != run.phases.back()) {
        if (sweep.phase() == SweepPhase::kTurnAround) run.pose_at_turn_start = sim.true_pose();
        if (run.phases.back() == SweepPhase::kTurnAround) run.pose_at_turn_end = sim.true_pose();
        run.phases.push_back(sweep.phase());
      }
      if (sweep.phase() == SweepPhase::kDone) break;
      sim.SetCommand(cmd.linear_mps, cmd.angular_rps);
    }
    sim.Step();
    run.bumped = run.bumped || sim.bumped();
    for (size_t i = 0; i < world.signs.size(); ++i) {
      const Vec2 p = world.SignPosition(world.signs[i]);
      cv::Point2d px;
      if (!sim.camera().Project(sim.true_pose(), {p.x, p.y, world.signs[i].center_height_m}, &px)) continue;
      if (px.x < 0 || px.x >= k.width_px || px.y < 0 || px.y >= k.height_px) continue;
      if (sweep.phase() == SweepPhase::kFollowOut) run.seen_out[i] = true;
      if (sweep.phase() == SweepPhase::kFollowBack) run.seen_back[i] = true;
    }
  }
  run.end_pose = sim.true_pose();
  return run;
}

TEST(CorridorSweep, GoesOutTurnsAroundAndComesBackNearTheStart) {
  const World world = CorridorWithTwoPlates();
  const SweepRun run = RunSweep(world, CorridorSweepOptions{});
  const std::vector<SweepPhase> expected = {SweepPhase::kFollowOut, SweepPhase::kTurnAround, SweepPhase::kFollowBack,
                                            SweepPhase::kDone};
  EXPECT_EQ(run.phases, expected);
  EXPECT_FALSE(run.bumped);
  // Out along the right (south) wall at 0.6 m, back along the north wall at 0.6 m, ending 0.7 m (the
  // end stop) plus the laser's view of the end wall before the west wall: near the start's x.
  EXPECT_NEAR(run.pose_at_turn_start.y_m, 0.6, 0.1);
  EXPECT_GT(run.pose_at_turn_start.x_m, 8.0 - 0.7 - 0.2);
  EXPECT_NEAR(run.end_pose.x_m, world.start_pose.x_m, 0.5);
  EXPECT_NEAR(run.end_pose.y_m, 2.0 - 0.6, 0.1);
  EXPECT_NEAR(std::fabs(NormalizeAngle(run.end_pose.theta_rad)), M_PI, 0.1);
}

TEST(CorridorSweep, TheCameraSeesTheFarWallOutAndTheOtherWallBack) {
  const World world = CorridorWithTwoPlates();
  const SweepRun run = RunSweep(world, CorridorSweepOptions{});
  // The camera looks left: north plate (index 1) on the way out, south plate (index 0) on the way back.
  EXPECT_TRUE(run.seen_out[1]);
  EXPECT_FALSE(run.seen_out[0]);
  EXPECT_TRUE(run.seen_back[0]);
  EXPECT_FALSE(run.seen_back[1]);
}

TEST(CorridorSweep, TheTurnEndsWhenTheWallIsParallelAgain) {
  const SweepRun run = RunSweep(CorridorWithTwoPlates(), CorridorSweepOptions{});
  const double turned = NormalizeAngle(run.pose_at_turn_end.theta_rad - run.pose_at_turn_start.theta_rad);
  EXPECT_NEAR(std::fabs(turned), M_PI, 0.12);
  // In place: the position did not change during the turn.
  EXPECT_NEAR(Norm(run.pose_at_turn_end.Position() - run.pose_at_turn_start.Position()), 0.0, 1e-6);
}

TEST(CorridorSweep, FollowsTheLeftWallAndTurnsClockwiseWhenAsked) {
  World world = test::RectangleCorridor(8.0, 2.0);
  CorridorSweepOptions options;
  options.follower.wall_side = "left";
  const SweepRun run = RunSweep(world, options);
  ASSERT_EQ(run.phases.back(), SweepPhase::kDone);
  EXPECT_NEAR(run.pose_at_turn_start.y_m, 2.0 - 0.6, 0.1);
  EXPECT_NEAR(run.end_pose.y_m, 0.6, 0.1);
}

TEST(CorridorSweep, GoesStraightPastAnAlcoveInTheFollowedWall) {
  // 12 m × 2 m with a 2 m wide, 1.2 m deep alcove in the south wall from x = 5 to 7.
  World world;
  world.walls = {
      {"south_a", {{0, 0}, {5, 0}}, true, {200, 200, 200}},     {"alcove_w", {{5, 0}, {5, -1.2}}, false, {200, 200, 200}},
      {"alcove_s", {{5, -1.2}, {7, -1.2}}, true, {200, 200, 200}}, {"alcove_e", {{7, -1.2}, {7, 0}}, false, {200, 200, 200}},
      {"south_b", {{7, 0}, {12, 0}}, true, {200, 200, 200}},    {"north", {{0, 2}, {12, 2}}, false, {200, 200, 200}},
      {"west", {{0, 0}, {0, 2}}, false, {200, 200, 200}},       {"east", {{12, 0}, {12, 2}}, true, {200, 200, 200}},
  };
  world.start_pose = {0.7, 0.6, 0.0};
  BuildSurfaces(world);
  const SweepRun run = RunSweep(world, CorridorSweepOptions{});
  ASSERT_EQ(run.phases.back(), SweepPhase::kDone);
  EXPECT_FALSE(run.bumped);
  EXPECT_NEAR(run.pose_at_turn_start.y_m, 0.6, 0.1);  // not pulled into the alcove
  EXPECT_GT(run.pose_at_turn_start.x_m, 12.0 - 0.7 - 0.2);
  EXPECT_NEAR(run.end_pose.y_m, 1.4, 0.1);
}

// Exact scans at chosen poses of an 8 m × 2 m corridor drive the phases step by step.
TEST(CorridorSweep, EndsDoneWithAZeroCommandAtTheSecondEndAndResetStartsAgain) {
  const World world = test::RectangleCorridor(8.0, 2.0);
  const LaserSimulator laser(LaserOptions{});
  CorridorSweep sweep(CorridorSweepOptions{});
  auto step = [&](const Pose2D& true_pose, double odom_yaw_rad) {
    const SimulatedScan scan = laser.CastExact(world, true_pose);
    return sweep.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, {0.0, 0.0, odom_yaw_rad});
  };
  VelocityCommand cmd = step({7.4, 0.6, 0.0}, 0.0);  // 0.6 m before the east wall: the first leg ends
  EXPECT_EQ(sweep.phase(), SweepPhase::kTurnAround);
  EXPECT_DOUBLE_EQ(cmd.linear_mps, 0.0);
  EXPECT_GT(cmd.angular_rps, 0.0);  // counter-clockwise, away from the right wall
  step({7.4, 0.6, M_PI / 2}, M_PI / 2);
  EXPECT_EQ(sweep.phase(), SweepPhase::kTurnAround);  // half way
  cmd = step({7.4, 0.6, M_PI}, M_PI);
  EXPECT_EQ(sweep.phase(), SweepPhase::kFollowBack);  // turned pi, north wall parallel on the right
  EXPECT_GT(cmd.linear_mps, 0.0);
  cmd = step({0.6, 1.4, M_PI}, M_PI);  // 0.6 m before the west wall
  EXPECT_EQ(sweep.phase(), SweepPhase::kDone);
  EXPECT_DOUBLE_EQ(cmd.linear_mps, 0.0);
  EXPECT_DOUBLE_EQ(cmd.angular_rps, 0.0);
  cmd = step({4.0, 1.4, M_PI}, M_PI);  // stays done even with the corridor open ahead
  EXPECT_EQ(sweep.phase(), SweepPhase::kDone);
  EXPECT_DOUBLE_EQ(cmd.linear_mps, 0.0);
  sweep.Reset();
  EXPECT_EQ(sweep.phase(), SweepPhase::kFollowOut);
  EXPECT_GT(step({4.0, 0.6, 0.0}, 0.0).linear_mps, 0.0);
}

TEST(CorridorSweep, InvalidOptionsNameTheField) {
  CorridorSweepOptions options;
  options.turn_speed_rps = 0.0;
  try {
    CorridorSweep sweep(options);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("CorridorSweepOptions.turn_speed_rps"), std::string::npos);
  }
  options = CorridorSweepOptions{};
  options.follower.cruise_speed_mps = -1.0;
  EXPECT_THROW(CorridorSweep{options}, std::invalid_argument);
  EXPECT_STREQ(SweepPhaseName(SweepPhase::kFollowBack), "follow_back");
}

}  // namespace
}  // namespace doorplate_localization

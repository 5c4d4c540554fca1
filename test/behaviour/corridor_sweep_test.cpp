#include "doorplate_localization/behaviour/corridor_sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <stdexcept>
#include <vector>

#include "../sim/test_worlds.h"
#include "doorplate_localization/sim/laser_simulator.h"
#include "doorplate_localization/sim/simulator.h"
#include "doorplate_localization/sim/world_loader.h"

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

// A person in the scan: a 0.4 m wide body (flat front) 0.5 m straight ahead.
void AddPersonAhead(LaserScan* scan) {
  for (std::size_t i = 0; i < scan->ranges_m.size(); ++i) {
    const double a = scan->angle_min_rad + static_cast<double>(i) * scan->angle_increment_rad;
    if (std::cos(a) > 0 && std::fabs(std::tan(a)) * 0.5 <= 0.2) scan->ranges_m[i] = static_cast<float>(0.5 / std::cos(a));
  }
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
      const LaserScan scan = sim.Scan();
      const VelocityCommand cmd =
          sweep.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, sim.odom_pose(), sim.time_s());
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
  CorridorSweepOptions options;
  options.end_confirm_s = 0.0;  // each end at once (the wait is the next test's)
  CorridorSweep sweep(options);
  auto step = [&](const Pose2D& true_pose, double odom_yaw_rad) {
    const LaserScan scan = laser.CastExact(world, true_pose);
    return sweep.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, {0.0, 0.0, odom_yaw_rad}, 0.0);
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

// A person crossing the lane (or a few spurious returns) 0.5 m ahead stops the robot but does not end the leg
// when it clears within end_confirm_s; the end wall, still there after end_confirm_s, does.
TEST(CorridorSweep, WaitsForSomethingAheadToClearBeforeEndingALeg) {
  const World world = test::RectangleCorridor(8.0, 2.0);
  const LaserSimulator laser(LaserOptions{});
  CorridorSweepOptions options;
  options.end_confirm_s = 4.0;
  CorridorSweep sweep(options);
  auto step = [&](const Pose2D& true_pose, double time_s, bool person_ahead) {
    LaserScan scan = laser.CastExact(world, true_pose);
    if (person_ahead) AddPersonAhead(&scan);
    return sweep.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, {0.0, 0.0, 0.0}, time_s);
  };
  EXPECT_GT(step({3.0, 0.6, 0.0}, 0.0, false).linear_mps, 0.0);
  VelocityCommand cmd = step({3.0, 0.6, 0.0}, 0.1, true);
  EXPECT_EQ(sweep.phase(), SweepPhase::kFollowOut);
  EXPECT_DOUBLE_EQ(cmd.linear_mps, 0.0);  // stops before it
  EXPECT_DOUBLE_EQ(step({3.0, 0.6, 0.0}, 3.9, true).linear_mps, 0.0);
  EXPECT_EQ(sweep.phase(), SweepPhase::kFollowOut);  // 3.8 s < end_confirm_s
  EXPECT_GT(step({3.0, 0.6, 0.0}, 4.0, false).linear_mps, 0.0);  // it has gone: on along the wall
  EXPECT_EQ(sweep.phase(), SweepPhase::kFollowOut);
  // Someone stands in the lane: narrower than end_min_width_m, so the robot waits narrow_end_confirm_s (30 s)
  // for them to walk on, and only then takes them for the corridor's end.
  EXPECT_DOUBLE_EQ(step({5.0, 0.6, 0.0}, 5.0, true).linear_mps, 0.0);
  EXPECT_DOUBLE_EQ(step({5.0, 0.6, 0.0}, 30.0, true).linear_mps, 0.0);
  EXPECT_EQ(sweep.phase(), SweepPhase::kFollowOut);  // 25 s: still waiting
  EXPECT_GT(step({5.0, 0.6, 0.0}, 31.0, false).linear_mps, 0.0);  // gone after 26 s: on along the wall
  EXPECT_EQ(sweep.phase(), SweepPhase::kFollowOut);
  // The east wall 0.6 m ahead spans the corridor: a stop for end_confirm_s only, then the turn.
  EXPECT_DOUBLE_EQ(step({7.4, 0.6, 0.0}, 40.0, false).linear_mps, 0.0);
  step({7.4, 0.6, 0.0}, 43.9, false);
  EXPECT_EQ(sweep.phase(), SweepPhase::kFollowOut);
  cmd = step({7.4, 0.6, 0.0}, 44.0, false);
  EXPECT_EQ(sweep.phase(), SweepPhase::kTurnAround);
  EXPECT_GT(cmd.angular_rps, 0.0);
}

TEST(CorridorSweep, APersonWhoNeverLeavesTheLaneEndsTheLegAfterTheLongWait) {
  const World world = test::RectangleCorridor(8.0, 2.0);
  LaserScan scan = LaserSimulator(LaserOptions{}).CastExact(world, {3.0, 0.6, 0.0});
  AddPersonAhead(&scan);
  CorridorSweep sweep(CorridorSweepOptions{});
  for (double t = 0.0; t < 29.95; t += 0.1) sweep.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, {}, t);
  EXPECT_EQ(sweep.phase(), SweepPhase::kFollowOut);
  sweep.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, {}, 30.1);
  EXPECT_EQ(sweep.phase(), SweepPhase::kTurnAround);
}

TEST(BlockingWidth, AnEndWallSpansTheCorridorAPersonDoesNot) {
  const World world = test::RectangleCorridor(8.0, 2.0);
  const LaserSimulator laser(LaserOptions{});
  const LaserScan end = laser.CastExact(world, {7.4, 0.6, 0.0});  // the east wall 0.6 m ahead
  EXPECT_NEAR(BlockingWidth(end.ranges_m, end.angle_min_rad, end.angle_increment_rad), 2.0, 0.05);
  LaserScan person = laser.CastExact(world, {3.0, 1.0, 0.0});  // mid-corridor
  AddPersonAhead(&person);
  EXPECT_NEAR(BlockingWidth(person.ranges_m, person.angle_min_rad, person.angle_increment_rad), 0.4, 0.05);
  // Nothing ahead within ±45°: 0.
  const std::vector<float> none(360, std::numeric_limits<float>::infinity());
  EXPECT_EQ(BlockingWidth(none, -M_PI, 2 * M_PI / 360), 0.0);
}

// The realistic corridor (worlds/paper_real_corridor_realistic.yaml): a glazed day room on the north wall,
// people walking, the laser's spurious returns. With the old rules (a leg ended at the first return ahead)
// 7 of Table II's 10 sweeps ended early there, at people, spurious returns or the glass (the wall fit took
// the room behind it and steered the robot into it). Seeds 4 and 9 here still failed with the wait and the
// direction check alone (the gate had locked onto the room); seed 18 ended its way back at a walker who stood
// 20 s in the lane (the world's pause_s) until a narrow thing ahead was given narrow_end_confirm_s. Seeds
// 1-40 all pass with every rule (checked once; four run here). Along the way each leg keeps its wall
// distance: these four seeds strayed 0.44-0.72 m from it on the way back (towards the other wall's plates, out
// of the camera's band) after a leg direction taken from one fit across a radiator's end.
TEST(CorridorSweep, SweepsTheWholeRealisticCorridorPastGlassAndPeople) {
  const World world = LoadWorldFile(std::string(DOORPLATE_SOURCE_DIR) + "/worlds/paper_real_corridor_realistic.yaml");
  for (const std::uint64_t seed : {2, 3, 4, 9}) {
    SimulatorOptions sim_options;
    sim_options.seed = seed;
    Simulator sim(world, sim_options);
    CorridorSweepOptions options;
    CorridorSweep sweep(options);
    double turn_x_m = 0.0, leg_start_s = 0.0, max_stray_m = 0.0;
    SweepPhase phase = sweep.phase();
    const int steps_per_scan =
        static_cast<int>(std::lround(1.0 / (world.sensors.laser.rate_hz * sim_options.physics_step_s)));
    for (long long step = 0; sim.time_s() < 400.0 && sweep.phase() != SweepPhase::kDone; ++step) {
      if (step % steps_per_scan == 0) {
        const LaserScan scan = sim.Scan();
        const VelocityCommand cmd =
            sweep.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, sim.odom_pose(), sim.time_s());
        if (sweep.phase() == SweepPhase::kTurnAround && turn_x_m == 0.0) turn_x_m = sim.true_pose().x_m;
        if (sweep.phase() != phase) phase = sweep.phase(), leg_start_s = sim.time_s();
        const Pose2D pose = sim.true_pose();
        // Along a leg (past its first 8 s, the approach, and clear of the clutter at the ends): south wall out,
        // north wall (y = 1.85 m) back.
        if (phase != SweepPhase::kTurnAround && sim.time_s() - leg_start_s > 8.0 && pose.x_m > 3.5 && pose.x_m < 40.0) {
          const double wall_distance_m = phase == SweepPhase::kFollowOut ? pose.y_m : 1.85 - pose.y_m;
          max_stray_m = std::max(max_stray_m, std::fabs(wall_distance_m - options.follower.wall_distance_m));
        }
        sim.SetCommand(cmd.linear_mps, cmd.angular_rps);
      }
      sim.Step();
    }
    EXPECT_LT(max_stray_m, 0.25) << "seed " << seed;
    EXPECT_EQ(sweep.phase(), SweepPhase::kDone) << "seed " << seed;
    EXPECT_GT(turn_x_m, 40.0) << "seed " << seed;               // the bed at the east end is at 41.3 m
    EXPECT_LT(sim.true_pose().x_m, 3.5) << "seed " << seed;    // back at the west end (bench and plant)
  }
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
  options = CorridorSweepOptions{};
  options.end_confirm_s = -1.0;
  EXPECT_THROW(CorridorSweep{options}, std::invalid_argument);
  options = CorridorSweepOptions{};
  options.max_wall_turn_rad = 2.0;
  EXPECT_THROW(CorridorSweep{options}, std::invalid_argument);
  options = CorridorSweepOptions{};
  options.wall_gate_reset_s = 0.0;
  EXPECT_THROW(CorridorSweep{options}, std::invalid_argument);
  options = CorridorSweepOptions{};
  options.wall_direction_gain = 0.0;
  EXPECT_THROW(CorridorSweep{options}, std::invalid_argument);
  options = CorridorSweepOptions{};
  options.wall_reacquire_s = options.wall_gate_reset_s;
  EXPECT_THROW(CorridorSweep{options}, std::invalid_argument);
  options = CorridorSweepOptions{};
  options.end_min_width_m = NAN;
  EXPECT_THROW(CorridorSweep{options}, std::invalid_argument);
  options = CorridorSweepOptions{};
  options.narrow_end_confirm_s = options.end_confirm_s - 1.0;
  EXPECT_THROW(CorridorSweep{options}, std::invalid_argument);
  options = CorridorSweepOptions{};
  options.end_max_wall_angle_rad = M_PI / 2;
  EXPECT_THROW(CorridorSweep{options}, std::invalid_argument);
  EXPECT_STREQ(SweepPhaseName(SweepPhase::kFollowBack), "follow_back");
}

}  // namespace
}  // namespace doorplate_localization

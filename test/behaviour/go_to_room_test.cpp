#include "doorplate_localization/behaviour/go_to_room.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "../sim/test_worlds.h"
#include "doorplate_localization/behaviour/plate_route.h"
#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/simulator.h"

namespace doorplate_localization {
namespace {

// A 12 m × 2 m corridor: "102", "104", "106" on the south wall at x = 3, 6, 9; "101", "103" on the north
// wall at x = 4.5, 7.5.
World PlateCorridor() {
  World world = test::RectangleCorridor(12.0, 2.0);
  const auto add = [&world](const char* text, int wall, double offset_m) {
    TextSign plate;
    plate.text = text;
    plate.wall_index = wall;
    plate.offset_m = offset_m;
    plate.corridor_side_left = world.walls[wall].corridor_side_left;
    world.signs.push_back(plate);
  };
  add("102", 0, 3.0);
  add("104", 0, 6.0);
  add("106", 0, 9.0);
  add("101", 1, 4.5);
  add("103", 1, 7.5);
  BuildSurfaces(world);
  return world;
}

struct DriveRun {
  std::vector<GoToRoomState> states;  // each state once, in the order entered
  bool bumped = false;
};

// Closed loop in the Simulator (physics 100 Hz, laser and controller 10 Hz). The controller gets the true
// pose (a converged localizer in the map frame) or, with `use_odometry`, the simulator's odometry.
DriveRun Drive(Simulator* sim, GoToRoom* go, bool use_odometry, double max_time_s = 120.0) {
  DriveRun run;
  run.states.push_back(go->state());
  const double end_s = sim->time_s() + max_time_s;
  for (int step = 0; sim->time_s() < end_s; ++step) {
    if (step % 10 == 0) {
      const LaserScan scan = sim->Scan();
      const Pose2D pose = use_odometry ? sim->odom_pose() : sim->true_pose();
      const VelocityCommand cmd =
          go->Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, pose, sim->time_s());
      if (go->state() != run.states.back()) run.states.push_back(go->state());
      if (!go->active()) break;
      sim->SetCommand(cmd.linear_mps, cmd.angular_rps);
    }
    sim->Step();
    run.bumped = run.bumped || sim->bumped();
  }
  sim->SetCommand(0.0, 0.0);
  return run;
}

const RoomGoalPlanner& Planner() {
  static const RoomGoalPlanner planner(RoomGoalPlannerOptions{}, GroundTruthTextMap(PlateCorridor()), "plates");
  return planner;
}

// The robot's true pose relative to the plate: along the wall, distance from the wall, yaw error to facing it.
struct PlateOffset {
  double along_m, from_wall_m, yaw_error_rad;
};
PlateOffset OffsetFrom(const TextMap& map, int landmark, const Pose2D& robot) {
  const Pose2D& plate = map.landmarks[static_cast<size_t>(landmark)].pose;
  const Pose2D local = plate.Between(robot);  // x: out of the wall, y: along it
  return {local.y_m, local.x_m, NormalizeAngle(robot.theta_rad - (plate.theta_rad + M_PI))};
}

TEST(GoToRoom, DrivesToAPlateAheadOnTheOtherWallAndStopsFacingTheDoor) {
  Simulator sim(PlateCorridor(), SimulatorOptions{});
  sim.Teleport({0.6, 0.6, 0.0});  // near the west wall, which the left side sector sees at first
  GoToRoom go(GoToRoomOptions{});
  const RoomGoalResult plan = Planner().Plan("103", sim.true_pose());
  ASSERT_TRUE(plan.goal) << plan.refusal;
  go.Start(*plan.goal);
  const DriveRun run = Drive(&sim, &go, /*use_odometry=*/false);
  const std::vector<GoToRoomState> expected = {GoToRoomState::kTurning, GoToRoomState::kDriving,
                                               GoToRoomState::kFacing, GoToRoomState::kArrived};
  EXPECT_EQ(run.states, expected);
  EXPECT_FALSE(run.bumped);
  const PlateOffset offset = OffsetFrom(Planner().map(), plan.goal->landmark, sim.true_pose());
  EXPECT_NEAR(offset.along_m, 0.0, go.options().arrive_tolerance_m);
  EXPECT_NEAR(offset.from_wall_m, 0.6, 0.1);  // crossed the corridor to follow the north wall
  EXPECT_NEAR(offset.yaw_error_rad, 0.0, go.options().face_tolerance_rad);
  EXPECT_EQ(go.Status().rfind("arrived: room 103, ", 0), 0u) << go.Status();
}

TEST(GoToRoom, TurnsAroundFirstWhenTheGoalIsBehind) {
  Simulator sim(PlateCorridor(), SimulatorOptions{});
  sim.Teleport({10.0, 0.6, 0.0});
  GoToRoom go(GoToRoomOptions{});
  const RoomGoalResult plan = Planner().Plan("104", sim.true_pose());
  ASSERT_TRUE(plan.goal) << plan.refusal;
  go.Start(*plan.goal);
  GoToRoomState first = go.state();
  const std::vector<float> no_scan;
  const VelocityCommand turn = go.Step(no_scan, 0.0, 0.01, sim.true_pose(), 0.0);
  EXPECT_EQ(first, GoToRoomState::kTurning);
  EXPECT_EQ(go.state(), GoToRoomState::kTurning);
  EXPECT_EQ(turn.linear_mps, 0.0);  // in place
  EXPECT_NE(turn.angular_rps, 0.0);
  const DriveRun run = Drive(&sim, &go, /*use_odometry=*/false);
  EXPECT_EQ(run.states.back(), GoToRoomState::kArrived);
  EXPECT_FALSE(run.bumped);
  const PlateOffset offset = OffsetFrom(Planner().map(), plan.goal->landmark, sim.true_pose());
  EXPECT_NEAR(offset.along_m, 0.0, go.options().arrive_tolerance_m);
  EXPECT_NEAR(offset.from_wall_m, 0.6, 0.1);
  EXPECT_NEAR(offset.yaw_error_rad, 0.0, go.options().face_tolerance_rad);
}

// The robot has just read "102" on its left while driving west along the north wall; room "106" is 6 m
// behind by the adjacent distances (eq. 15). Returns the true offset from plate "106" at arrival.
PlateOffset DriveByEq15(const World& world) {
  Simulator sim(world, SimulatorOptions{});
  sim.Teleport({3.0, 1.4, M_PI});
  MatchedPlateReading reading;
  reading.landmark = Planner().map().Find("102").front();
  reading.odom_pose = sim.odom_pose();
  reading.plate_on_left = true;
  const RoomGoalResult plan = PlanFromReading(Planner(), "106", reading);
  EXPECT_TRUE(plan.goal) << plan.refusal;
  if (!plan.goal) return {};
  GoToRoom go(GoToRoomOptions{});
  go.Start(*plan.goal);
  const DriveRun run = Drive(&sim, &go, /*use_odometry=*/true);
  EXPECT_EQ(run.states.front(), GoToRoomState::kTurning);  // 106 is behind
  EXPECT_EQ(run.states.back(), GoToRoomState::kArrived);
  EXPECT_FALSE(run.bumped);
  const PlateOffset offset = OffsetFrom(Planner().map(), plan.goal->landmark, sim.true_pose());
  std::printf("%s; true offset along %.3f m, from wall %.3f m, yaw %.3f rad\n", plan.goal->note.c_str(),
              offset.along_m, offset.from_wall_m, offset.yaw_error_rad);
  return offset;
}

TEST(GoToRoom, TheEq15FallbackDrivesTheAdjacentDistancesByOdometry) {
  World exact = PlateCorridor();
  exact.sensors.odometry = OdometryNoiseOptions{0, 0, 0, 0, 0, 0, 50.0, {}};
  const PlateOffset offset = DriveByEq15(exact);
  EXPECT_NEAR(offset.along_m, 0.0, GoToRoomOptions{}.arrive_tolerance_m + 0.01);
  EXPECT_NEAR(offset.from_wall_m, 0.6, 0.05);  // crossed over to the plates' wall
  EXPECT_NEAR(offset.yaw_error_rad, 0.0, GoToRoomOptions{}.face_tolerance_rad);
}

TEST(GoToRoom, WithNoisyOdometryTheEq15FallbackErrsOnlyByTheOdometryError) {
  // The world's default odometry: 2 % scale error (0.12 m over the 6 m), a yaw error after the turn of about
  // sqrt(alpha1 * pi) = 0.056 rad that shows the 0.8 m crossing of the corridor as 0.8 * sin(3 sigma) = 0.13 m
  // along at worst, and 3 sigma of the random translation, 3 sqrt(alpha3 * 7 m) = 0.16 m: at most 0.41 m.
  const PlateOffset offset = DriveByEq15(PlateCorridor());
  EXPECT_NEAR(offset.along_m, 0.0, 0.41);
  EXPECT_NEAR(offset.from_wall_m, 0.6, 0.1);
  EXPECT_NEAR(offset.yaw_error_rad, 0.0, 3 * std::sqrt(0.001 * 2 * M_PI) + 0.05);  // two turns in odometry
}

TEST(GoToRoom, FailsWhenTheCorridorEndsBeforeTheGoal) {
  Simulator sim(PlateCorridor(), SimulatorOptions{});
  sim.Teleport({8.0, 0.6, 0.0});
  GoToRoom go(GoToRoomOptions{});
  RoomGoal beyond;
  beyond.room = "999";
  beyond.pose = {14.0, 0.6, -M_PI / 2};  // 2 m past the east wall
  go.Start(beyond);
  const DriveRun run = Drive(&sim, &go, /*use_odometry=*/false);
  EXPECT_EQ(run.states.back(), GoToRoomState::kFailed);
  EXPECT_FALSE(run.bumped);
  EXPECT_NE(go.reason().find("stopped by a wall or obstacle"), std::string::npos) << go.reason();
  EXPECT_EQ(go.Status().rfind("failed: room 999: stopped by a wall", 0), 0u) << go.Status();
}

// Someone stands 0.4 m before the robot from 3 s after the start until `until_s` (the beams within ±20° of
// straight ahead end on them). Returns the final state and the time it was reached.
std::pair<GoToRoomState, double> DriveWithSomeoneAhead(double until_s, std::string* reason) {
  Simulator sim(PlateCorridor(), SimulatorOptions{});
  sim.Teleport({0.6, 0.6, 0.0});
  GoToRoom go(GoToRoomOptions{});
  const RoomGoalResult plan = Planner().Plan("103", sim.true_pose());
  go.Start(*plan.goal);
  for (int step = 0; sim.time_s() < 120.0 && go.active(); ++step) {
    if (step % 10 == 0) {
      LaserScan scan = sim.Scan();
      if (sim.time_s() >= 3.0 && sim.time_s() < until_s) {
        for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
          const double a = scan.angle_min_rad + static_cast<double>(i) * scan.angle_increment_rad;
          if (std::fabs(NormalizeAngle(a)) < 0.35) scan.ranges_m[i] = 0.4f;
        }
      }
      const VelocityCommand cmd =
          go.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, sim.true_pose(), sim.time_s());
      sim.SetCommand(cmd.linear_mps, cmd.angular_rps);
    }
    sim.Step();
  }
  *reason = go.reason();
  return {go.state(), sim.time_s()};
}

// A demo on the realistic corridor failed its goal the moment a person walked past in front of the robot: the
// robot now stops and waits blocked_wait_s (10 s) before something ahead fails the goal.
TEST(GoToRoom, SomeoneWhoWalksPastIsWaitedForAndSomeoneWhoStaysFailsTheGoal) {
  std::string reason;
  EXPECT_EQ(DriveWithSomeoneAhead(8.0, &reason).first, GoToRoomState::kArrived) << reason;
  const auto [state, time_s] = DriveWithSomeoneAhead(1e9, &reason);
  EXPECT_EQ(state, GoToRoomState::kFailed);
  EXPECT_NEAR(time_s, 13.0, 0.5);  // blocked at 3 s, failed blocked_wait_s later
  EXPECT_EQ(reason.rfind("stopped by a wall or obstacle 0.", 0), 0u) << reason;
  EXPECT_NE(reason.find(" m ahead for 10.1 s with "), std::string::npos) << reason;
}

TEST(GoToRoom, ARefusedRequestKeepsItsReasonAndCommandsNothing) {
  GoToRoom go(GoToRoomOptions{});
  EXPECT_EQ(go.Status(), "idle");
  const RoomGoalResult plan = Planner().Plan("999", Pose2D{});
  ASSERT_FALSE(plan.goal);
  go.Refuse(plan.refusal);
  EXPECT_EQ(go.state(), GoToRoomState::kRefused);
  EXPECT_EQ(go.Status(), "refused: room 999 is not in the text map plates; known rooms: 101, 102, 103, 104, 106");
  const std::vector<float> ranges(360, 1.0f);
  const VelocityCommand cmd = go.Step(ranges, -M_PI, 2 * M_PI / 360, Pose2D{}, 0.0);
  EXPECT_EQ(cmd.linear_mps, 0.0);
  EXPECT_EQ(cmd.angular_rps, 0.0);
}

TEST(GoToRoom, ANonFinitePoseStopsTheRobotWithoutEndingTheGoal) {
  GoToRoom go(GoToRoomOptions{});
  const RoomGoalResult plan = Planner().Plan("104", Pose2D{});
  ASSERT_TRUE(plan.goal);
  go.Start(*plan.goal);
  const std::vector<float> ranges(360, 1.0f);
  const VelocityCommand turn = go.Step(ranges, -M_PI, 2 * M_PI / 360, Pose2D{1.0, 0.6, M_PI}, 0.0);
  EXPECT_NE(turn.angular_rps, 0.0);  // turning towards 104, ahead in +x
  const VelocityCommand stop = go.Step(ranges, -M_PI, 2 * M_PI / 360, Pose2D{std::nan(""), 0.6, 0.0}, 0.0);
  EXPECT_EQ(stop.linear_mps, 0.0);
  EXPECT_EQ(stop.angular_rps, 0.0);
  EXPECT_EQ(go.state(), GoToRoomState::kTurning);
}

TEST(GoToRoom, InvalidOptionsNameTheField) {
  GoToRoomOptions options;
  options.align_tolerance_rad = 2.0;
  try {
    GoToRoom go(options);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("GoToRoomOptions.align_tolerance_rad"), std::string::npos) << e.what();
  }
  options = GoToRoomOptions{};
  options.follower.wall_distance_m = 0.0;
  EXPECT_THROW(GoToRoom go(options), std::invalid_argument);  // the follower's own check
  options = GoToRoomOptions{};
  options.blocked_wait_s = -1.0;
  EXPECT_THROW(GoToRoom go(options), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

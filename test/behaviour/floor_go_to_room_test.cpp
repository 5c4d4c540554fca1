#include "doorplate_localization/behaviour/floor_go_to_room.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "../sim/test_worlds.h"
#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/simulator.h"

namespace doorplate_localization {
namespace {

// An L of 2 m corridors: along x from 0 to 8 (y in [0, 2]), then up along y (x in [6, 8]) to y = 8.
World LCorridorWorld() { return test::LCorridor(8.0, 8.0); }

RoomGoal GoalAt(const Pose2D& pose) {
  RoomGoal goal;
  goal.room = "105";
  goal.landmark = 0;
  goal.pose = pose;
  return goal;
}

struct DriveRun {
  FloorGoToRoomState state = FloorGoToRoomState::kIdle;
  Pose2D end;
  bool bumped = false;
};

// Closed loop in the Simulator (physics 100 Hz, control 10 Hz) on the true pose; `teleport_at_s` (> 0)
// moves the robot once to `teleport_to` (a pose jump the behaviour sees as a localization jump).
DriveRun Drive(const World& world, FloorGoToRoom* go, double teleport_at_s = -1, Pose2D teleport_to = {}) {
  Simulator sim(world, SimulatorOptions{});
  sim.Teleport(world.start_pose);
  DriveRun run;
  bool teleported = false;
  for (int step = 0; sim.time_s() < 150.0; ++step) {
    if (teleport_at_s > 0 && !teleported && sim.time_s() >= teleport_at_s) {
      sim.Teleport(teleport_to);
      teleported = true;
    }
    if (step % 10 == 0) {
      const LaserScan scan = sim.Scan();
      const VelocityCommand cmd =
          go->Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, sim.true_pose(), sim.time_s());
      if (!go->active()) break;
      sim.SetCommand(cmd.linear_mps, cmd.angular_rps);
    }
    sim.Step();
    run.bumped = run.bumped || sim.bumped();
  }
  run.state = go->state();
  run.end = sim.true_pose();
  return run;
}

TEST(FloorGoToRoom, GoesRoundTheCornerToTheGoalAndFacesTheDoor) {
  const World world = LCorridorWorld();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  FloorGoToRoom go(FloorGoToRoomOptions{}, grid);
  const Pose2D goal{6.6, 6.0, M_PI};  // facing the inner (west) wall of the second leg
  ASSERT_TRUE(go.Start(GoalAt(goal), world.start_pose)) << go.reason();
  EXPECT_EQ(go.Status().rfind("following: room 105, turning", 0), 0u) << go.Status();
  const DriveRun run = Drive(world, &go);
  EXPECT_EQ(run.state, FloorGoToRoomState::kArrived) << go.Status();
  EXPECT_FALSE(run.bumped);
  EXPECT_LT(Norm(run.end.Position() - goal.Position()), 0.1);
  EXPECT_LT(std::fabs(NormalizeAngle(run.end.theta_rad - goal.theta_rad)), 0.08);
  EXPECT_EQ(go.replans(), 0);
  EXPECT_EQ(go.Status().rfind("arrived: room 105, 0.0", 0), 0u) << go.Status();
}

TEST(FloorGoToRoom, PlansAgainAfterAJumpOffThePath) {
  const World world = LCorridorWorld();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  FloorGoToRoom go(FloorGoToRoomOptions{}, grid);
  const Pose2D goal{7.4, 6.5, 0.0};
  ASSERT_TRUE(go.Start(GoalAt(goal), world.start_pose));
  const DriveRun run = Drive(world, &go, 5.0, {7.0, 4.0, M_PI});  // carried round the corner, facing back
  EXPECT_EQ(run.state, FloorGoToRoomState::kArrived) << go.Status();
  EXPECT_GE(go.replans(), 1);
  EXPECT_LT(Norm(run.end.Position() - goal.Position()), 0.1);
}

TEST(FloorGoToRoom, RefusesAGoalInsideAWallWithThePlannersReason) {
  const World world = LCorridorWorld();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  FloorGoToRoom go(FloorGoToRoomOptions{}, grid);
  EXPECT_FALSE(go.Start(GoalAt({4.0, 4.0, 0.0}), world.start_pose));
  EXPECT_EQ(go.state(), FloorGoToRoomState::kRefused);
  EXPECT_NE(go.Status().find("refused: room 105: goal inside an obstacle"), std::string::npos) << go.Status();
  const LaserScan scan = Simulator(world, SimulatorOptions{}).Scan();
  const VelocityCommand cmd =
      go.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, world.start_pose, 0.0);
  EXPECT_EQ(cmd.linear_mps, 0.0);
  EXPECT_EQ(cmd.angular_rps, 0.0);
}

TEST(FloorGoToRoom, InvalidOptionsNameTheField) {
  const World world = LCorridorWorld();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  FloorGoToRoomOptions o;
  o.max_path_deviation_m = 0;
  try {
    FloorGoToRoom go(o, grid);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_path_deviation_m"), std::string::npos);
  }
  o = {};
  o.follower.look_ahead_m = -1;
  EXPECT_THROW(FloorGoToRoom(o, grid), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

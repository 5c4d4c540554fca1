#include "doorplate_localization/behaviour/contour_steering.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "../sim/test_worlds.h"
#include "doorplate_localization/sim/laser_simulator.h"
#include "doorplate_localization/sim/simulator.h"

namespace doorplate_localization {
namespace {

constexpr double kDeg = M_PI / 180.0;

Wall MakeWall(const char* id, Vec2 a, Vec2 b, bool corridor_left) { return {id, {a, b}, corridor_left, {200, 200, 200}}; }

ContourSteeringResult SteerAt(const World& world, const Pose2D& pose, ContourSteeringOptions options = {}) {
  const LaserScan scan = LaserSimulator(LaserOptions{}).CastExact(world, pose);
  return ContourSteering(options).Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad);
}

// A 2 m wide corridor along x from 0 to 12 with a 2 m wide side corridor leaving the south (right) wall
// at x = 5..7 towards −y, 6 m long.
World SideCorridorWorld() {
  World world;
  world.walls = {MakeWall("south_a", {0, 0}, {5, 0}, true),   MakeWall("side_w", {5, 0}, {5, -6}, false),
                 MakeWall("side_s", {5, -6}, {7, -6}, true),  MakeWall("side_e", {7, -6}, {7, 0}, true),
                 MakeWall("south_b", {7, 0}, {12, 0}, true),  MakeWall("north", {0, 2}, {12, 2}, false),
                 MakeWall("west", {0, 0}, {0, 2}, false),     MakeWall("east", {12, 0}, {12, 2}, true)};
  world.start_pose = {1, 0.6, 0};
  BuildSurfaces(world);
  return world;
}

TEST(ContourSteering, BesideAStraightWallAtTheRightDistanceDrivesStraightAtCruiseSpeed) {
  const ContourSteeringResult r = SteerAt(test::RectangleCorridor(12, 2), {4, 0.6, 0});
  ASSERT_TRUE(r.target_found);
  EXPECT_NEAR(r.target_bearing_rad, 0.0, 3 * kDeg);
  EXPECT_NEAR(r.command.angular_rps, 0.0, 0.03);
  EXPECT_GT(r.command.linear_mps, 0.35);
}

TEST(ContourSteering, ASpuriousReturnInItsLaneDoesNotMakeItTurn) {
  const World world = test::RectangleCorridor(12, 2);
  LaserScan scan = LaserSimulator(LaserOptions{}).CastExact(world, {4, 0.6, 0});
  const std::size_t ahead = static_cast<std::size_t>(std::lround(-scan.angle_min_rad / scan.angle_increment_rad));
  scan.ranges_m[ahead] = 0.5f;
  const ContourSteeringResult r = ContourSteering(ContourSteeringOptions{}).Step(scan.ranges_m, scan.angle_min_rad,
                                                                                  scan.angle_increment_rad);
  EXPECT_NEAR(r.target_bearing_rad, 0.0, 3 * kDeg);
  EXPECT_GT(r.command.linear_mps, 0.3);
}

TEST(ContourSteering, TurnsTowardsTheWallWhenTooFarAndAwayWhenTooClose) {
  const World world = test::RectangleCorridor(12, 2);
  EXPECT_LT(SteerAt(world, {4, 0.9, 0}).command.angular_rps, -0.05);  // right, towards the south wall
  EXPECT_GT(SteerAt(world, {4, 0.4, 0}).command.angular_rps, 0.05);   // left, away from it
}

TEST(ContourSteering, DrivesOnTowardsAWallAheadUntilCloseAndThenTurnsOnTheSpotAwayFromTheFollowedWall) {
  const ContourSteeringResult far = SteerAt(test::RectangleCorridor(12, 2), {10.5, 0.6, 0});
  EXPECT_GT(far.command.linear_mps, 0.0);
  EXPECT_LT(far.look_ahead_m, 1.0);
  const ContourSteeringResult r = SteerAt(test::RectangleCorridor(12, 2), {11.3, 0.6, 0});
  EXPECT_EQ(r.command.linear_mps, 0.0);
  EXPECT_GT(r.command.angular_rps, 0.5);
}

TEST(ContourSteering, TurnsIntoASideCorridorOnTheFollowedSideOncePastItsCorner) {
  const World world = SideCorridorWorld();
  EXPECT_NEAR(SteerAt(world, {4.0, 0.6, 0}).target_bearing_rad, 0.0, 5 * kDeg);  // before the opening
  const ContourSteeringResult past = SteerAt(world, {5.7, 0.6, 0});
  EXPECT_LT(past.target_bearing_rad, -60 * kDeg);
  EXPECT_LT(past.command.angular_rps, 0.0);
  EXPECT_GT(past.command.linear_mps, 0.0);  // an arc round the corner, not a spin
}

TEST(ContourSteering, GoesStraightPastAnOpenDoorInTheFollowedWall) {
  World world = test::RectangleCorridor(12, 2);
  world.doors.push_back({"d", 0, 6.0, 0.9, 2.1, true, 3.0, 3.0, {140, 95, 60}});
  BuildSurfaces(world);
  for (const double x : {5.4, 5.8, 6.0, 6.3, 6.6}) {
    EXPECT_NEAR(SteerAt(world, {x, 0.6, 0}).target_bearing_rad, 0.0, 6 * kDeg) << "x = " << x;
  }
}

TEST(ContourSteering, FollowsTheLeftWallAsTheMirrorImage) {
  ContourSteeringOptions options;
  options.wall_side = "left";
  const World world = test::RectangleCorridor(12, 2);
  EXPECT_NEAR(SteerAt(world, {4, 1.4, 0}, options).target_bearing_rad, 0.0, 3 * kDeg);
  EXPECT_GT(SteerAt(world, {4, 1.1, 0}, options).command.angular_rps, 0.05);  // too far: left, towards it
  EXPECT_LT(SteerAt(world, {11.3, 1.4, 0}, options).command.angular_rps, -0.5);  // wall ahead: clockwise
}

// A 4 m x 4 m lift lobby (x 0..4, y 0..4) off the north wall of a 2 m corridor (y -2..0, x -6..10): the
// robot stands at a lift door in the lobby's north wall, its back to the door (1.2 m behind, out of reach of
// a wall beside it), facing the corridor, with no wall on its right within reach.
World LobbyWorld() {
  World world;
  world.walls = {MakeWall("north_w", {-6, 0}, {0, 0}, true),   MakeWall("lobby_w", {0, 0}, {0, 4}, true),
                 MakeWall("lobby_n", {0, 4}, {4, 4}, true),    MakeWall("lobby_e", {4, 4}, {4, 0}, true),
                 MakeWall("north_e", {4, 0}, {10, 0}, true),   MakeWall("east", {10, 0}, {10, -2}, true),
                 MakeWall("courtyard", {10, -2}, {-6, -2}, true), MakeWall("west", {-6, -2}, {-6, 0}, true)};
  world.start_pose = {3.0, 2.8, -M_PI / 2};
  BuildSurfaces(world);
  return world;
}

TEST(ContourSteering, WithItsBackToAWallAndNoneBesideItDrivesStraightOn) {
  const ContourSteeringResult r = SteerAt(LobbyWorld(), {3.0, 2.8, -M_PI / 2});
  EXPECT_FALSE(r.wall_found);
  EXPECT_NEAR(r.target_bearing_rad, 0.0, 3 * kDeg);
  EXPECT_NEAR(r.command.angular_rps, 0.0, 0.03);
}

TEST(ContourSteering, LeavesALobbyFromALiftDoorAndFollowsTheCorridorWall) {
  // Closed loop (physics 100 Hz, steering 10 Hz). Before the fix the wall behind counted as the followed
  // wall, and the robot circled on the spot in front of the door for ever.
  const World world = LobbyWorld();
  Simulator sim(world, SimulatorOptions{});
  const ContourSteering steering({});
  double min_y = world.start_pose.y_m;
  double east_along_courtyard_m = -1e9;  // the farthest x reached 0.6 ± 0.15 m from the courtyard wall
  for (int step = 0; sim.time_s() < 60.0; ++step) {
    if (step % 10 == 0) {
      const LaserScan scan = sim.Scan();
      const VelocityCommand cmd = steering.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad).command;
      sim.SetCommand(cmd.linear_mps, cmd.angular_rps);
    }
    sim.Step();
    min_y = std::min(min_y, sim.true_pose().y_m);
    if (std::fabs(sim.true_pose().y_m - (-2.0 + 0.6)) < 0.15) {
      east_along_courtyard_m = std::max(east_along_courtyard_m, sim.true_pose().x_m);
    }
    ASSERT_FALSE(sim.bumped()) << "at " << sim.time_s() << " s";
  }
  EXPECT_LT(min_y, -0.5) << "never left the lobby (y > 0) for the corridor";
  // Then along the courtyard wall (on its right) eastwards, 0.6 m from it, to beyond the lobby.
  EXPECT_GT(east_along_courtyard_m, 7.0);
}

TEST(ContourSteering, BoxedInTurnsOnTheSpot) {
  const ContourSteeringResult r = SteerAt(test::RectangleCorridor(1.2, 1.2), {0.6, 0.6, 0});
  EXPECT_FALSE(r.target_found);
  EXPECT_EQ(r.command.linear_mps, 0.0);
  EXPECT_NE(r.command.angular_rps, 0.0);
}

TEST(ContourSteering, IgnoresNonFiniteRanges) {
  const World world = test::RectangleCorridor(12, 2);
  LaserScan scan = LaserSimulator(LaserOptions{}).CastExact(world, {4, 0.6, 0});
  for (std::size_t i = 0; i < scan.ranges_m.size(); i += 7) scan.ranges_m[i] = std::nanf("");
  scan.ranges_m[3] = INFINITY;
  const ContourSteeringResult r = ContourSteering({}).Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad);
  EXPECT_NEAR(r.target_bearing_rad, 0.0, 3 * kDeg);
}

TEST(ContourSteering, RejectsInvalidOptionsNamingTheField) {
  ContourSteeringOptions o;
  o.wall_side = "up";
  EXPECT_THROW({ try { ContourSteering s(o); } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("wall_side"), std::string::npos); throw; } }, std::invalid_argument);
  o = {};
  o.robot_clearance_m = 0.9;
  EXPECT_THROW(ContourSteering s(o), std::invalid_argument);
  o = {};
  o.max_range_m = 1.0;
  EXPECT_THROW(ContourSteering s(o), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization


#include "doorplate_localization/sim/simulator.h"

#include <gtest/gtest.h>

#include "test_worlds.h"

namespace doorplate_localization {
namespace {

void RunFor(Simulator& sim, double seconds) {
  const int steps = static_cast<int>(std::lround(seconds / 0.01));
  for (int i = 0; i < steps; ++i) sim.Step();
}

TEST(Simulator, DrivesForwardAtTheCommandedSpeed) {
  Simulator sim(test::RectangleCorridor(), SimulatorOptions{});
  sim.SetCommand(0.5, 0.0);
  RunFor(sim, 4.0);
  EXPECT_NEAR(sim.true_pose().x_m, 1.0 + 2.0, 1e-6);
  EXPECT_NEAR(sim.time_s(), 4.0, 1e-9);
  EXPECT_NEAR(sim.distance_travelled_m(), 2.0, 1e-6);
  EXPECT_NEAR(sim.odom_pose().x_m, 2.0, 0.15);  // odometry starts at its own origin
}

TEST(Simulator, TurnsOnAnArc) {
  Simulator sim(test::RectangleCorridor(), SimulatorOptions{});
  sim.SetCommand(0.0, 0.5);
  RunFor(sim, 3.0);
  EXPECT_NEAR(sim.true_pose().theta_rad, 1.5, 1e-6);
  EXPECT_NEAR(sim.true_pose().x_m, 1.0, 1e-9);
}

TEST(Simulator, StopsAtAWallInsteadOfPassingThrough) {
  Simulator sim(test::RectangleCorridor(), SimulatorOptions{});
  sim.SetCommand(0.0, 0.0);
  sim.Teleport({1.0, 1.0, M_PI / 2});
  sim.SetCommand(1.0, 0.0);
  RunFor(sim, 3.0);
  EXPECT_LE(sim.true_pose().y_m, 2.0 - sim.world().robot_radius_m + 1e-9);
  EXPECT_TRUE(sim.bumped());
  // Backing away from the wall is allowed.
  sim.SetCommand(-0.5, 0.0);
  RunFor(sim, 0.5);
  EXPECT_FALSE(sim.bumped());
  EXPECT_LT(sim.true_pose().y_m, 2.0 - sim.world().robot_radius_m - 0.2);
}

TEST(Simulator, CommandsAreClampedAndNonFiniteCommandsStopTheRobot) {
  Simulator sim(test::RectangleCorridor(), SimulatorOptions{});
  sim.SetCommand(5.0, -9.0);
  EXPECT_DOUBLE_EQ(sim.linear_velocity_mps(), 1.0);
  EXPECT_DOUBLE_EQ(sim.angular_velocity_rps(), -2.0);
  sim.SetCommand(NAN, 0.1);
  EXPECT_DOUBLE_EQ(sim.linear_velocity_mps(), 0.0);
  EXPECT_DOUBLE_EQ(sim.angular_velocity_rps(), 0.0);
}

TEST(Simulator, SameSeedSameRunAndImagesDoNotChangeOdometry) {
  SimulatorOptions options;
  options.seed = 11;
  Simulator a(test::RectangleCorridor(), options), b(test::RectangleCorridor(), options);
  for (Simulator* sim : {&a, &b}) sim->SetCommand(0.6, 0.1);
  for (int i = 0; i < 300; ++i) {
    a.Step();
    b.Step();
    if (i % 10 == 0) b.CameraImage();  // only b renders images
  }
  EXPECT_DOUBLE_EQ(a.odom_pose().x_m, b.odom_pose().x_m);
  EXPECT_DOUBLE_EQ(a.odom_pose().theta_rad, b.odom_pose().theta_rad);
  EXPECT_EQ(a.Scan().ranges_m, b.Scan().ranges_m);
}

TEST(Simulator, TeleportMovesTheRobotButNotTheOdometry) {
  Simulator sim(test::RectangleCorridor(), SimulatorOptions{});
  const Pose2D odom_before = sim.odom_pose();
  sim.Teleport({7.0, 1.5, 1.0});
  sim.Step();
  EXPECT_DOUBLE_EQ(sim.true_pose().x_m, 7.0);
  EXPECT_DOUBLE_EQ(sim.odom_pose().x_m, odom_before.x_m);
}

TEST(Simulator, ALiftRideChangesTheWorldTheLaserSeesButNotTheOdometry) {
  Simulator sim(test::RectangleCorridor(), SimulatorOptions{});
  sim.SetCommand(0.5, 0.0);
  RunFor(sim, 1.0);
  const Pose2D odom_before = sim.odom_pose();
  const double travelled = sim.distance_travelled_m();
  World upstairs = test::RectangleCorridor();
  for (Wall& wall : upstairs.walls) {  // the same corridor 1 m wider to the north
    if (wall.segment.a.y > 0.5) wall.segment.a.y += 1.0;
    if (wall.segment.b.y > 0.5) wall.segment.b.y += 1.0;
  }
  upstairs.surfaces.clear();
  const LaserScan before = sim.Scan();
  sim.ChangeWorld(upstairs, sim.true_pose());
  const LaserScan after = sim.Scan();
  EXPECT_DOUBLE_EQ(sim.odom_pose().x_m, odom_before.x_m);
  EXPECT_DOUBLE_EQ(sim.distance_travelled_m(), travelled);
  EXPECT_DOUBLE_EQ(sim.linear_velocity_mps(), 0.0);
  EXPECT_EQ(sim.world().walls.size(), upstairs.walls.size());
  // The beam pointing left (+90 deg) now reaches the moved wall 1 m farther.
  const auto left = static_cast<size_t>(std::lround((M_PI / 2 - before.angle_min_rad) / before.angle_increment_rad));
  ASSERT_LT(left, before.ranges_m.size());
  EXPECT_NEAR(after.ranges_m[left] - before.ranges_m[left], 1.0, 0.1);
}

}  // namespace
}  // namespace doorplate_localization

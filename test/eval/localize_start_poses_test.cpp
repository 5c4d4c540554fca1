// Random start and kidnap poses in the main corridor, and over a floor's corridors.
#include "localize_start_poses.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "doorplate_localization/sim/ground_truth_maps.h"
#include "eval_test_worlds.h"

namespace doorplate_localization {
namespace {

// 10 m × 2 m corridor with an open door on the north wall (a room behind it: free in the grid, but not
// part of the main corridor).
World CorridorWithOpenDoor() {
  World world = test::CorridorWithPlates(10.0, 2.0, {});
  Door door;
  door.wall_index = 1;
  door.offset_m = 5.0;
  door.open = true;
  world.doors.push_back(door);
  BuildSurfaces(world);
  return world;
}

TEST(FindCorridorBand, BoundsTheCorridorThroughTheStartPoseByItsWalls) {
  const CorridorBand band = FindCorridorBand(CorridorWithOpenDoor());
  EXPECT_NEAR(band.x_min_m, 0.0, 1e-9);
  EXPECT_NEAR(band.x_max_m, 10.0, 1e-9);
  EXPECT_NEAR(band.y_min_m, 0.0, 1e-9);
  EXPECT_NEAR(band.y_max_m, 2.0, 1e-9);
}

TEST(FindCorridorBand, RefusesAnOpenEndedWorld) {
  World world = test::CorridorWithPlates(10.0, 2.0, {});
  world.walls.pop_back();  // no east wall
  world.surfaces.clear();
  BuildSurfaces(world);
  EXPECT_THROW(FindCorridorBand(world), std::runtime_error);
}

TEST(StartPoseSampler, DrawsPosesInsideTheMarginsHeadingAlongTheCorridorEitherWay) {
  const World world = CorridorWithOpenDoor();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  StartPoseSamplerOptions options;
  const StartPoseSampler sampler(FindCorridorBand(world), grid, options);
  std::mt19937_64 rng(3);
  int backwards = 0;
  for (int i = 0; i < 200; ++i) {
    const Pose2D p = sampler.Sample(rng);
    EXPECT_GE(p.x_m, options.end_margin_m);
    EXPECT_LE(p.x_m, 10.0 - options.end_margin_m);
    EXPECT_GE(p.y_m, options.wall_margin_m);
    EXPECT_LE(p.y_m, 2.0 - options.wall_margin_m);
    const double off_axis = std::min(std::fabs(p.theta_rad), M_PI - std::fabs(p.theta_rad));
    EXPECT_LE(off_axis, options.heading_noise_rad + 1e-9);
    if (std::fabs(p.theta_rad) > M_PI / 2.0) ++backwards;
  }
  EXPECT_GT(backwards, 60);
  EXPECT_LT(backwards, 140);
}

TEST(StartPoseSampler, IsReproducibleForASeed) {
  const World world = CorridorWithOpenDoor();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  const StartPoseSampler sampler(FindCorridorBand(world), grid, {});
  std::mt19937_64 a(9), b(9);
  for (int i = 0; i < 5; ++i) {
    const Pose2D pa = sampler.Sample(a), pb = sampler.Sample(b);
    EXPECT_EQ(pa.x_m, pb.x_m);
    EXPECT_EQ(pa.y_m, pb.y_m);
    EXPECT_EQ(pa.theta_rad, pb.theta_rad);
  }
}

TEST(StartPoseSampler, KidnapTargetsAreFarEnoughFromTheRobot) {
  const World world = CorridorWithOpenDoor();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  StartPoseSamplerOptions options;
  options.min_kidnap_distance_m = 4.0;
  const StartPoseSampler sampler(FindCorridorBand(world), grid, options);
  std::mt19937_64 rng(4);
  const Pose2D robot{5.0, 1.0, 0.0};
  for (int i = 0; i < 50; ++i) {
    const Pose2D p = sampler.SampleAwayFrom(robot, rng);
    EXPECT_GE(std::hypot(p.x_m - robot.x_m, p.y_m - robot.y_m), 4.0);
  }
}

TEST(StartPoseSampler, ClearanceNeedsFreeCellsAllAround) {
  const World world = CorridorWithOpenDoor();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  const StartPoseSampler sampler(FindCorridorBand(world), grid, {});
  EXPECT_TRUE(sampler.HasClearance({5.0, 1.0}));
  EXPECT_FALSE(sampler.HasClearance({5.0, 0.2}));   // 0.2 m from the south wall
  EXPECT_FALSE(sampler.HasClearance({50.0, 1.0}));  // outside the grid
}

TEST(StartPoseSampler, RefusesBadOptionsAndATooNarrowBand) {
  const World world = CorridorWithOpenDoor();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  StartPoseSamplerOptions options;
  options.heading_noise_rad = -1.0;
  EXPECT_THROW(StartPoseSampler(FindCorridorBand(world), grid, options), std::invalid_argument);
  options = {};
  options.wall_margin_m = 1.0;  // 2 m wide corridor: nothing left
  EXPECT_THROW(StartPoseSampler(FindCorridorBand(world), grid, options), std::invalid_argument);
}

using test::LShapedFloor;

bool InUp(const Pose2D& p) { return p.y_m > 2.0; }

TEST(FloorStartPoseSampler, DrawsEachCorridorInProportionToItsLength) {
  const World world = LShapedFloor();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  const StartPoseSampler sampler = MakeStartPoseSampler(world, grid, {});
  ASSERT_TRUE(sampler.on_floor());
  std::mt19937_64 rng(5);
  int up = 0;
  const int n = 2000;
  for (int i = 0; i < n; ++i) up += InUp(sampler.Sample(rng)) ? 1 : 0;
  EXPECT_NEAR(static_cast<double>(up) / n, 4.0 / 14.0, 0.04);
}

TEST(FloorStartPoseSampler, KeepsTheMarginsAndHeadsAlongTheCorridorEitherWay) {
  const World world = LShapedFloor();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  StartPoseSamplerOptions options;
  const StartPoseSampler sampler = MakeStartPoseSampler(world, grid, options);
  std::mt19937_64 rng(6);
  int forwards[2] = {0, 0}, backwards[2] = {0, 0};
  for (int i = 0; i < 400; ++i) {
    const Pose2D p = sampler.Sample(rng);
    const int c = InUp(p) ? 1 : 0;
    const double axis = c == 1 ? M_PI / 2.0 : 0.0;  // the corridor's direction from its `from` to its `to`
    if (c == 0) {
      EXPECT_GE(p.x_m, options.end_margin_m);
      EXPECT_LE(p.x_m, 10.0 - options.end_margin_m);
      EXPECT_GE(p.y_m, options.wall_margin_m);
      EXPECT_LE(p.y_m, 2.0 - options.wall_margin_m);
    } else {
      EXPECT_GE(p.x_m, 8.0 + options.wall_margin_m);
      EXPECT_LE(p.x_m, 10.0 - options.wall_margin_m);
      EXPECT_GE(p.y_m, 2.0 + options.end_margin_m);
      EXPECT_LE(p.y_m, 6.0 - options.end_margin_m);
    }
    const double off = NormalizeAngle(p.theta_rad - axis);
    const double off_axis = std::min(std::fabs(off), M_PI - std::fabs(off));
    EXPECT_LE(off_axis, options.heading_noise_rad + 1e-9);
    ++(std::fabs(off) < M_PI / 2.0 ? forwards : backwards)[c];
  }
  for (int c = 0; c < 2; ++c) {
    EXPECT_GT(forwards[c], 20) << "corridor " << c;
    EXPECT_GT(backwards[c], 20) << "corridor " << c;
  }
}

TEST(FloorStartPoseSampler, IsReproducibleAndKidnapTargetsAreFarEnough) {
  const World world = LShapedFloor();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  const StartPoseSampler sampler = MakeStartPoseSampler(world, grid, {});
  std::mt19937_64 a(9), b(9);
  for (int i = 0; i < 5; ++i) {
    const Pose2D pa = sampler.Sample(a), pb = sampler.Sample(b);
    EXPECT_EQ(pa.x_m, pb.x_m);
    EXPECT_EQ(pa.y_m, pb.y_m);
    EXPECT_EQ(pa.theta_rad, pb.theta_rad);
  }
  const Pose2D robot{9.0, 4.0, M_PI / 2.0};
  for (int i = 0; i < 50; ++i) {
    const Pose2D p = sampler.SampleAwayFrom(robot, a);
    EXPECT_GE(std::hypot(p.x_m - robot.x_m, p.y_m - robot.y_m), 3.0);
  }
}

TEST(FloorStartPoseSampler, WorldsWithoutCorridorsKeepTheBand) {
  const World world = CorridorWithOpenDoor();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  const StartPoseSampler made = MakeStartPoseSampler(world, grid, {});
  const StartPoseSampler band(FindCorridorBand(world), grid, {});
  EXPECT_FALSE(made.on_floor());
  std::mt19937_64 a(11), b(11);
  for (int i = 0; i < 5; ++i) {  // the very same draws as the band sampler's
    const Pose2D pa = made.Sample(a), pb = band.Sample(b);
    EXPECT_EQ(pa.x_m, pb.x_m);
    EXPECT_EQ(pa.y_m, pb.y_m);
    EXPECT_EQ(pa.theta_rad, pb.theta_rad);
  }
}

TEST(FloorStartPoseSampler, RefusesACorridorNarrowerThanItsMarginsNamingIt) {
  World world = LShapedFloor();
  world.corridors[1].width_m = 0.8;  // wall margins 2 x 0.45
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  try {
    MakeStartPoseSampler(world, grid, {});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'up'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace doorplate_localization

// The go-to-room experiment on a tiny L-shaped floor (laser-only tracking, to keep it short).
#include "goto_eval.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "../sim/test_worlds.h"
#include "eval_test_worlds.h"
#include "doorplate_localization/sim/ground_truth_maps.h"

namespace doorplate_localization {
namespace {

// An L of 2 m corridors (along x from 0 to 8, then up x in [6, 8] to y = 8) with three plates.
World LFloor() {
  World world = test::LCorridor(8.0, 8.0);
  world.name = "l_floor";
  const auto plate = [&world](const char* text, int wall_index, double offset_m) {
    TextSign sign;
    sign.text = text;
    sign.wall_index = wall_index;
    sign.offset_m = offset_m;
    sign.corridor_side_left = true;
    world.signs.push_back(sign);
  };
  plate("101", 0, 3.0);
  plate("102", 1, 5.5);
  plate("103", 3, 2.0);
  world.corridors = {{"along_x", {{0, 1}, {8, 1}}, 2.0}, {"along_y", {{7, 0}, {7, 8}}, 2.0}};
  world.start_pose = {1.0, 1.0, 0.0};
  BuildSurfaces(world);
  return world;
}

TEST(GotoEval, ArrivesAtRandomRoomsOfAnLFloorFromRandomCorridorPoses) {
  const World world = LFloor();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  auto text_map = std::make_shared<const TextMap>(GroundTruthTextMap(world));
  GotoEvalOptions options;
  options.trials = 3;
  options.seed = 2;
  options.use_text = false;
  options.filter.filter.max_particles = 1000;
  const GotoEvalResult r = RunGotoEval(world, grid, text_map, options);
  ASSERT_EQ(r.trials.size(), 3u);
  for (const GotoTrial& t : r.trials) {
    EXPECT_TRUE(t.success) << "trial " << t.index << " to " << t.room << ": " << t.outcome << ", " << t.distance_m
                           << " m from the goal";
    EXPECT_GT(t.plan_length_m, 0.0);
    EXPECT_FALSE(t.bumped);
    EXPECT_LT(std::fabs(t.yaw_error_rad), 0.15);
    EXPECT_NEAR(t.distance_m * t.distance_m, t.along_m * t.along_m + t.across_m * t.across_m, 1e-9);
  }
  const GotoSummary s = Summarize(r);
  EXPECT_EQ(s.successes, 3);
  EXPECT_EQ(s.trials, 3);
}

TEST(GotoEval, ProgressLinesTellTheRoomAndTheDistanceLeft) {
  const World world = LFloor();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  GotoEvalOptions options;
  options.trials = 1;
  options.seed = 2;
  options.use_text = false;
  options.filter.filter.max_particles = 1000;
  options.progress_every_s = 3.0;  // simulated seconds; stderr is a file here: plain lines
  testing::internal::CaptureStderr();
  const auto text_map = std::make_shared<const TextMap>(GroundTruthTextMap(world));
  const GotoEvalResult r = RunGotoEval(world, grid, text_map, options);
  const std::string progress = testing::internal::GetCapturedStderr();
  ASSERT_EQ(r.trials.size(), 1u);
  ASSERT_GT(r.trials[0].sim_seconds, 6.0) << "too short a trial for two lines";
  EXPECT_NE(progress.find("goto: trial 1/1, to room " + r.trials[0].room + ", 3 s simulated, "), std::string::npos)
      << progress;
  EXPECT_NE(progress.find(", 6 s simulated, "), std::string::npos) << progress;
  EXPECT_NE(progress.find("distance left "), std::string::npos) << progress;
}

TEST(GotoEval, InABuildingTheRobotTakesTheLiftNamedAndFindsTheRoomsFloorByItsPlates) {
  const test::TwoFloorBuilding b = test::MakeTwoFloorBuilding();
  GotoEvalOptions options;
  options.trials = 1;
  options.seed = 4;
  options.camera_rate_hz = 8.0;
  options.filter.filter.max_particles = 2000;
  const GotoEvalResult r = RunGotoEval(LocalizeBuilding{"two_floor_test", b.worlds, b.maps, b.grids}, options);
  ASSERT_EQ(r.trials.size(), 1u);
  const GotoTrial& t = r.trials[0];
  EXPECT_NE(t.start_floor, t.room_floor);
  EXPECT_EQ(t.lift, "A");
  EXPECT_NE(t.instruction.find("take lift A from floor " + t.start_floor + " to floor " + t.room_floor),
            std::string::npos) << t.instruction;
  EXPECT_TRUE(t.rode);
  EXPECT_LT(t.lift_stop_distance_m, 0.3);
  EXPECT_TRUE(t.found_floor);
  EXPECT_TRUE(t.success) << t.outcome << ", " << t.distance_m << " m from the goal";
  EXPECT_EQ(Summarize(r).rides, 1);
}

TEST(GotoEval, RefusesAWorldWithoutCorridors) {
  World world = LFloor();
  world.corridors.clear();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  auto text_map = std::make_shared<const TextMap>(GroundTruthTextMap(world));
  EXPECT_THROW(RunGotoEval(world, grid, text_map, GotoEvalOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

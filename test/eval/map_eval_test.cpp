// Smoke test of the mapping experiment: sweeps of a tiny corridor with the real text extractor, a patrol
// with periodic solves, an exploration of a tiny L.
#include "map_eval.h"

#include <gtest/gtest.h>

#include "eval_test_worlds.h"

namespace doorplate_localization {
namespace {

// 8 m × 1.85 m, two plates a wall; camera at 15 Hz (the tracker needs two readings a plate).
World TinyCorridor() {
  World world = test::CorridorWithPlates(
      8.0, 1.85, {{1, 2.5, "202"}, {1, 5.5, "204"}, {0, 2.5, "201"}, {0, 5.5, "203"}});
  world.sensors.camera.rate_hz = 15.0;
  return world;
}

MapEvalOptions Options(MapMethod method) {
  MapEvalOptions options;
  options.method = method;
  options.seed = 3;
  options.speed_mps = 0.5;
  options.max_time_s = 120.0;
  options.slam.slam.num_particles = 8;
  return options;
}

TEST(MapEval, TextMethodMapsTheTinyCorridorAndEveryPlate) {
  const MapEvalResult r = RunMapEval(TinyCorridor(), Options(MapMethod::kRbpfText));
  EXPECT_TRUE(r.sweep_done);
  EXPECT_NEAR(r.truth.length_m, 8.0, 1e-9);
  EXPECT_NEAR(r.truth.width_m, 1.85, 1e-9);
  ASSERT_TRUE(r.estimate.ok);
  EXPECT_GT(r.length_accuracy, 0.98);
  EXPECT_GT(r.width_accuracy, 0.95);
  EXPECT_EQ(r.plates.plates_true, 4);
  EXPECT_EQ(r.plates.plates_mapped, 4);
  EXPECT_LT(r.plates.max_error_m, 0.2);
  EXPECT_EQ(r.plate_reports_used, r.plate_reports);
  EXPECT_GT(r.scans_processed, 10);
  EXPECT_EQ(r.trajectory.size(), static_cast<std::size_t>(r.scans_processed));
}

TEST(MapEval, LaserOnlyMethodMapsNoPlates) {
  const MapEvalResult r = RunMapEval(TinyCorridor(), Options(MapMethod::kRbpf));
  EXPECT_TRUE(r.sweep_done);
  EXPECT_EQ(r.plate_reports, 0);
  EXPECT_EQ(r.plates.plates_in_map, 0);
  EXPECT_GT(r.length_accuracy, 0.98);
}

// An L of two 2 m wide corridors (10 m along x, then 6 m north), plates on both walls of both legs, and
// its `corridors` ground truth: a floor the sweep cannot cover.
World TinyLFloor() {
  World world = test::LCorridor(10.0, 8.0);
  world.name = "tiny_l";
  const std::vector<std::pair<int, double>> places = {{0, 3.0}, {0, 6.5}, {4, 4.0}, {4, 6.5}, {1, 4.5}, {3, 2.5}};
  for (std::size_t i = 0; i < places.size(); ++i) {
    TextSign sign;
    sign.text = std::to_string(301 + i);
    sign.wall_index = places[i].first;
    sign.offset_m = places[i].second;
    world.signs.push_back(sign);
  }
  world.corridors = {{"leg_x", {{0, 1}, {10, 1}}, 2.0}, {"leg_y", {{9, 0}, {9, 8}}, 2.0}};
  world.start_pose = {0.8, 0.6, 0.0};
  world.sensors.camera.rate_hz = 15.0;
  BuildSurfaces(world);
  return world;
}

TEST(MapEval, ExploreDrivesBothLegsOfAnLReadsEveryPlateAndMeasuresEachCorridor) {
  MapEvalOptions options = Options(MapMethod::kRbpfText);
  options.drive = MapDrive::kExplore;
  options.explore.passes = 1;
  options.explore.min_revisit_travel_m = 10.0;
  options.max_time_s = 300.0;
  const MapEvalResult r = RunMapEval(TinyLFloor(), options);
  EXPECT_TRUE(r.sweep_done);
  ASSERT_EQ(r.pass_ends.size(), 1u);
  EXPECT_NE(r.pass_ends[0], "max_distance");  // back at the start: by its pose or by its first plates
  EXPECT_GT(r.distance_m, 25.0);  // both legs out and back
  std::string mapped;
  for (const TextLandmark& l : r.text_map.landmarks) mapped += l.text + " ";
  EXPECT_EQ(r.plates.plates_mapped, 6) << "mapped: " << mapped << "; " << r.plate_reports << " reports";
  EXPECT_LT(r.plates.max_error_m, 0.25);
  ASSERT_EQ(r.corridors.size(), 2u);
  for (const CorridorAccuracy& c : r.corridors) {
    EXPECT_TRUE(c.ok) << c.id;
    EXPECT_GT(c.length_accuracy, 0.97) << c.id;
  }
  ASSERT_EQ(r.pass_end_errors_m.size(), 1u);
  EXPECT_LT(r.pass_end_errors_m[0], 0.3);
}

TEST(MapEval, APatrolSweepsUntilTheTimeIsUpAndRecordsEveryPeriodicSolve) {
  MapEvalOptions options = Options(MapMethod::kRbpf);
  options.slam.back_end.enabled = true;  // laser only, with the back end the periodic solves run
  options.drive = MapDrive::kPatrol;
  options.max_time_s = 150.0;
  options.map_update_interval_s = 30.0;
  const MapEvalResult r = RunMapEval(TinyCorridor(), options);
  EXPECT_TRUE(r.sweep_done);
  EXPECT_GE(r.sweeps_done, 2);
  EXPECT_NEAR(r.sim_seconds, 150.0, 0.2);
  // A solve at the first scan, one every ~30 s of scans after it, and the final one.
  ASSERT_GE(r.solves.size(), 5u);
  for (std::size_t i = 1; i < r.solves.size(); ++i) {
    EXPECT_GE(r.solves[i].nodes, r.solves[i - 1].nodes) << "solve " << i;
    EXPECT_GE(r.solves[i].sim_time_s, r.solves[i - 1].sim_time_s) << "solve " << i;
  }
  EXPECT_EQ(r.solves.back().nodes, r.scans_processed);
  EXPECT_GT(r.loop_closures, 0);  // the second sweep closes on the first
  EXPECT_GT(r.length_accuracy, 0.98);
}

TEST(MapEval, DriveNamesRoundTripAndUnknownOnesAreRefused) {
  EXPECT_EQ(ParseMapDrive(MapDriveName(MapDrive::kSweep)), MapDrive::kSweep);
  EXPECT_EQ(ParseMapDrive(MapDriveName(MapDrive::kPatrol)), MapDrive::kPatrol);
  EXPECT_EQ(ParseMapDrive(MapDriveName(MapDrive::kExplore)), MapDrive::kExplore);
  EXPECT_THROW(ParseMapDrive("frontier"), std::invalid_argument);
}

TEST(MapEval, MethodNamesRoundTripAndUnknownOnesAreRefused) {
  EXPECT_EQ(ParseMapMethod(MapMethodName(MapMethod::kRbpf)), MapMethod::kRbpf);
  EXPECT_EQ(ParseMapMethod(MapMethodName(MapMethod::kRbpfText)), MapMethod::kRbpfText);
  EXPECT_THROW(ParseMapMethod("gmapping"), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

// Smoke test of the mapping experiment: one sweep of a tiny corridor with the real text extractor.
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

TEST(MapEval, MethodNamesRoundTripAndUnknownOnesAreRefused) {
  EXPECT_EQ(ParseMapMethod(MapMethodName(MapMethod::kRbpf)), MapMethod::kRbpf);
  EXPECT_EQ(ParseMapMethod(MapMethodName(MapMethod::kRbpfText)), MapMethod::kRbpfText);
  EXPECT_THROW(ParseMapMethod("gmapping"), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

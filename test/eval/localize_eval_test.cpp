// The localization experiment on a tiny symmetric corridor, with Tesseract in the loop for text_amcl, and
// the contour drive on a tiny L-shaped floor.
#include "localize_eval.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "doorplate_localization/sim/ground_truth_maps.h"
#include "eval_test_worlds.h"

namespace doorplate_localization {
namespace {

// 10 m × 2 m, closed doors flush: the laser sees a rectangle, symmetric under a half turn. Two plates a
// wall, all different; the camera runs at 8 Hz to keep the test short (a plate stays in view for ~3 s,
// the tracker needs two readings).
struct TinyCorridor {
  World world = test::CorridorWithPlates(10.0, 2.0, {{1, 3.0, "201"}, {1, 7.0, "203"}, {0, 2.5, "202"}, {0, 6.5, "204"}});
  OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  std::shared_ptr<const TextMap> text_map = std::make_shared<const TextMap>(GroundTruthTextMap(world));
};

LocalizeEvalOptions Fast(LocalizeMethod method, int trials) {
  LocalizeEvalOptions options;
  options.method = method;
  options.trials = trials;
  options.seed = 3;
  options.speed_mps = 0.5;
  options.max_travel_m = 40.0;
  options.camera_rate_hz = 8.0;
  options.filter.filter.max_particles = 2000;
  return options;
}

TEST(LocalizeEval, TextAmclConvergesOnTheTruePoseAfterReadingAPlate) {
  const TinyCorridor c;
  const LocalizeEvalResult r = RunLocalizeEval(c.world, c.grid, c.text_map, c.grid, Fast(LocalizeMethod::kTextAmcl, 2));
  ASSERT_EQ(r.trials.size(), 2u);
  for (const LocalizeTrial& t : r.trials) {
    EXPECT_TRUE(t.Success()) << "trial " << t.index << ": error " << t.fix.error_m << " m, " << t.fix.error_deg << " deg";
    EXPECT_GE(t.plate_updates, 1);
    EXPECT_GT(t.fix.travel_m, 0.0);
    EXPECT_LT(t.fix.travel_m, 40.0);
    EXPECT_FALSE(t.kidnapped);
  }
  EXPECT_NE(r.trials[0].start_pose.x_m, r.trials[1].start_pose.x_m);
  const LocalizeSummary s = Summarize(r);
  EXPECT_EQ(s.successes, 2);
  EXPECT_EQ(s.wrong_convergences, 0);
  EXPECT_EQ(s.success_rate, 1.0);
}

TEST(LocalizeEval, TextAmclRecoversFromAKidnap) {
  const TinyCorridor c;
  LocalizeEvalOptions options = Fast(LocalizeMethod::kTextAmcl, 1);
  options.kidnap = true;
  options.seed = 7;  // a short trial: converged after ~2 m, kidnapped near a plate
  const LocalizeEvalResult r = RunLocalizeEval(c.world, c.grid, c.text_map, c.grid, options);
  const LocalizeTrial& t = r.trials.at(0);
  ASSERT_TRUE(t.Success());
  ASSERT_TRUE(t.kidnapped);
  EXPECT_GE(std::hypot(t.kidnap_pose.x_m - t.fix.truth.x_m, t.kidnap_pose.y_m - t.fix.truth.y_m), 3.0 - 0.5);
  EXPECT_TRUE(t.recovered) << "error " << t.recovery.error_m << " m after " << t.recovery.travel_m << " m";
  EXPECT_TRUE(t.recovery.within_tolerance);
  EXPECT_EQ(Summarize(r).recoveries, 1);
}

TEST(LocalizeEval, AmclRunsWithoutTheCameraAndIsReproducibleWithOrWithoutProgressLines) {
  const TinyCorridor c;
  const LocalizeEvalOptions options = Fast(LocalizeMethod::kAmcl, 2);
  const LocalizeEvalResult a = RunLocalizeEval(c.world, c.grid, nullptr, c.grid, options);
  LocalizeEvalOptions with_progress = options;
  with_progress.progress_every_s = 2.0;  // simulated seconds; stderr is a file here: plain lines
  testing::internal::CaptureStderr();
  const LocalizeEvalResult b = RunLocalizeEval(c.world, c.grid, nullptr, c.grid, with_progress);
  const std::string progress = testing::internal::GetCapturedStderr();
  EXPECT_NE(progress.find("localize: trial 1/2, "), std::string::npos) << progress;
  EXPECT_NE(progress.find("particle spread "), std::string::npos) << progress;
  EXPECT_NE(progress.find("0/0 plates used"), std::string::npos) << progress;
  EXPECT_EQ(progress.find('\r'), std::string::npos) << "no rewriting in place off a terminal";
  ASSERT_EQ(a.trials.size(), 2u);
  for (size_t i = 0; i < a.trials.size(); ++i) {
    EXPECT_EQ(a.trials[i].plate_reports, 0);
    EXPECT_EQ(a.trials[i].converged, b.trials[i].converged);
    EXPECT_EQ(a.trials[i].fix.travel_m, b.trials[i].fix.travel_m);
    EXPECT_EQ(a.trials[i].fix.estimate.x_m, b.trials[i].fix.estimate.x_m);
    EXPECT_EQ(a.trials[i].laser_updates, b.trials[i].laser_updates);
  }
}

TEST(LocalizeEval, RefusesTextAmclWithoutATextMapAndBadOptions) {
  const TinyCorridor c;
  EXPECT_THROW(RunLocalizeEval(c.world, c.grid, nullptr, c.grid, Fast(LocalizeMethod::kTextAmcl, 1)),
               std::invalid_argument);
  LocalizeEvalOptions options = Fast(LocalizeMethod::kAmcl, 1);
  options.max_travel_m = 0.0;
  EXPECT_THROW(RunLocalizeEval(c.world, c.grid, nullptr, c.grid, options), std::invalid_argument);
}

TEST(LocalizeEval, ContourDriveSearchesAFloorFromPosesInEveryCorridor) {
  const World world = test::LShapedFloor();
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
  LocalizeEvalOptions options = Fast(LocalizeMethod::kAmcl, 4);
  options.drive = LocalizeDrive::kContour;
  options.max_travel_m = 15.0;
  const LocalizeEvalResult r = RunLocalizeEval(world, grid, nullptr, grid, options);
  EXPECT_TRUE(r.floor_start_poses);
  ASSERT_EQ(r.trials.size(), 4u);
  for (const LocalizeTrial& t : r.trials) {
    // The robot drives (no wall blocks it) until the filter converges or the search ends.
    EXPECT_GT(t.fix.travel_m, 0.5) << "trial " << t.index;
    if (!t.converged) {
      EXPECT_GE(t.fix.travel_m, options.max_travel_m) << "trial " << t.index;
    }
    // It never leaves the floor: the truth stays inside the L's walls.
    const Pose2D& p = t.fix.truth;
    const bool inside = (p.x_m > 0.0 && p.x_m < 10.0 && p.y_m > 0.0 && p.y_m < 2.0) ||
                        (p.x_m > 8.0 && p.x_m < 10.0 && p.y_m >= 2.0 && p.y_m < 6.0);
    EXPECT_TRUE(inside) << "trial " << t.index << " at (" << p.x_m << ", " << p.y_m << ")";
  }
}

TEST(LocalizeEval, InABuildingThePlatesPickTheFloorAndAFixCountsOnlyOnTheRightFloor) {
  const test::TwoFloorBuilding b = test::MakeTwoFloorBuilding();
  LocalizeBuilding building{"two_floor_test", b.worlds, b.maps, b.grids};
  LocalizeEvalOptions options = Fast(LocalizeMethod::kTextAmcl, 2);
  options.seed = 5;
  const LocalizeEvalResult r = RunLocalizeEval(building, options);
  ASSERT_EQ(r.floors, (std::vector<std::string>{"2", "3"}));
  ASSERT_EQ(r.trials.size(), 2u);
  for (const LocalizeTrial& t : r.trials) {
    EXPECT_TRUE(t.Success()) << "trial " << t.index << " on floor " << t.start_floor << ": fix on floor " << t.fix.floor
                             << ", error " << t.fix.error_m << " m";
    EXPECT_EQ(t.fix.true_floor, t.start_floor);
    EXPECT_GE(t.floor_travel_m, 0.0);
    EXPECT_LE(t.floor_travel_m, t.fix.travel_m + 1e-9);
  }
  EXPECT_EQ(Summarize(r).wrong_floor, 0);
}

TEST(ParticleSpreadM, IsTheRmsDistanceOfThePositionsFromTheirMean) {
  const auto at = [](double x, double y) { return Particle{{x, y, 0.0}, 0.25}; };
  EXPECT_EQ(ParticleSpreadM({}), 0.0);
  EXPECT_EQ(ParticleSpreadM({at(5, 5)}), 0.0);
  EXPECT_DOUBLE_EQ(ParticleSpreadM({at(0, 0), at(2, 0)}), 1.0);
  EXPECT_DOUBLE_EQ(ParticleSpreadM({at(1, 1), at(-1, 1), at(-1, -1), at(1, -1)}), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(ParticleSpreadM({at(10, 3), at(12, 3), at(10, 3), at(12, 3)}), 1.0);  // wherever it lies
}

TEST(LocalizeDrive, ParsesItsNamesAndRefusesOthers) {
  EXPECT_EQ(ParseLocalizeDrive("patrol"), LocalizeDrive::kPatrol);
  EXPECT_EQ(ParseLocalizeDrive("contour"), LocalizeDrive::kContour);
  EXPECT_STREQ(ToString(LocalizeDrive::kContour), "contour");
  EXPECT_THROW(ParseLocalizeDrive("explore"), std::invalid_argument);
}

TEST(Summarize, TakesMediansOverTheConvergedTrialsOnly) {
  LocalizeEvalResult r;
  for (const auto& [converged, error, travel] :
       {std::tuple<bool, double, double>{true, 0.1, 4.0}, {true, 0.2, 6.0}, {true, 3.0, 20.0}, {false, 9.0, 99.0}, {false, 0.1, 99.0}}) {
    LocalizeTrial t;
    t.converged = converged;
    t.fix.error_m = error;
    t.fix.travel_m = travel;
    t.fix.within_tolerance = error <= 0.3;
    r.trials.push_back(t);
  }
  const LocalizeSummary s = Summarize(r);
  EXPECT_EQ(s.trials, 5);
  EXPECT_EQ(s.successes, 2);
  EXPECT_EQ(s.wrong_convergences, 1);
  EXPECT_EQ(s.not_converged, 2);
  EXPECT_EQ(s.not_converged_estimate_right, 1);
  EXPECT_EQ(s.success_rate, 0.4);
  EXPECT_EQ(s.median_travel_m, 6.0);
  EXPECT_EQ(s.longest_travel_m, 20.0);
  EXPECT_EQ(s.median_final_error_m, 0.2);
  EXPECT_EQ(s.kidnaps, 0);
  EXPECT_EQ(s.recovery_rate, 0.0);
}

}  // namespace
}  // namespace doorplate_localization

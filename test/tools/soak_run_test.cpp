#include "soak_run.h"

#include <gtest/gtest.h>

#include "doorplate_localization/sim/world_loader.h"

namespace doorplate_localization::tools {
namespace {

World ClosedDoors() { return LoadWorldFile(std::string(DOORPLATE_SOURCE_DIR) + "/worlds/paper_sim_closed_doors.yaml"); }

TEST(RunSoak, ReportsEveryWindowWithItsScansFramesMemoryAndNoErrors) {
  SoakOptions options;
  options.duration_s = 20.0;
  options.window_s = 10.0;
  options.camera_rate_hz = 2.0;
  options.max_particles = 300;
  const SoakResult result = RunSoak(ClosedDoors(), options);
  ASSERT_EQ(result.windows.size(), 2u);
  EXPECT_GT(result.start_rss_mb, 0.0);
  for (const SoakWindow& w : result.windows) {
    EXPECT_EQ(w.scans, 100);  // the world's laser at 10 Hz
    EXPECT_EQ(w.frames, 20);  // 2 Hz
    EXPECT_GT(w.rss_mb, 0.0);
    EXPECT_GT(w.wall_s, 0.0);
    EXPECT_GT(w.cpu_s, 0.0);
    EXPECT_EQ(w.errors, 0);
    EXPECT_LT(w.mean_error_m, 0.5);  // started at the true pose: it tracks
  }
  EXPECT_NEAR(result.windows.back().end_sim_s, 20.0, 1e-6);
  EXPECT_GT(result.distance_m, 2.0);
}

// Issue 8's faults, the outages shortened (camera 10 s instead of 30 s) to keep the test short: the
// localizer must recover from each, and the run must stop once the last one has.
TEST(RunSoak, LocalizationRecoversFromEachInjectedFault) {
  SoakOptions options;
  options.duration_s = 400.0;  // a cap: the run ends when the faults are done
  options.window_s = 400.0;
  options.camera_rate_hz = 2.0;
  options.max_particles = 1000;
  options.seed = 3;
  options.faults.schedule = {{FaultKind::kCameraOff, 10.0},
                             {FaultKind::kLaserOff, 5.0},
                             {FaultKind::kLocalizerRestart, 0.0},
                             {FaultKind::kKidnap, 0.0},
                             {FaultKind::kKidnap, 0.0}};
  options.faults.first_fault_s = 10.0;
  options.faults.settle_s = 5.0;
  options.faults.max_recovery_s = 120.0;
  const SoakResult result = RunSoak(ClosedDoors(), options);
  EXPECT_EQ(result.errors, 0);
  ASSERT_EQ(result.faults.size(), 5u);
  for (const FaultReport& f : result.faults) {
    EXPECT_TRUE(f.recovered) << ToString(f.kind) << " at " << f.start_s << " s";
    EXPECT_GE(f.recovery_distance_m, 0.0);
  }
  EXPECT_GE(result.faults[3].kidnap_jump_m, options.faults.kidnap_min_jump_m);
  EXPECT_GT(result.faults[3].max_error_m, 1.0);  // the kidnap did move the robot away from the estimate
  ASSERT_FALSE(result.windows.empty());
  EXPECT_LT(result.windows.back().end_sim_s, options.duration_s);  // stopped after the last recovery
}

TEST(RunSoak, RefusesFaultsWithoutTheLocalizer) {
  SoakOptions options;
  options.duration_s = 10.0;
  options.window_s = 10.0;
  options.localizer = false;
  options.faults.schedule = {{FaultKind::kKidnap, 0.0}};
  EXPECT_THROW(RunSoak(ClosedDoors(), options), std::invalid_argument);
}

TEST(RunSoak, RejectsAWindowLongerThanTheRun) {
  SoakOptions options;
  options.duration_s = 10.0;
  options.window_s = 20.0;
  EXPECT_THROW(RunSoak(ClosedDoors(), options), std::invalid_argument);
}

TEST(ResidentMegabytes, ReadsThisProcesssMemory) { EXPECT_GT(ResidentMegabytes(), 1.0); }

}  // namespace
}  // namespace doorplate_localization::tools

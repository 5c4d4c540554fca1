// doorplate_map_rawlog end to end on real data: mrpt-common's Málaga Telecom Faculty loop (224
// action-observation pairs, SICK scans, wheel odometry). The final pose must agree with MRPT's own
// regression value for that log (RBPF_SLAM_App_unittest: [3.4548 -18.0399 -86.48 deg]) as MRPT's test
// requires of MRPT (|log of the difference| < 1). Skipped where mrpt-common is not installed.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "doorplate_localization/maps/map_io.h"

namespace {

namespace fs = std::filesystem;

const char kRawlog[] = "/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";

TEST(MapRawlog, TheMalagaLoopEndsWhereMrptsRegressionValueSaysAndTheMapLoads) {
  if (!fs::exists(kRawlog)) GTEST_SKIP() << kRawlog << " is missing (apt-get install mrpt-common)";
  const fs::path dir = fs::temp_directory_path() / ("map_rawlog_test_" + std::to_string(::getpid()));
  const std::string command = std::string(DOORPLATE_MAP_RAWLOG) + " '" + kRawlog + "' --out-dir " + dir.string() +
                              " --seed 1 --expect '3.4548 -18.0399 -86.48' > " + dir.string() + ".txt 2>&1";
  const int status = std::system(command.c_str());
  std::ifstream in(dir.string() + ".txt");
  const std::string output((std::istreambuf_iterator<char>(in)), {});
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << output;  // 3: |log| >= 1
  EXPECT_NE(output.find("224 action-observation pairs"), std::string::npos) << output;
  const doorplate_localization::OccupancyGrid grid =
      doorplate_localization::LoadOccupancyMap((dir / "map.yaml").string());
  EXPECT_GT(grid.WidthM(), 30.0);  // the faculty floor seen from the loop
  fs::remove_all(dir);
  fs::remove(dir.string() + ".txt");
}

}  // namespace

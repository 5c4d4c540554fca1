#include "doorplate_localization/slam/carmen_reader.h"

#include <cmath>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

constexpr double kPi = 3.141592653589793;

std::string Fixture(const std::string& name) {
  return std::string(DOORPLATE_SOURCE_DIR) + "/test/data/slam/" + name;
}

std::string ErrorOf(const std::string& text) {
  std::istringstream in(text);
  try {
    ReadCarmenLog(in, "x.log");
  } catch (const CarmenLogError& e) {
    return e.what();
  }
  return "";
}

TEST(ReadCarmenLog, ReadsOnlyTheFlaserLinesOfARealLog) {
  const CarmenLog log = ReadCarmenLogFile(Fixture("intel_head.log"));
  ASSERT_EQ(log.scans.size(), 3u);  // the comments, PARAM and ODOM lines are skipped
  EXPECT_EQ(log.scans[0].line_number, 6);
  EXPECT_EQ(log.scans[2].scan_index, 2);
  const CarmenScan& first = log.scans[0];
  ASSERT_EQ(first.scan.ranges_m.size(), 180u);
  EXPECT_FLOAT_EQ(first.scan.ranges_m[0], 1.09f);
  EXPECT_FLOAT_EQ(first.scan.ranges_m[179], 1.23f);
  EXPECT_NEAR(first.laser_pose.x_m, 0.600266, 1e-9);
  EXPECT_NEAR(first.laser_pose.theta_rad, -0.354665, 1e-9);
  EXPECT_NEAR(first.odometry_pose.y_m, -0.0320327, 1e-9);
  EXPECT_NEAR(first.timestamp_s, 32.9068, 1e-9);
}

TEST(ReadCarmenLog, OneHundredEightyBeamsSpanMinus90To89DegreesInOneDegreeSteps) {
  const CarmenLog log = ReadCarmenLogFile(Fixture("intel_head.log"));
  const CarmenScan& scan = log.scans[0];
  EXPECT_NEAR(scan.scan.angle_min_rad, -kPi / 2, 1e-12);
  EXPECT_NEAR(scan.scan.angle_increment_rad, kPi / 180, 1e-12);
  EXPECT_NEAR(scan.scan.BeamAngle(179), kPi / 180 * 89, 1e-12);
}

TEST(ReadCarmenLog, ThreeHundredSixtyOneBeamsSpanTheHalfCircleInHalfDegrees) {
  const CarmenLog log = ReadCarmenLogFile(Fixture("csail_one.log"));
  const CarmenScan& scan = log.scans[0];
  ASSERT_EQ(scan.scan.ranges_m.size(), 361u);
  EXPECT_NEAR(scan.scan.angle_increment_rad, kPi / 360, 1e-12);
  EXPECT_NEAR(scan.scan.BeamAngle(360), kPi / 2, 1e-12);
}

TEST(ReadCarmenLog, TheLogsLargestReadingIsTheNoReturnValueAndBecomesInfinity) {
  const CarmenLog log = ReadCarmenLogFile(Fixture("intel_head.log"));
  EXPECT_NEAR(log.no_return_range_m, 81.83, 1e-4);
  const std::vector<float>& r = log.scans[0].scan.ranges_m;
  EXPECT_TRUE(std::isinf(r[110]) && r[110] > 0);  // "81.83" in the file
  EXPECT_FALSE(std::isinf(r[114]));               // a real echo between no-return beams
  EXPECT_TRUE(std::isinf(log.scans[2].scan.ranges_m[179]));
}

TEST(ReadCarmenLog, AGivenNoReturnValueOverridesDetection) {
  CarmenReaderOptions options;
  options.no_return_range_m = 4.0;
  const CarmenLog log = ReadCarmenLogFile(Fixture("intel_head.log"), options);
  EXPECT_TRUE(std::isinf(log.scans[2].scan.ranges_m[0]));    // 4.07 >= 4.0
  EXPECT_FALSE(std::isinf(log.scans[0].scan.ranges_m[0]));   // 1.09
}

TEST(ReadCarmenLog, ShortLogsWithoutLongReadingsHaveNoNoReturnValue) {
  std::istringstream in("FLASER 2 1.5 2.5 0 0 0 0 0 0\n");
  const CarmenLog log = ReadCarmenLog(in, "x.log");
  EXPECT_EQ(log.no_return_range_m, 0.0);
  EXPECT_FLOAT_EQ(log.scans[0].scan.ranges_m[1], 2.5f);
}

TEST(ReadCarmenLog, MalformedLinesNameTheFileTheLineAndTheField) {
  EXPECT_NE(ErrorOf("# c\nFLASER 3 1 2 x 0 0 0 0 0 0\n").find("x.log:2: range 2: not a finite number: 'x'"),
            std::string::npos);
  EXPECT_NE(ErrorOf("FLASER 3 1 2 3 0 0 0\n").find("needs 11 fields"), std::string::npos);
  EXPECT_NE(ErrorOf("FLASER 2.5 1 2 0 0 0 0 0 0\n").find("beam count"), std::string::npos);
  EXPECT_NE(ErrorOf("FLASER 2 1 2 0 0 nan 0 0 0\n").find("laser pose theta"), std::string::npos);
}

// A full CARMEN line ends with ipc_timestamp ipc_hostname logger_timestamp: one beam lost must be blamed on
// the beam count, not on the hostname read as a timestamp.
TEST(ReadCarmenLog, ALineMissingOneBeamIsBlamedOnTheBeamCount) {
  std::istringstream full("FLASER 3 1 2 3 0 0 0 0 0 0 12.5 pippo 12.6\n");
  EXPECT_DOUBLE_EQ(ReadCarmenLog(full, "x.log").scans[0].timestamp_s, 12.5);
  const std::string error = ErrorOf("FLASER 3 1 2 0 0 0 0 0 0 12.5 pippo 12.6\n");
  EXPECT_NE(error.find("x.log:1: FLASER with 3 beams needs 11 fields"), std::string::npos) << error;
  EXPECT_NE(error.find("got 13: does the number of ranges match the beam count?"), std::string::npos) << error;
}

// Finite but absurd (issue 18): a pose shifted by 1e15 m made the SLAM allocate until std::bad_alloc, and a
// range of 1e308 does not fit the float it is stored in.
TEST(ReadCarmenLog, RefusesPosesBeyondTheCoordinateLimitAndRangesNoFloatHolds) {
  const std::string shifted = ErrorOf("FLASER 2 1 2 0 0 0 1e15 0 0\n");
  EXPECT_NE(shifted.find("x.log:1: odometry pose x: must be finite and within +-1e+06 m (limits::kMaxCoordinateM), "
                         "got 1e+15"), std::string::npos) << shifted;
  EXPECT_NE(ErrorOf("# c\nFLASER 2 1 2 0 -2e6 0 0 0 0\n").find("x.log:2: laser pose y: "), std::string::npos);
  const std::string huge = ErrorOf("FLASER 2 1 1e308 0 0 0 0 0 0\n");
  EXPECT_NE(huge.find("x.log:1: range 1: 1e308 does not fit a float range"), std::string::npos) << huge;
  std::istringstream at_the_limit("FLASER 2 1 2 1e6 -1e6 0 1e6 -1e6 0\n");
  EXPECT_EQ(ReadCarmenLog(at_the_limit, "x.log").scans.size(), 1u);
}

TEST(ReadCarmenLogFile, AMissingFileIsAnErrorNamingIt) {
  try {
    ReadCarmenLogFile("/nonexistent/x.log");
    FAIL();
  } catch (const CarmenLogError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/x.log"), std::string::npos);
  }
}

}  // namespace
}  // namespace doorplate_localization

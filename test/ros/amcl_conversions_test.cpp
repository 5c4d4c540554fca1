#include "doorplate_localization/ros/amcl_conversions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <tf2/LinearMath/Quaternion.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

#include "doorplate_localization/common/limits.h"

namespace doorplate_localization {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(ToLocalizationScan, KeepsNonFiniteRangesAndTheMountingPose) {
  sensor_msgs::LaserScan msg;
  msg.angle_min = -1.0f;
  msg.angle_increment = 0.5f;
  msg.range_min = 0.1f;
  msg.range_max = 8.0f;
  msg.ranges = {1.0f, kInf, std::numeric_limits<float>::quiet_NaN()};
  const LaserScan scan = ToLocalizationScan(msg, Pose2D{0.2, 0.0, M_PI});
  EXPECT_EQ(ValidateLocalizationScan(scan), "");
  EXPECT_FLOAT_EQ(scan.angle_min_rad, -1.0);
  EXPECT_FLOAT_EQ(scan.max_range_m, 8.0);
  ASSERT_EQ(scan.ranges_m.size(), 3u);
  EXPECT_TRUE(std::isinf(scan.ranges_m[1]));
  EXPECT_TRUE(std::isnan(scan.ranges_m[2]));
  EXPECT_DOUBLE_EQ(scan.laser_pose.theta_rad, M_PI);
}

TextDetection Detection(const std::string& text, float bearing_rad, bool crossed, float confidence = 0.9f) {
  TextDetection d;
  d.text = text;
  d.bearing_rad = bearing_rad;
  d.crossed_center = crossed;
  d.confidence = confidence;
  return d;
}

TEST(ToPlateReadings, KeepsCrossedCentreReadingsWithTheBearingInBaseLinkAndNoRange) {
  TextDetectionArray msg;
  msg.detections = {Detection("214", 0.05f, true), Detection("215", 0.0f, false), Detection("", 0.0f, true)};
  std::vector<std::string> problems;
  const std::vector<PlateReading> readings = ToPlateReadings(msg, CameraAxis{M_PI / 2, 1.0}, &problems);
  EXPECT_TRUE(problems.empty());
  ASSERT_EQ(readings.size(), 1u);
  EXPECT_EQ(readings[0].text, "214");
  EXPECT_NEAR(readings[0].confidence, 0.9, 1e-6);
  EXPECT_NEAR(readings[0].bearing_rad, M_PI / 2 + 0.05, 1e-6);
  EXPECT_FALSE(readings[0].range_m.has_value());  // the session measures it (TextAmclSession)
  EXPECT_EQ(readings[0].camera_side, CameraSide::kUnknown);
}

TEST(ToPlateReadings, TurnsTheBearingOfAnUpsideDownCameraClockwise) {
  TextDetectionArray msg;
  msg.detections = {Detection("214", 0.05f, true)};
  const std::vector<PlateReading> readings = ToPlateReadings(msg, CameraAxis{-M_PI / 2, -1.0}, nullptr);
  ASSERT_EQ(readings.size(), 1u);
  EXPECT_NEAR(readings[0].bearing_rad, -M_PI / 2 - 0.05, 1e-6);
}

TEST(ToPlateReadings, ReportsAnInvalidReadingAndKeepsTheOthers) {
  TextDetectionArray msg;
  msg.detections = {Detection("214", 0.0f, true, 1.5f), Detection("216", std::nanf(""), true),
                    Detection("218", 0.1f, true)};
  std::vector<std::string> problems;
  const std::vector<PlateReading> readings = ToPlateReadings(msg, CameraAxis{0.0, 1.0}, &problems);
  ASSERT_EQ(readings.size(), 1u);
  EXPECT_EQ(readings[0].text, "218");
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("detection '214'"), std::string::npos);
  EXPECT_NE(problems[0].find("confidence"), std::string::npos);
  EXPECT_NE(problems[1].find("bearing"), std::string::npos);
}

// Issue 18: a 1 MB detection text is refused by its length and quoted cut short (100 such messages made
// 40 MB of rosout.log).
TEST(ToPlateReadings, RefusesAnOverlongTextQuotingOnlyItsStart) {
  TextDetectionArray msg;
  msg.detections = {Detection(std::string(1 << 20, '4'), 0.0f, true)};
  std::vector<std::string> problems;
  EXPECT_TRUE(ToPlateReadings(msg, CameraAxis{0.0, 1.0}, &problems).empty());
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0], "detection '" + std::string(64, '4') +
                             "... (1048576 bytes)': PlateReading.text: 1048576 bytes, more than the limit of 64 "
                             "(limits::kMaxPlateTextBytes)");
}

geometry_msgs::PoseWithCovarianceStamped InitialPose() {
  geometry_msgs::PoseWithCovarianceStamped msg;
  msg.header.frame_id = "map";
  msg.pose.pose = ToPoseMsg(Pose2D{3.0, 1.0, -0.5});
  msg.pose.covariance[0] = 0.25;
  msg.pose.covariance[1] = msg.pose.covariance[6] = 0.01;
  msg.pose.covariance[7] = 0.16;
  msg.pose.covariance[35] = 0.07;
  return msg;
}

TEST(FromInitialPoseMsg, ReadsThePlanarPoseAndItsCovariance) {
  Pose2D mean;
  Eigen::Matrix3d cov;
  ASSERT_EQ(FromInitialPoseMsg(InitialPose(), "map", &mean, &cov), "");
  EXPECT_NEAR(mean.x_m, 3.0, 1e-12);
  EXPECT_NEAR(mean.theta_rad, -0.5, 1e-12);
  EXPECT_DOUBLE_EQ(cov(0, 0), 0.25);
  EXPECT_DOUBLE_EQ(cov(0, 1), 0.01);
  EXPECT_DOUBLE_EQ(cov(1, 1), 0.16);
  EXPECT_DOUBLE_EQ(cov(2, 2), 0.07);
  geometry_msgs::PoseWithCovarianceStamped no_frame = InitialPose();
  no_frame.header.frame_id = "";  // amcl accepts it
  EXPECT_EQ(FromInitialPoseMsg(no_frame, "map", &mean, &cov), "");
}

TEST(FromInitialPoseMsg, RefusesAnotherFrameABrokenQuaternionAndANegativeVariance) {
  Pose2D mean{9.0, 9.0, 0.0};
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  geometry_msgs::PoseWithCovarianceStamped msg = InitialPose();
  msg.header.frame_id = "odom";
  EXPECT_EQ(FromInitialPoseMsg(msg, "map", &mean, &cov), "header.frame_id is 'odom', expected 'map'");
  msg = InitialPose();
  msg.pose.pose.orientation.w = 0.0;
  msg.pose.pose.orientation.z = 0.0;
  EXPECT_NE(FromInitialPoseMsg(msg, "map", &mean, &cov).find("unit quaternion"), std::string::npos);
  msg = InitialPose();
  msg.pose.covariance[35] = -1.0;
  EXPECT_NE(FromInitialPoseMsg(msg, "map", &mean, &cov).find("positive semi-definite"), std::string::npos);
  msg = InitialPose();
  msg.pose.pose.position.x = std::nan("");
  EXPECT_EQ(FromInitialPoseMsg(msg, "map", &mean, &cov), "pose must be finite");
  EXPECT_EQ(mean.x_m, 9.0);
}

// Found by fuzz/message_conversions_fuzz.cpp (issue 18): a pose at 3.4e38 m was accepted, and a covariance
// symmetric within this check's tolerance (2.2e-26 off the diagonal of a zero matrix) was handed to
// TextAmcl::Initialize, whose norm-relative check refused it.
TEST(FromInitialPoseMsg, RefusesAPoseBeyondTheCoordinateLimitAndHandsOnAnExactlySymmetricCovariance) {
  Pose2D mean{9.0, 9.0, 0.0};
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  geometry_msgs::PoseWithCovarianceStamped msg = InitialPose();
  msg.pose.pose.position.y = 3.4028234663852886e38;
  EXPECT_EQ(FromInitialPoseMsg(msg, "map", &mean, &cov),
            "pose.position.y: must be finite and within +-1e+06 m (limits::kMaxCoordinateM), got 3.40282e+38");
  EXPECT_EQ(mean.x_m, 9.0);
  msg = InitialPose();
  for (double& c : msg.pose.covariance) c = 0.0;
  msg.pose.covariance[5 * 6 + 1] = 2.2247599395766315e-26;  // yaw row, y column; its mirror stays 0
  ASSERT_EQ(FromInitialPoseMsg(msg, "map", &mean, &cov), "");
  EXPECT_EQ(cov, cov.transpose());
  EXPECT_TRUE(cov.isApprox(cov.transpose(), 1e-9));  // TextAmcl::Initialize's check
}

TEST(ToAmclPoseMsg, PlacesTheCovarianceAtXYAndYaw) {
  PoseEstimate estimate;
  estimate.pose = {1.0, 2.0, 0.5};
  estimate.covariance << 0.04, 0.01, 0.0, 0.01, 0.09, 0.0, 0.0, 0.0, 0.02;
  const geometry_msgs::PoseWithCovarianceStamped msg = ToAmclPoseMsg(estimate, "map", ros::Time(4.0));
  EXPECT_EQ(msg.header.frame_id, "map");
  EXPECT_NEAR(tf2::getYaw(msg.pose.pose.orientation), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(msg.pose.covariance[0], 0.04);
  EXPECT_DOUBLE_EQ(msg.pose.covariance[1], 0.01);
  EXPECT_DOUBLE_EQ(msg.pose.covariance[6], 0.01);
  EXPECT_DOUBLE_EQ(msg.pose.covariance[7], 0.09);
  EXPECT_DOUBLE_EQ(msg.pose.covariance[35], 0.02);
  EXPECT_DOUBLE_EQ(msg.pose.covariance[14], 0.0);  // z
}

TEST(ToParticleCloudMsg, OnePosePerParticle) {
  const std::vector<Particle> particles{{Pose2D{1.0, 0.0, 0.0}, 0.5}, {Pose2D{0.0, 2.0, -1.0}, 0.5}};
  const geometry_msgs::PoseArray msg = ToParticleCloudMsg(particles, "map", ros::Time(1.0));
  ASSERT_EQ(msg.poses.size(), 2u);
  EXPECT_EQ(msg.header.frame_id, "map");
  EXPECT_DOUBLE_EQ(msg.poses[1].position.y, 2.0);
  EXPECT_NEAR(tf2::getYaw(msg.poses[1].orientation), -1.0, 1e-12);
}

TEST(StateText, NamesTheReasonOnlyWhenLost) {
  EXPECT_EQ(StateText(LocalizationState::kTracking, LostReason::kNone), "tracking");
  EXPECT_EQ(StateText(LocalizationState::kConverged, LostReason::kNone), "converged");
  EXPECT_EQ(StateText(LocalizationState::kLost, LostReason::kPlateContradiction), "lost: plate_contradiction");
  EXPECT_EQ(StateText(LocalizationState::kLost, LostReason::kLikelihoodCollapse), "lost: likelihood_collapse");
}

TEST(DescribePlateOutcome, SaysWhatBecameOfTheReading) {
  PlateReadingOutcome weighed;
  weighed.reading.text = "214";
  weighed.reading.bearing_rad = 1.5708;
  weighed.reading.range_m = 1.2;
  weighed.result.used = true;
  weighed.result.explained_ratio = 3.1;
  weighed.result.best_cluster_explained_ratio = 4.0;
  EXPECT_EQ(DescribePlateOutcome(weighed),
            "plate '214' at 1.571 rad, range 1.20 m: explained 3.10 (best cluster 4.00), 0 reseeded");
  weighed.result.used = false;
  weighed.result.ignored_reason = "confidence 0.2 below text_min_confidence 0.5";
  EXPECT_EQ(DescribePlateOutcome(weighed), "plate '214' not used: confidence 0.2 below text_min_confidence 0.5");
  PlateReadingOutcome unknown;
  unknown.reading.text = "999";
  unknown.disposition = PlateDisposition::kUnknownRoomFirst;
  EXPECT_EQ(DescribePlateOutcome(unknown), "room '999' is not in the text map");
  PlateReadingOutcome stale = unknown;
  stale.disposition = PlateDisposition::kStale;
  stale.stamp_s = 12.3;
  stale.detail = "older than the odometry kept";
  EXPECT_EQ(DescribePlateOutcome(stale), "plate '999' at 12.300 s ignored (stale): older than the odometry kept");
}

TEST(DescribePlateOutcome, QuotesAtMostTheLoggedTextLimit) {
  PlateReadingOutcome invalid;
  invalid.reading.text = std::string(1000, 'x') + "\xc3\xa9";
  invalid.disposition = PlateDisposition::kInvalid;
  invalid.detail = "too long";
  const std::string line = DescribePlateOutcome(invalid);
  EXPECT_EQ(line, "plate '" + std::string(64, 'x') + "... (1002 bytes)' at 0.000 s ignored (invalid): too long");
  // A cut never splits a UTF-8 character: 63 x then a 2-byte character at bytes 63-64 is cut before it.
  EXPECT_EQ(limits::TruncateForLog(std::string(63, 'x') + "\xc3\xa9" + "yy"), std::string(63, 'x') + "... (67 bytes)");
}

// --- ~state and /diagnostics (LocalizerHealth) ---

LocalizerHealth Flowing(LocalizationState state) {
  LocalizerHealth h;
  h.map_in_force = true;
  h.map = "/amcl/map_file: 40 x 20 at 0.100 m";
  h.scan_age_s = 0.1;
  h.scan_timeout_s = 2.0;
  h.status.state = state;
  return h;
}

TEST(NodeStateText, SaysConvergedOnlyWhileAMapIsInForceAndScansAreTaken) {
  EXPECT_EQ(NodeStateText(Flowing(LocalizationState::kConverged)), "converged");
  LocalizerHealth h = Flowing(LocalizationState::kConverged);
  h.map_in_force = false;
  EXPECT_EQ(NodeStateText(h), "waiting_for_map");
  h = Flowing(LocalizationState::kConverged);
  h.scan_age_s = -1.0;  // none since the (re)start
  EXPECT_EQ(NodeStateText(h), "waiting_for_scan");
  h.scan_age_s = 2.5;  // stale
  EXPECT_EQ(NodeStateText(h), "waiting_for_scan");
  h.scan_timeout_s = 0.0;  // never stale
  EXPECT_EQ(NodeStateText(h), "converged");
  h.error = "std::bad_alloc";
  EXPECT_EQ(NodeStateText(h), "error: std::bad_alloc");
  h = Flowing(LocalizationState::kLost);
  h.status.lost_reason = LostReason::kPlateContradiction;
  EXPECT_EQ(NodeStateText(h), "lost: plate_contradiction");
}

TEST(ToDiagnosticStatus, GivesTheLevelTheStateAndTheFiguresAUserChecks) {
  LocalizerHealth h = Flowing(LocalizationState::kConverged);
  h.scan_rate_hz = 9.96;
  h.tf_age_s = 0.04;
  h.status.particle_count = 500;
  h.plates_used = 3;
  diagnostic_msgs::DiagnosticStatus d = ToDiagnosticStatus(h, "/amcl: localization", "/amcl");
  EXPECT_EQ(d.level, diagnostic_msgs::DiagnosticStatus::OK);
  EXPECT_EQ(d.message, "converged");
  EXPECT_EQ(d.name, "/amcl: localization");
  const auto value = [&d](const std::string& key) {
    for (const auto& kv : d.values) {
      if (kv.key == key) return kv.value;
    }
    return std::string("(missing)");
  };
  EXPECT_EQ(value("state"), "converged");
  EXPECT_EQ(value("map in force"), "/amcl/map_file: 40 x 20 at 0.100 m");
  EXPECT_EQ(value("scan rate (Hz)"), "10.0");
  EXPECT_EQ(value("odometry tf age (s)"), "0.04");
  EXPECT_EQ(value("particles"), "500");
  EXPECT_EQ(value("plates used"), "3");
  EXPECT_EQ(value("last error"), "none");
  EXPECT_EQ(value("scans dropped"), "0");
  EXPECT_EQ(value("last scan dropped"), "none");
  h.scans_dropped = 3;
  h.last_scan_dropped = "no tf from 'laser' to 'odom' at the scan's stamp 2.000 s: older than tf's cache holds";
  d = ToDiagnosticStatus(h, "n", "h");
  EXPECT_EQ(d.level, diagnostic_msgs::DiagnosticStatus::OK) << "drops alone: ~state says when scans stop";
  EXPECT_EQ(value("scans dropped"), "3");
  EXPECT_EQ(value("last scan dropped"), h.last_scan_dropped);
  h.map_in_force = false;
  h.global_localization_queued = true;
  d = ToDiagnosticStatus(h, "n", "h");
  EXPECT_EQ(d.level, diagnostic_msgs::DiagnosticStatus::WARN);
  EXPECT_EQ(d.message, "waiting_for_map (global_localization queued until a map is in force)");
  EXPECT_EQ(value("map in force"), "none");
  h.map_in_force = true;
  h.error = "boom";
  EXPECT_EQ(ToDiagnosticStatus(h, "n", "h").level, diagnostic_msgs::DiagnosticStatus::ERROR);
}

}  // namespace
}  // namespace doorplate_localization

// Tests of the SLAM message conversions (slam_conversions.h) on tiny hand-made messages; the shared pose,
// grid and marker conversions are tested in pose_conversions_test.cpp and map_conversions_test.cpp.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "doorplate_localization/ros/slam_conversions.h"

namespace doorplate_localization {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

geometry_msgs::Transform Rpy(double x, double y, double roll, double pitch, double yaw) {
  // Rotation R = Rz(yaw) Ry(pitch) Rx(roll) as a quaternion.
  const double cr = std::cos(roll / 2), sr = std::sin(roll / 2), cp = std::cos(pitch / 2), sp = std::sin(pitch / 2);
  const double cy = std::cos(yaw / 2), sy = std::sin(yaw / 2);
  geometry_msgs::Transform t;
  t.translation.x = x;
  t.translation.y = y;
  t.rotation.w = cr * cp * cy + sr * sp * sy;
  t.rotation.x = sr * cp * cy - cr * sp * sy;
  t.rotation.y = cr * sp * cy + sr * cp * sy;
  t.rotation.z = cr * cp * sy - sr * sp * cy;
  return t;
}

sensor_msgs::LaserScan FourBeamScan() {
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = "laser";
  scan.angle_min = -1.5f;
  scan.angle_increment = 1.0f;
  scan.angle_max = 1.5f;
  scan.range_min = 0.15f;
  scan.range_max = 12.0f;
  scan.ranges = {1.0f, kInf, kNaN, 0.05f};
  return scan;
}

TEST(ToLaserMounting, ReadsALevelLaserAndFlagsAnUpsideDownOne) {
  LaserMounting m;
  ASSERT_EQ(ToLaserMounting(Rpy(0.2, 0.0, 0.0, 0.0, 0.1), &m), "");
  EXPECT_FALSE(m.upside_down);
  EXPECT_NEAR(m.pose.x_m, 0.2, 1e-12);
  EXPECT_NEAR(m.pose.theta_rad, 0.1, 1e-9);
  ASSERT_EQ(ToLaserMounting(Rpy(0.2, 0.0, M_PI, 0.0, 0.0), &m), "");
  EXPECT_TRUE(m.upside_down);
}

TEST(ToLaserMounting, RefusesATiltedScanPlane) {
  LaserMounting m;
  EXPECT_NE(ToLaserMounting(Rpy(0, 0, 0.0, 0.3, 0.0), &m).find("tilted"), std::string::npos);
}

TEST(ToMappingScan, MarksNoEchoAndInvalidBeamsAndKeepsTheGeometry) {
  LaserScan out;
  ASSERT_EQ(ToMappingScan(FourBeamScan(), LaserMounting{{0.1, 0.0, 0.0}, false}, 0.0, 1, &out), "");
  ASSERT_EQ(out.ranges_m.size(), 4u);
  EXPECT_FLOAT_EQ(out.ranges_m[0], 1.0f);
  EXPECT_TRUE(std::isinf(out.ranges_m[1]) && out.ranges_m[1] > 0);  // +inf: no echo
  EXPECT_TRUE(std::isnan(out.ranges_m[2]));
  EXPECT_TRUE(std::isnan(out.ranges_m[3]));  // below range_min
  EXPECT_FLOAT_EQ(out.angle_min_rad, -1.5);
  EXPECT_FLOAT_EQ(out.angle_increment_rad, 1.0);
  EXPECT_NEAR(out.laser_pose.x_m, 0.1, 1e-12);
}

TEST(ToMappingScan, ReadingsAtOrBeyondMaxRangeBecomeNoEcho) {
  sensor_msgs::LaserScan scan = FourBeamScan();
  scan.ranges = {5.0f, 4.0f, 13.0f, 1.0f};
  LaserScan out;
  ASSERT_EQ(ToMappingScan(scan, LaserMounting{}, 4.5, 1, &out), "");
  EXPECT_TRUE(std::isinf(out.ranges_m[0]));
  EXPECT_FLOAT_EQ(out.ranges_m[1], 4.0f);
  EXPECT_TRUE(std::isinf(out.ranges_m[2]));  // beyond range_max
}

TEST(ToMappingScan, MirrorsTheAnglesOfAnUpsideDownLaser) {
  LaserScan out;
  ASSERT_EQ(ToMappingScan(FourBeamScan(), LaserMounting{{}, true}, 0.0, 1, &out), "");
  EXPECT_FLOAT_EQ(out.angle_min_rad, 1.5);
  EXPECT_FLOAT_EQ(out.angle_increment_rad, -1.0);
}

TEST(ToMappingScan, RefusesBrokenShortAndAllInvalidScansLeavingTheOutputAlone) {
  LaserScan out;
  out.min_range_m = 42.0;
  sensor_msgs::LaserScan nan_increment = FourBeamScan();
  nan_increment.angle_increment = kNaN;
  EXPECT_NE(ToMappingScan(nan_increment, {}, 0.0, 1, &out), "");
  sensor_msgs::LaserScan short_scan = FourBeamScan();
  short_scan.ranges.resize(2);  // angle_min..angle_max says 4 beams
  EXPECT_NE(ToMappingScan(short_scan, {}, 0.0, 1, &out).find("make 4 beams"), std::string::npos);
  sensor_msgs::LaserScan all_nan = FourBeamScan();
  all_nan.ranges = {kNaN, kNaN, kInf, kNaN};
  EXPECT_NE(ToMappingScan(all_nan, {}, 0.0, 1, &out).find("only 0 of 4"), std::string::npos);
  EXPECT_EQ(out.min_range_m, 42.0);
}

TEST(ToPlateSighting, ComposesTheBearingWithTheCameraAxis) {
  TextDetection d;
  d.text = "105";
  d.confidence = 0.8f;
  d.bearing_rad = 0.1f;  // towards the image's left
  d.crossed_center = true;
  std::string why;
  const auto s = ToPlateSighting(d, CameraAxis{M_PI / 2, 1.0}, &why);
  ASSERT_TRUE(s.has_value()) << why;
  EXPECT_EQ(s->text, "105");
  EXPECT_NEAR(s->confidence, 0.8, 1e-6);
  EXPECT_NEAR(s->bearing_rad, M_PI / 2 + 0.1, 1e-6);
  EXPECT_FALSE(s->range_m.has_value());
  EXPECT_NEAR(ToPlateSighting(d, CameraAxis{M_PI - 0.05, 1.0}, &why)->bearing_rad, -M_PI + 0.05, 1e-6);  // wrapped
}

TEST(ToPlateSighting, SkipsDetectionsAwayFromTheCentreEmptyOrBroken) {
  TextDetection d;
  d.text = "105";
  d.crossed_center = false;
  std::string why;
  EXPECT_FALSE(ToPlateSighting(d, CameraAxis{0.0, 1.0}, &why));
  EXPECT_EQ(why, "not at the image-centre crossing");
  d.crossed_center = true;
  d.text.clear();
  EXPECT_FALSE(ToPlateSighting(d, CameraAxis{0.0, 1.0}, &why));
  d.text = "105";
  d.bearing_rad = kNaN;
  EXPECT_FALSE(ToPlateSighting(d, CameraAxis{0.0, 1.0}, &why));
  EXPECT_NE(why.find("bearing_rad"), std::string::npos);
  // What the mapping session would refuse is refused here (a fuzzing find): a text of separators only.
  d.bearing_rad = 0.0;
  d.text = "-";
  EXPECT_FALSE(ToPlateSighting(d, CameraAxis{0.0, 1.0}, &why));
  EXPECT_EQ(why, "PlateReading.text: empty");
}

// Issue 18: a 1 MB detection text reached the mapping session and its log line whole.
TEST(ToPlateSighting, RefusesATextLongerThanTheLimitNamingIt) {
  TextDetection d;
  d.text = std::string(1 << 20, '4');
  d.crossed_center = true;
  std::string why;
  EXPECT_FALSE(ToPlateSighting(d, CameraAxis{0.0, 1.0}, &why));
  EXPECT_EQ(why, "text: 1048576 bytes, more than the limit of 64 (limits::kMaxPlateTextBytes)");
  d.text = std::string(64, '4');
  EXPECT_TRUE(ToPlateSighting(d, CameraAxis{0.0, 1.0}, &why)) << why;
}

// A tf tree as a lookup: base_link -> laser (0.2 m ahead), base_link -> camera_optical (looking left),
// odom -> base_link at (1, 2, 0.5); anything else is missing.
TransformLookup FakeTf() {
  return [](const std::string& target, const std::string& source, const ros::Time&,
            std::string* problem) -> std::optional<geometry_msgs::Transform> {
    if (target == "base_link" && source == "laser") return Rpy(0.2, 0, 0, 0, 0);
    if (target == "base_link" && source == "camera_optical") return Rpy(0, 0, -M_PI / 2, 0, 0);
    if (target == "odom" && source == "base_link") return Rpy(1, 2, 0, 0, 0.5);
    *problem = "no tf " + target + " -> " + source;
    return std::nullopt;
  };
}

TEST(PrepareSlamScan, GivesTheScanWithItsMountingAndTheOdometryAtItsStamp) {
  LaserScan scan;
  Pose2D odom;
  ASSERT_EQ(PrepareSlamScan(FourBeamScan(), FakeTf(), SlamInputFrames{"odom", "base_link", 0.0, 1}, &scan, &odom), "");
  EXPECT_NEAR(scan.laser_pose.x_m, 0.2, 1e-12);
  EXPECT_NEAR(odom.x_m, 1.0, 1e-12);
  EXPECT_NEAR(odom.theta_rad, 0.5, 1e-9);
}

TEST(PrepareSlamScan, NamesTheMissingTransformOrTheBrokenScan) {
  LaserScan scan;
  Pose2D odom;
  sensor_msgs::LaserScan msg = FourBeamScan();
  msg.header.frame_id = "laser2";
  EXPECT_EQ(PrepareSlamScan(msg, FakeTf(), SlamInputFrames{"odom", "base_link", 0.0, 1}, &scan, &odom),
            "no tf base_link -> laser2");
  EXPECT_NE(PrepareSlamScan(FourBeamScan(), FakeTf(), SlamInputFrames{"odom2", "base_link", 0.0, 1}, &scan, &odom)
                .find("odom2"), std::string::npos);
  msg.header.frame_id.clear();
  EXPECT_EQ(PrepareSlamScan(msg, FakeTf(), SlamInputFrames{}, &scan, &odom), "header.frame_id is empty");
}

TEST(PrepareSlamSightings, KeepsCrossingsListsBrokenDetectionsAndNeedsTheCameraTf) {
  TextDetectionArray array;
  array.header.frame_id = "camera_optical";
  TextDetection d;
  d.text = "105";
  d.confidence = 0.9f;
  d.crossed_center = true;
  array.detections.push_back(d);       // used
  d.crossed_center = false;
  array.detections.push_back(d);       // silently skipped: not at the crossing
  d.crossed_center = true;
  d.confidence = 2.0f;
  array.detections.push_back(d);       // listed: broken
  std::vector<PlateReading> sightings;
  std::vector<std::string> rejected;
  Pose2D odom;
  ASSERT_EQ(PrepareSlamSightings(array, FakeTf(), SlamInputFrames{}, &sightings, &odom, &rejected), "");
  ASSERT_EQ(sightings.size(), 1u);
  EXPECT_NEAR(sightings[0].bearing_rad, M_PI / 2, 1e-6);
  EXPECT_NEAR(odom.y_m, 2.0, 1e-12);
  ASSERT_EQ(rejected.size(), 1u);
  EXPECT_NE(rejected[0].find("'105': confidence"), std::string::npos) << rejected[0];
  array.header.frame_id = "camera2";
  EXPECT_EQ(PrepareSlamSightings(array, FakeTf(), SlamInputFrames{}, &sightings, &odom, &rejected),
            "no tf base_link -> camera2");
  EXPECT_TRUE(sightings.empty());
}

SlamParticle At(const Pose2D& pose) {
  SlamParticle p{pose, 0.0, 0.0, TiledGrid(TiledGridOptions()), {}, {}};
  return p;
}

TEST(PoseEntropy, GrowsWithTheSpreadAndStaysFiniteForOnePose) {
  std::vector<SlamParticle> tight, wide;
  for (int i = 0; i < 8; ++i) {
    const double dx = (i % 2 ? 1 : -1) * 0.01 * (i + 1), dy = (i % 3 - 1) * 0.01, dt = (i % 4 - 1.5) * 0.01;
    tight.push_back(At({dx, dy, dt}));
    wide.push_back(At({10 * dx, 10 * dy, 10 * dt}));
  }
  EXPECT_LT(PoseEntropy(tight), PoseEntropy(wide));
  EXPECT_NEAR(PoseEntropy(wide) - PoseEntropy(tight), 3.0 * std::log(10.0), 1e-6);  // ½ ln(10⁶)
  std::vector<SlamParticle> one(3, At({1, 1, 1}));
  EXPECT_TRUE(std::isfinite(PoseEntropy(one)));
}

// The mapping nodelet's /diagnostics (issue 18): "mapping" only while scans are taken, why scans are
// dropped, an error above all.
TEST(ToMapperDiagnosticStatus, SaysMappingOnlyWhileScansAreTakenAndNamesDropsAndErrors) {
  MapperHealth h;
  diagnostic_msgs::DiagnosticStatus d = ToMapperDiagnosticStatus(h, "/slam_mapping: mapping", "/slam_mapping");
  EXPECT_EQ(d.level, diagnostic_msgs::DiagnosticStatus::WARN);
  EXPECT_EQ(d.message, "waiting_for_scan");
  EXPECT_EQ(d.name, "/slam_mapping: mapping");
  h.scan_age_s = 0.1;
  h.scan_rate_hz = 10.0;
  h.scans_processed = 42;
  h.map = "310 x 40 at 0.05 m";
  d = ToMapperDiagnosticStatus(h, "n", "n");
  EXPECT_EQ(d.level, diagnostic_msgs::DiagnosticStatus::OK);
  EXPECT_EQ(d.message, "mapping");
  const auto value = [&d](const std::string& key) {
    for (const auto& kv : d.values) {
      if (kv.key == key) return kv.value;
    }
    return std::string("(missing)");
  };
  EXPECT_EQ(value("scans processed"), "42");
  EXPECT_EQ(value("scan rate (Hz)"), "10.0");
  EXPECT_EQ(value("map"), "310 x 40 at 0.05 m");
  EXPECT_EQ(value("scans waiting for the camera"), "off");  // the default: scans do not wait
  h.scans_waiting_for_camera = 3;
  h.camera_waits_expired = 2;
  h.plates_late = 1;
  h.solves = 7;
  h.last_solve_s = 1.234;
  h.solves_deferred = 5;
  h.back_end_nodes = 900;
  h.nodes_on_mapped_ground = 600;
  d = ToMapperDiagnosticStatus(h, "/slam_mapping: mapping", "/slam_mapping");
  EXPECT_EQ(value("back-end nodes"), "900");
  EXPECT_EQ(value("nodes on mapped ground (scan not kept)"), "600");
  EXPECT_EQ(value("scans waiting for the camera"), "3");
  EXPECT_EQ(value("camera waits run out"), "2");
  EXPECT_EQ(value("plates later than the camera wait"), "1");
  EXPECT_EQ(value("back-end solves"), "7");
  EXPECT_EQ(value("last solve (s)"), "1.23");
  EXPECT_EQ(value("solves deferred (solve share)"), "5");
  h.scans_dropped = 3;
  h.last_drop = "/scan: no tf odom -> laser";
  d = ToMapperDiagnosticStatus(h, "n", "n");
  EXPECT_EQ(d.message, "mapping; last scan dropped: /scan: no tf odom -> laser");
  EXPECT_EQ(value("scans dropped"), "3");
  h.scan_age_s = 2.5;  // past scan_timeout_s: the laser or tf is gone
  EXPECT_EQ(ToMapperDiagnosticStatus(h, "n", "n").level, diagnostic_msgs::DiagnosticStatus::WARN);
  h.error = "TextSlam: boom";
  d = ToMapperDiagnosticStatus(h, "n", "n");
  EXPECT_EQ(d.level, diagnostic_msgs::DiagnosticStatus::ERROR);
  EXPECT_EQ(d.message.rfind("error: TextSlam: boom", 0), 0u);
}

}  // namespace
}  // namespace doorplate_localization

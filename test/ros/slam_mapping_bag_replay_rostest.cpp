// Issue 16's proof that the shipped loop is the measured one, on a recorded bag: the mapping nodelet fed
// by `rosbag play --clock` (ROS time, its tf filter and callbacks as users run it) and doorplate_map_bag
// reading the same bag with the same seed must give the same trajectory and plates (within 1 cm and
// 0.5°; the stamp order of MappingSession makes them equal). The bag is written here with the rosbag API:
// the simulator core drives 20 m along a corridor; scans and odometry tf at 10 Hz; the camera's arrays
// (empty, or a plate crossing the optical axis) every 0.1 s, recorded 0.45 s after their image, as OCR
// delivers them; the odometry tf recorded 0.25 s late, so the nodelet's tf filter holds each scan while
// arrays arrive (the offline tool reads all tf first: without the stamp order the two interleave scans
// and plates differently); plates every 2.5 m on the left wall (the camera looks left).
// Launched by slam_mapping_bag_replay.test (the nodelet standalone with config/mapping.yaml).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <sys/wait.h>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <std_srvs/Trigger.h>
#include <tf2_msgs/TFMessage.h>

#include "doorplate_localization/TextDetectionArray.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/ros/sim_conversions.h"
#include "doorplate_localization/sim/simulator.h"
#include "rostest_util.h"
#include "sim_bag_util.h"
#include "test_worlds.h"

namespace doorplate_localization {
namespace {

namespace fs = std::filesystem;
using rostest_util::PrivateParam;
using rostest_util::WaitFor;

constexpr double kCorridorWidthM = 2.0;
constexpr double kReportLagS = 0.45;   // an OCR report is recorded this long after its image
constexpr double kOdometryLagS = 0.25; // odometry tf this long after its stamp: the nodelet's scans wait for it


// Writes the bag; returns the number of plates reported.
int WriteBag(const std::string& path) {
  Simulator sim(test::RectangleCorridor(24.0, kCorridorWidthM), SimulatorOptions{});
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  const ros::Time t0(100.0);
  test::WriteStaticTf(&bag, t0, test::SimStaticTf(sim, t0));

  std::vector<double> plates_x;  // left (north) wall
  for (double x = 2.5; x < 21.0; x += 2.5) plates_x.push_back(x);
  std::vector<bool> reported(plates_x.size(), false);
  int reports = 0, step = 0;
  while (sim.true_pose().x_m < 21.5) {
    sim.SetCommand(0.5, 0.0);
    sim.Step();
    if (++step % 5 != 0) continue;  // 20 Hz: scans on even ticks, camera images on odd ones
    const ros::Time stamp = t0 + ros::Duration(sim.time_s());
    bag.write("/tf", stamp + ros::Duration(kOdometryLagS), test::Tf(ToTransformStampedMsg(sim.odom_pose(), "odom", "base_link", stamp)));
    if (step % 10 == 0) {
      bag.write("/scan", stamp, ToLaserScanMsg(sim.Scan(), 10.0, "laser", stamp));
      continue;
    }
    TextDetectionArray array;
    array.header.stamp = stamp;
    array.header.frame_id = "camera_optical";
    const Pose2D p = sim.true_pose();
    for (std::size_t k = 0; k < plates_x.size(); ++k) {
      const double bearing_in_base = std::atan2(kCorridorWidthM - p.y_m, plates_x[k] - p.x_m) - p.theta_rad;
      if (reported[k] || bearing_in_base < M_PI / 2) continue;  // crossing the optical axis (yaw +pi/2)
      reported[k] = true;
      ++reports;
      TextDetection d;
      d.text = std::to_string(301 + 2 * k);
      d.confidence = 0.9f;
      d.bearing_rad = static_cast<float>(bearing_in_base - M_PI / 2);
      d.frame_count = 3;
      d.crossed_center = true;
      array.detections.push_back(d);
    }
    bag.write("/text_detections", stamp + ros::Duration(kReportLagS), array);
  }
  // The camera's last array, after the last scan: no scan waits for the camera when the bag ends.
  TextDetectionArray last;
  last.header.stamp = t0 + ros::Duration(sim.time_s() + 0.05);
  last.header.frame_id = "camera_optical";
  bag.write("/text_detections", last.header.stamp + ros::Duration(kReportLagS), last);
  bag.close();
  return reports;
}

int RunCommand(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::map<int, Pose2D> ReadTrajectory(const std::string& path) {
  std::map<int, Pose2D> poses;
  std::ifstream in(path);
  int index = 0;
  Pose2D p;
  while (in >> index >> p.x_m >> p.y_m >> p.theta_rad) poses[index] = p;
  return poses;
}

TEST(SlamMappingBagReplay, TheNodeletFedByRosbagPlayMapsTheBagAsTheOfflineToolDoes) {
  const fs::path dir = PrivateParam<std::string>("work_dir");
  const fs::path nodelet_dir = PrivateParam<std::string>("nodelet_output_dir");
  const int seed = PrivateParam<int>("seed"), particles = PrivateParam<int>("particles");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string bag = (dir / "replay.bag").string();
  const int reports = WriteBag(bag);
  ASSERT_EQ(reports, 8);

  // Offline: the tool with the nodelet's seed and particles (config/mapping.yaml holds the core's defaults).
  const std::string offline = (dir / "offline").string();
  ASSERT_EQ(RunCommand(std::string(DOORPLATE_MAP_BAG) + " " + bag + " --out-dir " + offline + " --seed " +
                std::to_string(seed) + " --set num_particles=" + std::to_string(particles) + " --progress-s 0 2> " +
                (dir / "offline.log").string()),
            0);
  const std::map<int, Pose2D> offline_path = ReadTrajectory(offline + "/trajectory.txt");
  const TextMap offline_map = LoadTextMap(offline + "/map.text_map.yaml");
  ASSERT_EQ(offline_map.landmarks.size(), 8u);
  ASSERT_GT(offline_path.size(), 30u);

  // The nodelet: rosbag play at 2x, 2 s after it advertised (its subscriptions are connected by then: the first
  // scan, 0.1 s after the latched /tf_static, finds the mountings); then ~save_maps until everything played has
  // been mapped.
  ASSERT_TRUE(WaitFor([] { return ros::service::exists("/slam_mapping/save_maps", false); }, 60.0));
  ASSERT_EQ(RunCommand("rosbag play --clock -q -d 2 -r 2 " + bag + " > " + (dir / "play.log").string() + " 2>&1"), 0);
  ros::ServiceClient save = ros::NodeHandle().serviceClient<std_srvs::Trigger>("/slam_mapping/save_maps");
  std::map<int, Pose2D> nodelet_path;
  std::string last_message;
  const bool complete = WaitFor([&] {
    std_srvs::Trigger call;
    if (!save.call(call) || !call.response.success) return false;
    last_message = call.response.message;
    nodelet_path = ReadTrajectory((nodelet_dir / "map.trajectory.txt").string());
    return nodelet_path.size() >= offline_path.size();
  }, 60.0);
  ASSERT_TRUE(complete) << "the nodelet mapped " << nodelet_path.size() << " of " << offline_path.size()
                        << " poses; last save: " << last_message;
  const TextMap nodelet_map = LoadTextMap((nodelet_dir / "map.text_map.yaml").string());

  ASSERT_EQ(nodelet_path.size(), offline_path.size());
  for (const auto& [index, pose] : offline_path) {
    ASSERT_EQ(nodelet_path.count(index), 1u) << "scan " << index << " mapped offline only";
    const Pose2D& other = nodelet_path.at(index);
    EXPECT_LT(std::hypot(pose.x_m - other.x_m, pose.y_m - other.y_m), 0.01) << "scan " << index;
    EXPECT_LT(std::abs(std::remainder(pose.theta_rad - other.theta_rad, 2 * M_PI)), 0.5 * M_PI / 180) << "scan " << index;
  }
  ASSERT_EQ(nodelet_map.landmarks.size(), offline_map.landmarks.size());
  for (const TextLandmark& plate : offline_map.landmarks) {
    const TextLandmark* other = nullptr;
    for (const TextLandmark& l : nodelet_map.landmarks) other = l.text == plate.text ? &l : other;
    ASSERT_NE(other, nullptr) << plate.text << " mapped offline only";
    EXPECT_LT(Norm(plate.pose.Position() - other->pose.Position()), 0.01) << plate.text;
  }
}

}  // namespace
}  // namespace doorplate_localization

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "slam_mapping_bag_replay_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}

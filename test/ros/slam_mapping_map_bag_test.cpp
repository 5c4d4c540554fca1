// doorplate_map_bag end to end on a tiny synthetic bag written with the rosbag API: the simulator core
// drives 6 m along a 10 m × 2 m corridor; the bag holds its scans, tf (odom -> base_link at every scan,
// static base_link -> laser and -> camera_optical) and one doorplate detection as the plate crosses the
// camera's centre, plus broken messages the tool must drop without stopping. Runs the built tool
// (DOORPLATE_MAP_BAG) and loads what it wrote with the core loaders.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include "doorplate_localization/TextDetectionArray.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/ros/sim_conversions.h"
#include "doorplate_localization/sim/simulator.h"
#include "sim_bag_util.h"
#include "test_worlds.h"

namespace doorplate_localization {
namespace {

namespace fs = std::filesystem;

const Vec2 kPlate{5.0, 2.0};  // on the north wall, facing south


struct BagRun {
  Pose2D world_to_odom;   // map frame of the SLAM = odom frame at the first scan
  Pose2D final_true_pose;
};

// Writes the bag; returns the frames needed to check the results.
BagRun WriteBag(const std::string& path) {
  Simulator sim(test::RectangleCorridor(10.0, 2.0), SimulatorOptions{});
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  const ros::Time t0(100.0);
  test::WriteStaticTf(&bag, t0, test::SimStaticTf(sim, t0));

  BagRun run;
  run.world_to_odom = sim.true_pose().Compose(sim.odom_pose().Inverse());
  sim.SetCommand(0.5, 0.0);
  bool plate_reported = false;
  int step = 0;
  while (sim.true_pose().x_m < 7.0) {
    sim.SetCommand(0.5, 0.0);
    sim.Step();
    if (++step % 10 != 0) continue;  // 10 Hz sensors
    const ros::Time stamp = t0 + ros::Duration(sim.time_s());
    bag.write("/tf", stamp, test::Tf(ToTransformStampedMsg(sim.odom_pose(), "odom", "base_link", stamp)));
    bag.write("/scan", stamp, ToLaserScanMsg(sim.Scan(), 10.0, "laser", stamp));
    const Pose2D p = sim.true_pose();
    const double bearing_in_base = std::atan2(kPlate.y - p.y_m, kPlate.x - p.x_m) - p.theta_rad;
    if (!plate_reported && bearing_in_base >= M_PI / 2) {  // crossing the optical axis (yaw +pi/2)
      plate_reported = true;
      TextDetectionArray array;
      array.header.stamp = stamp;
      array.header.frame_id = "camera_optical";
      TextDetection d;
      d.text = "101";
      d.confidence = 0.9f;
      d.bearing_rad = static_cast<float>(bearing_in_base - M_PI / 2);
      d.frame_count = 3;
      d.crossed_center = true;
      array.detections.push_back(d);
      bag.write("/text_detections", stamp, array);
      array.header.frame_id = "nowhere";  // no tf: dropped
      bag.write("/text_detections", stamp, array);
    }
    if (step == 200) {  // broken scans: no frame, and a stamp from the past
      const ros::Time later = stamp + ros::Duration(0.001);
      bag.write("/scan", later, ToLaserScanMsg(sim.Scan(), 10.0, "", later));
      bag.write("/scan", stamp, ToLaserScanMsg(sim.Scan(), 10.0, "laser", t0));
    }
  }
  run.final_true_pose = sim.true_pose();
  bag.close();
  return run;
}

std::string Slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

class MapBagTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("map_bag_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  int Run(const std::string& args) {
    const std::string command = std::string(DOORPLATE_MAP_BAG) + " " + args + " 2> " + (dir_ / "stderr.txt").string();
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  fs::path dir_;
};

TEST_F(MapBagTest, MapsTheBagIntoLoadableMapsATrajectoryAndThePlate) {
  const BagRun run = WriteBag((dir_ / "run.bag").string());
  const fs::path out = dir_ / "out";
  ASSERT_EQ(Run((dir_ / "run.bag").string() + " --out-dir " + out.string() + " --seed 3 --set num_particles=10"), 0)
      << Slurp((dir_ / "stderr.txt").string());
  const std::string log = Slurp((dir_ / "stderr.txt").string());
  EXPECT_NE(log.find("(2 dropped)"), std::string::npos) << log;           // the two broken scans
  EXPECT_NE(log.find("arrays (1 dropped)"), std::string::npos) << log;    // the array without tf

  const OccupancyGrid grid = LoadOccupancyMap((out / "map.yaml").string());
  EXPECT_GT(grid.WidthM(), 6.0);   // the corridor seen so far: ~10 m long, 2 m wide
  EXPECT_GT(grid.HeightM(), 2.0);
  const TextMap text_map = LoadTextMap((out / "map.text_map.yaml").string());
  ASSERT_EQ(text_map.landmarks.size(), 1u) << log;
  EXPECT_EQ(text_map.landmarks[0].text, "101");
  EXPECT_EQ(text_map.occupancy_map, "map.yaml");
  const Vec2 plate_in_map = run.world_to_odom.Inverse().TransformPoint(kPlate);
  EXPECT_LT(Norm(text_map.landmarks[0].pose.Position() - plate_in_map), 0.3);

  std::ifstream trajectory((out / "trajectory.txt").string());
  int lines = 0, index = 0;
  Pose2D last;
  while (trajectory >> index >> last.x_m >> last.y_m >> last.theta_rad) ++lines;
  EXPECT_GE(lines, 10);  // ~6 m at linear_update_m 0.5
  const Pose2D true_in_map = run.world_to_odom.Inverse().Compose(run.final_true_pose);
  EXPECT_LT(std::hypot(last.x_m - true_in_map.x_m, last.y_m - true_in_map.y_m), 0.5);
}

TEST_F(MapBagTest, RefusesABadCommandLineAndAMissingBagWritingNothing) {
  EXPECT_EQ(Run((dir_ / "run.bag").string()), 2);  // no --out-dir
  EXPECT_EQ(Run("x.bag --out-dir " + dir_.string() + " --set no_such_option=1"), 2);
  EXPECT_EQ(Run((dir_ / "missing.bag").string() + " --out-dir " + (dir_ / "out").string()), 1);
  EXPECT_FALSE(fs::exists(dir_ / "out" / "map.yaml"));
}

}  // namespace
}  // namespace doorplate_localization

// Checker node of corridor_sim_nodelet.test: the sim nodelet, loaded through pluginlib by a nodelet manager,
// publishes scan, odom, tf, camera images on demand and ground truth that moves on cmd_vel. Every wait is on
// a condition with a wall-clock timeout; a ride_lift it cannot make (one world, no lifts) is refused naming the
// topic and the message, and ~floor says the world. Also checks LoadCorridorSimOptions against this node's
// parameters, a building of several floors' worlds included.
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <string>

#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <rosgraph_msgs/Clock.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "corridor_sim_options.h"
#include "doorplate_localization/sim/world_loader.h"
#include "rostest_util.h"

namespace doorplate_localization {
namespace {

using rostest_util::PrivateParam;
using rostest_util::WaitFor;

constexpr double kTimeoutS = 30.0;

TEST(CorridorSimNodelet, PublishesScanWithConfiguredBeamsSpanningTheCorridorWidth) {
  const World world = LoadWorldFile(PrivateParam<std::string>("world"));
  double corridor_width_m = 0.0;
  ASSERT_TRUE(ros::NodeHandle("~").getParam("corridor_width_m", corridor_width_m));
  ros::NodeHandle nh;
  sensor_msgs::LaserScan::ConstPtr scan;
  ros::Subscriber sub = nh.subscribe<sensor_msgs::LaserScan>(
      "scan", 1, [&](const sensor_msgs::LaserScan::ConstPtr& msg) { scan = msg; });
  ASSERT_TRUE(WaitFor([&] { return scan != nullptr; }));

  EXPECT_EQ("laser", scan->header.frame_id);
  ASSERT_EQ(static_cast<size_t>(world.sensors.laser.num_beams), scan->ranges.size());
  // Nearest echo within 20° of the robot's left and right (it starts parallel to the walls, 0.6 m from the
  // end wall behind it, which these cones do not reach first): their sum is the corridor width.
  const double cone_rad = 20.0 * M_PI / 180.0;
  double left_m = std::numeric_limits<double>::infinity(), right_m = left_m;
  for (size_t i = 0; i < scan->ranges.size(); ++i) {
    const double angle = NormalizeAngle(scan->angle_min + i * scan->angle_increment + world.sensors.laser.mount_yaw_rad);
    if (!std::isfinite(scan->ranges[i])) continue;
    if (std::fabs(angle - M_PI / 2) < cone_rad) left_m = std::min(left_m, static_cast<double>(scan->ranges[i]));
    if (std::fabs(angle + M_PI / 2) < cone_rad) right_m = std::min(right_m, static_cast<double>(scan->ranges[i]));
  }
  EXPECT_NEAR(corridor_width_m, left_m + right_m, 0.1) << "left " << left_m << " right " << right_m;
}

TEST(CorridorSimNodelet, PublishesOdometryAndTransformsForEverySensorFrame) {
  ros::NodeHandle nh;
  nav_msgs::Odometry::ConstPtr odom;
  ros::Subscriber sub =
      nh.subscribe<nav_msgs::Odometry>("odom", 1, [&](const nav_msgs::Odometry::ConstPtr& msg) { odom = msg; });
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  ASSERT_TRUE(WaitFor([&] { return odom != nullptr; }));
  EXPECT_EQ("odom", odom->header.frame_id);
  EXPECT_EQ("base_link", odom->child_frame_id);
  EXPECT_GT(odom->header.stamp.toSec(), 0.0);  // sim time
  for (const char* child : {"base_link", "laser", "camera_link", "camera_optical"}) {
    EXPECT_TRUE(WaitFor([&] { return buffer.canTransform("odom", child, ros::Time(0)); })) << "odom -> " << child;
  }
  EXPECT_TRUE(buffer.canTransform("base_link", "laser", ros::Time(0)));
}

TEST(CorridorSimNodelet, RendersA640x480Bgr8ImageForASubscriber) {
  ros::NodeHandle nh;
  sensor_msgs::Image::ConstPtr image;
  ros::Subscriber sub = nh.subscribe<sensor_msgs::Image>(
      "camera/image_raw", 1, [&](const sensor_msgs::Image::ConstPtr& msg) { image = msg; });
  ASSERT_TRUE(WaitFor([&] { return image != nullptr; }));
  EXPECT_EQ(640u, image->width);
  EXPECT_EQ(480u, image->height);
  EXPECT_EQ("bgr8", image->encoding);
  EXPECT_EQ("camera_optical", image->header.frame_id);
  EXPECT_EQ(image->step * image->height, image->data.size());
}

TEST(CorridorSimNodelet, DrivesForwardOnCmdVelAndStopsWhenCommandsStop) {
  ros::NodeHandle nh;
  nav_msgs::Odometry::ConstPtr first, latest;
  ros::Subscriber sub = nh.subscribe<nav_msgs::Odometry>("base_pose_ground_truth", 10,
                                                         [&](const nav_msgs::Odometry::ConstPtr& msg) {
                                                           if (!first) first = msg;
                                                           latest = msg;
                                                         });
  ros::Publisher cmd = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  ASSERT_TRUE(WaitFor([&] { return first != nullptr; }));
  EXPECT_EQ("map", first->header.frame_id);
  geometry_msgs::Twist forward;
  forward.linear.x = 0.5;
  const auto moved_m = [&] { return latest->pose.pose.position.x - first->pose.pose.position.x; };
  EXPECT_TRUE(WaitFor([&] { return moved_m() > 0.3; }, kTimeoutS, [&] { cmd.publish(forward); })) << "moved " << moved_m();
  // No more commands: after cmd_vel_timeout_s the robot stands still.
  EXPECT_TRUE(WaitFor([&] { return latest->twist.twist.linear.x == 0.0; }));
}

TEST(CorridorSimNodelet, RefusesARideItCannotMakeNamingTheTopicAndKeepsRunning) {
  ros::NodeHandle nh;
  const rostest_util::RosoutLog warnings;
  std::string floor;
  ros::Subscriber floor_sub = nh.subscribe<std_msgs::String>(
      "corridor_sim/floor", 1, [&](const std_msgs::String::ConstPtr& m) { floor = m->data; });
  ASSERT_TRUE(WaitFor([&] { return !floor.empty(); })) << "no latched corridor_sim/floor";
  EXPECT_EQ(floor, LoadWorldFile(PrivateParam<std::string>("world")).name);
  ros::Publisher ride = nh.advertise<std_msgs::String>("ride_lift", 1);
  std_msgs::String msg;
  msg.data = "A 3";
  EXPECT_TRUE(WaitFor([&] { return warnings.Has("/ride_lift: 'A 3': no lift 'A'", "the robot stays"); }, kTimeoutS,
                      [&] { ride.publish(msg); }));
  msg.data = "A";
  EXPECT_TRUE(WaitFor([&] { return warnings.Has("/ride_lift: 'A': expected '<lift id> <floor id>'"); }, kTimeoutS,
                      [&] { ride.publish(msg); }));
  int scans = 0;
  ros::Subscriber scan_sub =
      nh.subscribe<sensor_msgs::LaserScan>("scan", 5, [&](const sensor_msgs::LaserScan::ConstPtr&) { ++scans; });
  EXPECT_TRUE(WaitFor([&] { return scans >= 5; })) << "the simulator stopped after the refused rides";
  EXPECT_EQ(floor, LoadWorldFile(PrivateParam<std::string>("world")).name);
}

// LoadCorridorSimOptions, on parameters set under this node's private namespace.
TEST(LoadCorridorSimOptions, MissingWorldIsAnErrorNamingTheParameter) {
  ros::NodeHandle nh("~no_world");
  try {
    LoadCorridorSimOptions(nh);
    FAIL() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string::npos, std::string(e.what()).find(nh.resolveName("world"))) << e.what();
  }
}

TEST(LoadCorridorSimOptions, BrokenWorldFileIsAnErrorNamingParameterAndFile) {
  const std::string path = testing::TempDir() + "/corridor_sim_broken_world.yaml";
  std::ofstream(path) << "format_version: 1\nwalls: [unclosed\n";
  ros::NodeHandle nh("~broken_world");
  nh.setParam("world", path);
  try {
    LoadCorridorSimOptions(nh);
    FAIL() << "no error";
  } catch (const ParameterError& e) {
    const std::string what = e.what();
    EXPECT_NE(std::string::npos, what.find(nh.resolveName("world"))) << what;
    EXPECT_NE(std::string::npos, what.find(path)) << what;
  }
}

TEST(LoadCorridorSimOptions, RejectsNegativeOrMistypedValuesNamingTheParameter) {
  ros::NodeHandle nh("~bad_values");
  nh.setParam("world", PrivateParam<std::string>("world"));
  nh.setParam("real_time_factor", -1.0);
  EXPECT_THROW(LoadCorridorSimOptions(nh), ParameterError);
  nh.setParam("real_time_factor", std::string("fast"));
  try {
    LoadCorridorSimOptions(nh);
    FAIL() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string::npos, std::string(e.what()).find(nh.resolveName("real_time_factor"))) << e.what();
  }
  nh.setParam("real_time_factor", 0.0);
  nh.setParam("base_frame_id", std::string("odom"));  // clashes with odom_frame_id
  EXPECT_THROW(LoadCorridorSimOptions(nh), ParameterError);
}

TEST(LoadCorridorSimOptions, CameraSizeAndIntrinsicsOverrideTheWorldsAndAreChecked) {
  ros::NodeHandle nh("~camera_values");
  nh.setParam("world", PrivateParam<std::string>("world"));
  nh.setParam("camera/width_px", 1280);
  nh.setParam("camera/height_px", 720);
  nh.setParam("camera/fy_px", 1010.0);
  const CameraOptions camera = LoadCorridorSimOptions(nh).world.sensors.camera;
  EXPECT_EQ(camera.width_px, 1280);
  EXPECT_EQ(camera.height_px, 720);
  EXPECT_DOUBLE_EQ(camera.fy_px, 1010.0);
  EXPECT_DOUBLE_EQ(camera.fx_px, 0.0);  // still derived from the field of view
  nh.setParam("camera/cy_px", 720.0);   // beyond the last row
  try {
    LoadCorridorSimOptions(nh);
    FAIL() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string::npos, std::string(e.what()).find(nh.resolveName("camera/cy_px"))) << e.what();
  }
}

TEST(LoadCorridorSimOptions, ABuildingGivesEveryFloorsWorldWithTheStartFloorsSensors) {
  const std::string building = std::string(DOORPLATE_SOURCE_DIR) + "/worlds/hospital_two_floors.building.yaml";
  ros::NodeHandle nh("~building");
  nh.setParam("building", building);
  nh.setParam("floor", std::string("3"));
  nh.setParam("camera/width_px", 1280);
  const CorridorSimOptions o = LoadCorridorSimOptions(nh);
  ASSERT_EQ(o.floor_worlds.size(), 2u);
  EXPECT_EQ(o.start_floor, 1);
  EXPECT_EQ(o.world.name, "hospital_floor3_ring");
  EXPECT_EQ(o.building.lifts.size(), 2u);
  for (const World& w : o.floor_worlds) EXPECT_EQ(w.sensors.camera.width_px, 1280) << w.name;
  const auto load = [](const ros::NodeHandle& h) {
    ros::NodeHandle copy(h);
    return LoadCorridorSimOptions(copy);
  };
  nh.setParam("floor", std::string("4"));
  rostest_util::ExpectLoadErrorNaming<ParameterError>(load, nh, "floor");
  nh.setParam("floor", std::string("3"));
  nh.setParam("world", PrivateParam<std::string>("world"));  // both: refused
  rostest_util::ExpectLoadErrorNaming<ParameterError>(load, nh, "building");
  nh.deleteParam("building");
  rostest_util::ExpectLoadErrorNaming<ParameterError>(load, nh, "floor");  // a world has none
  nh.deleteParam("floor");
  nh.setParam("building", std::string(DOORPLATE_SOURCE_DIR) + "/maps/hospital_two_floors.building.yaml");
  nh.deleteParam("world");  // a maps building file names no worlds
  rostest_util::ExpectLoadErrorNaming<ParameterError>(load, nh, "building");
}

TEST(LoadCorridorSimOptions, ReadsValuesOverDefaults) {
  ros::NodeHandle nh("~good_values");
  nh.setParam("world", PrivateParam<std::string>("world"));
  nh.setParam("seed", 42);
  nh.setParam("real_time_factor", 0.0);
  nh.setParam("laser_frame_id", std::string("front_laser"));
  const CorridorSimOptions options = LoadCorridorSimOptions(nh);
  EXPECT_EQ(42u, options.simulator.seed);
  EXPECT_EQ(0.0, options.real_time_factor);
  EXPECT_EQ("front_laser", options.laser_frame_id);
  EXPECT_EQ("odom", options.odom_frame_id);
  EXPECT_TRUE(options.publish_clock);
  EXPECT_FALSE(options.world.walls.empty());
}

// Only in corridor_sim_waits_for_recorder.test (~wait_for_recorder_s set, a recorder's view): sim time stays at
// 0 while base_pose_ground_truth has no subscriber, even with the sensors subscribed (a localizer); once it has
// one, the first ground truth is from the start, so a recording holds the whole run.
TEST(CorridorSimRecorder, HoldsSimTimeUntilGroundTruthIsSubscribed) {
  ros::NodeHandle nh;
  int clocks = 0, scans = 0;
  ros::Subscriber clock_sub = nh.subscribe<rosgraph_msgs::Clock>(
      "/clock", 10, [&](const rosgraph_msgs::Clock::ConstPtr&) { ++clocks; });
  ros::Subscriber scan_sub = nh.subscribe<sensor_msgs::LaserScan>(
      "scan", 10, [&](const sensor_msgs::LaserScan::ConstPtr&) { ++scans; });
  // A negative check needs a span of time: 2 wall s in which an unheld simulator would publish hundreds of clocks.
  EXPECT_FALSE(WaitFor([&] { return clocks > 0 || scans > 0; }, 2.0));
  nav_msgs::Odometry::ConstPtr first;
  ros::Subscriber truth_sub = nh.subscribe<nav_msgs::Odometry>(
      "base_pose_ground_truth", 10, [&](const nav_msgs::Odometry::ConstPtr& m) { if (!first) first = m; });
  ASSERT_TRUE(WaitFor([&] { return first != nullptr; }, kTimeoutS));
  EXPECT_LT(first->header.stamp.toSec(), 0.1) << "the recording missed the start";
}

}  // namespace
}  // namespace doorplate_localization

int main(int argc, char** argv) {
  return doorplate_localization::rostest_util::RunCheckerTests(argc, argv, "corridor_sim_checker");
}

// Checker node of slam_mapping_nodelet.test: the simulator, corridor following, the text extractor and the
// mapping nodelet run in one manager while the robot drives down a 15.5 m corridor. Every wait is on a
// condition with a wall-clock timeout. Also checks LoadSlamMappingOptions against this node's parameters.
// The cases run in order; the drive starts with the launch, so the option checks come first (they are quick).
#include <cmath>
#include <filesystem>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <gtest/gtest.h>
#include <nav_msgs/GetMap.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/LaserScan.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/slam/rbpf_slam_options.h"
#include "slam_mapping_options.h"
#include "diagnostics_entry.h"
#include "rostest_util.h"

namespace doorplate_localization {
namespace {

using rostest_util::DiagnosticsEntry;
using rostest_util::WaitFor;

void ExpectErrorNaming(const ros::NodeHandle& nh, const std::string& parameter) {
  rostest_util::ExpectLoadErrorNaming<ParameterError>(LoadSlamMappingOptions, nh, parameter);
}

TEST(LoadSlamMappingOptions, WithoutParametersUsesGmappingsDefaultsForItsNames) {
  const SlamMappingNodeOptions o = LoadSlamMappingOptions(ros::NodeHandle("~empty"));
  EXPECT_EQ(o.slam.slam.num_particles, 30);
  EXPECT_EQ(o.slam.slam.linear_update_m, 1.0);
  EXPECT_EQ(o.slam.slam.angular_update_rad, 0.5);
  EXPECT_EQ(o.slam.slam.max_usable_range_m, 80.0);
  EXPECT_EQ(o.slam.slam.motion.trans_noise_from_rot, 0.2);
  EXPECT_EQ(o.map_update_interval_s, 5.0);
  EXPECT_EQ(o.temporal_update_s, -1.0);  // gmapping's: off
  EXPECT_EQ(o.base_frame, "base_link");
  EXPECT_EQ(o.slam.slam.matcher.field_sigma_m, TextSlamOptions().slam.matcher.field_sigma_m);  // core default
  EXPECT_TRUE(o.ignored_parameters.empty());
}

// config/mapping.yaml claims to hold the core's defaults, i.e. what doorplate_map_log / doorplate_map_bag run
// without --set: a default changed on one side only would make the nodelet map differently.
TEST(LoadSlamMappingOptions, TheShippedConfigRunsTheCoreDefaults) {
  const SlamMappingNodeOptions o = LoadSlamMappingOptions(ros::NodeHandle("~config"));
  const TextSlamOptions core;
  for (const std::string& name : TextSlamOptionNames()) {
    EXPECT_EQ(GetTextSlamOption(name, o.slam), GetTextSlamOption(name, core)) << name;
  }
  EXPECT_EQ(o.slam.slam.seed, core.slam.seed);
}

TEST(LoadSlamMappingOptions, ReadsCoreOptionsByTheirTableNamesWithSlashes) {
  ros::NodeHandle nh("~core");
  nh.setParam("num_particles", 7);
  nh.setParam("matcher/field_sigma_m", 0.2);
  nh.setParam("text/plate_sigma_m", 0.3);
  nh.setParam("linearUpdate", 0.7);
  nh.setParam("ogain", 3.0);
  nh.setParam("temporalUpdate", 2.5);
  nh.setParam("throttle_scans", 2);
  const SlamMappingNodeOptions o = LoadSlamMappingOptions(nh);
  // The session runs gmapping's scan throttling and map updates as set.
  const MappingSessionOptions session = ToMappingSessionOptions(o);
  EXPECT_EQ(session.temporal_update_s, 2.5);
  EXPECT_EQ(session.throttle_scans, 2);
  EXPECT_EQ(session.map_update_interval_s, o.map_update_interval_s);
  EXPECT_EQ(session.slam.slam.linear_update_m, 0.7);
  EXPECT_EQ(o.slam.slam.num_particles, 7);
  EXPECT_EQ(o.slam.slam.matcher.field_sigma_m, 0.2);
  EXPECT_EQ(o.slam.plate_sigma_m, 0.3);
  EXPECT_EQ(o.slam.slam.linear_update_m, 0.7);
  EXPECT_EQ(o.ignored_parameters, std::vector<std::string>{nh.resolveName("ogain")});
  EXPECT_EQ(SlamOptionParamName("grid.resolution_m"), "grid/resolution_m");
}

TEST(LoadSlamMappingOptions, RejectsBadValuesNamingTheParameter) {
  ros::NodeHandle nh("~bad");
  nh.setParam("particles", 7);
  nh.setParam("num_particles", 7);
  ExpectErrorNaming(nh, "num_particles");  // the same option twice
  nh.deleteParam("num_particles");
  nh.setParam("particles", 2.5);
  ExpectErrorNaming(nh, "particles");
  nh.setParam("particles", std::string("many"));
  ExpectErrorNaming(nh, "particles");
  nh.deleteParam("particles");
  nh.setParam("matcher/field_sigma_m", std::nan(""));
  ExpectErrorNaming(nh, "matcher/field_sigma_m");
  nh.deleteParam("matcher");
  nh.setParam("throttle_scans", 0);
  ExpectErrorNaming(nh, "throttle_scans");
  nh.deleteParam("throttle_scans");
  nh.setParam("map_frame", std::string("/map"));
  ExpectErrorNaming(nh, "map_frame");
  nh.deleteParam("map_frame");
  nh.setParam("map_name", std::string("a/b"));
  ExpectErrorNaming(nh, "map_name");
  nh.deleteParam("map_name");
  nh.setParam("resampleThreshold", 1.5);  // range checked by the core: the message names the field
  try {
    LoadSlamMappingOptions(nh);
    ADD_FAILURE() << "no error for resampleThreshold 1.5";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("resample_neff_ratio"), std::string::npos) << e.what();
  }
}

TEST(LoadSlamMappingOptions, TheRoomPatternIsTheBuildingsAndMustBeARegex) {
  ros::NodeHandle nh("~rooms");
  EXPECT_EQ(LoadSlamMappingOptions(nh).slam.room_pattern, kDefaultRoomPattern);
  nh.setParam("room_pattern", std::string("[0-9]{3}|WC"));
  EXPECT_EQ(LoadSlamMappingOptions(nh).slam.room_pattern, "[0-9]{3}|WC");
  nh.setParam("room_pattern", std::string("[0-9"));
  ExpectErrorNaming(nh, "room_pattern");
  nh.deleteParam("room_pattern");
}

// The nodelet, in the manager, while the robot drives.
TEST(SlamMappingNodelet, MapsTheCorridorReadsAPlateAnswersServicesAndSavesLoadableMaps) {
  ros::NodeHandle nh, pnh("~");
  std::vector<std::string> north_texts;
  ASSERT_TRUE(pnh.getParam("north_wall_texts", north_texts));
  std::string output_dir;
  ASSERT_TRUE(pnh.getParam("output_dir", output_dir));
  for (const char* file : {"map.pgm", "map.yaml", "map.text_map.yaml"}) std::filesystem::remove(output_dir + "/" + file);

  nav_msgs::OccupancyGrid::ConstPtr map;
  ros::Subscriber map_sub = nh.subscribe<nav_msgs::OccupancyGrid>(
      "map", 1, [&](const nav_msgs::OccupancyGrid::ConstPtr& m) { map = m; });
  std::set<std::string> landmark_texts;
  ros::Subscriber marker_sub = nh.subscribe<visualization_msgs::MarkerArray>(
      "text_landmarks", 1, [&](const visualization_msgs::MarkerArray::ConstPtr& m) {
        landmark_texts.clear();
        for (const auto& marker : m->markers) {
          if (marker.ns == "plate_text") landmark_texts.insert(marker.text);
        }
      });
  std::vector<std::string> scan_warnings;
  ros::Subscriber log_sub = nh.subscribe<rosgraph_msgs::Log>("/rosout", 100, [&](const rosgraph_msgs::Log::ConstPtr& m) {
    // The mapping nodelet's warning (the wall follower reports the same scan as an error, "stopping").
    if (m->level == rosgraph_msgs::Log::WARN && m->msg.find("/scan:") != std::string::npos &&
        m->msg.find("dropping it") != std::string::npos) {
      scan_warnings.push_back(m->msg);
    }
  });
  tf2_ros::Buffer tf_buffer;
  tf2_ros::TransformListener tf_listener(tf_buffer);

  // A map that spans most of the corridor: 15.5 m x 2 m, seen from inside (the laser reaches the far end).
  ASSERT_TRUE(WaitFor([&] { return map != nullptr; }, 120.0)) << "no map published";
  EXPECT_TRUE(WaitFor([&] { return map->info.width * map->info.resolution >= 12.0; }, 120.0));
  const double width_m = map->info.width * map->info.resolution, height_m = map->info.height * map->info.resolution;
  EXPECT_LT(width_m, 40.0);
  EXPECT_GT(height_m, 1.8);
  EXPECT_LT(height_m, 20.0);
  EXPECT_EQ(map->header.frame_id, "map");
  std::string tf_error;
  EXPECT_TRUE(WaitFor([&] { return tf_buffer.canTransform("map", "base_link", ros::Time(0), &tf_error); }, 30.0))
      << tf_error;

  nav_msgs::GetMap get_map;
  ASSERT_TRUE(ros::service::waitForService("dynamic_map", ros::Duration(30.0)));
  ASSERT_TRUE(ros::service::call("dynamic_map", get_map));
  EXPECT_GT(get_map.response.map.info.width, 0u);
  EXPECT_EQ(get_map.response.map.data.size(), get_map.response.map.info.width * get_map.response.map.info.height);

  // The camera reads the north wall: at least one of its plates becomes a landmark.
  EXPECT_TRUE(WaitFor([&] { return !landmark_texts.empty(); }, 180.0)) << "no text landmark";
  for (const std::string& text : landmark_texts) {
    EXPECT_NE(std::find(north_texts.begin(), north_texts.end(), text), north_texts.end()) << text;
  }

  // Broken scans are dropped with a warning naming the topic; the nodelet keeps answering.
  ros::Publisher scan_pub = nh.advertise<sensor_msgs::LaserScan>("scan", 1);
  sensor_msgs::LaserScan broken;
  broken.header.frame_id = "laser";
  broken.angle_increment = std::nanf("");
  broken.range_max = 10.0f;
  broken.ranges.assign(10, 1.0f);
  EXPECT_TRUE(WaitFor([&] { return !scan_warnings.empty(); }, 30.0, [&] {
    broken.header.stamp = ros::Time::now();
    scan_pub.publish(broken);
  }));

  std_srvs::Trigger save;
  ASSERT_TRUE(ros::service::waitForService("slam_mapping/save_maps", ros::Duration(30.0)));
  ASSERT_TRUE(ros::service::call("slam_mapping/save_maps", save));
  EXPECT_TRUE(save.response.success) << save.response.message;
  const OccupancyGrid saved = LoadOccupancyMap(output_dir + "/map.yaml");
  EXPECT_GT(saved.WidthM(), 12.0);
  const TextMap text_map = LoadTextMap(output_dir + "/map.text_map.yaml");
  EXPECT_GE(text_map.landmarks.size(), 1u);
  EXPECT_EQ(text_map.occupancy_map, "map.yaml");
  EXPECT_EQ(text_map.frame_id, "map");
}

// Issue 18: the mapper's condition on /diagnostics, as the localizer's ("mapping" while it takes scans).
TEST(SlamMappingNodelet, PublishesItsHealthOnDiagnostics) {
  const DiagnosticsEntry entry("/slam_mapping: mapping");
  const diagnostic_msgs::DiagnosticStatus& status = entry.status();
  const auto value = [&entry](const std::string& key) { return entry.Value(key); };
  ASSERT_TRUE(WaitFor([&] {
    return entry.seen() && status.level == diagnostic_msgs::DiagnosticStatus::OK && value("scan rate (Hz)") != "0.0" &&
           value("map") != "none yet";
  }, 60.0)) << "no healthy /slam_mapping diagnostics: " << status.message;
  EXPECT_EQ(status.message.rfind("mapping", 0), 0u) << status.message;
  EXPECT_GT(std::stod(value("scan rate (Hz)")), 1.0);
  EXPECT_GT(std::stoi(value("scans processed")), 0);
  EXPECT_EQ(std::stoi(value("particles")), 20);  // the launch file's ~particles
  EXPECT_NE(value("map").find(" x "), std::string::npos) << value("map");
  EXPECT_EQ(value("last error"), "none");
  // config/mapping.yaml: use_text with camera_wait_s 5: scans wait for the extractor's arrays (stamp order).
  EXPECT_NE(value("scans waiting for the camera"), "off");
  EXPECT_GE(std::stoi(value("scans waiting for the camera")), 0);
  EXPECT_GE(std::stoll(value("camera waits run out")), 0);
}

}  // namespace
}  // namespace doorplate_localization

int main(int argc, char** argv) {
  return doorplate_localization::rostest_util::RunCheckerTests(argc, argv, "slam_mapping_nodelet_rostest");
}

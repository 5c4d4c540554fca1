// Checker node of text_amcl_nodelet.test: the simulator, the wall follower (started disabled), the text
// extractor and Text AMCL run in one nodelet manager on the paper's closed-door corridor. Checks amcl's
// interface (services, latched topics, the text landmark markers), that bad input is reported naming the
// topic while the node keeps running, global localization (after global_localization and a drive along the corridor, ~state says converged and
// amcl_pose and tf map -> base_link agree with base_pose_ground_truth), then ~save_pose_rate and set_map
// (a refused map changes nothing: amcl_pose flows on, ~state and the latched map stay), ~state and
// /diagnostics, and a second localizer (/late, no map yet) that queues global_localization until its map.
// Every wait is on a condition with a wall-clock timeout. The cases run in order: the drive starts in the
// global localization case. The same .test runs text_amcl_options_rostest (the parameter loader).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <set>
#include <string>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/SetMap.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>
#include <std_srvs/Empty.h>
#include <std_srvs/SetBool.h>
#include <tf2/utils.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include "doorplate_localization/TextDetectionArray.h"
#include "diagnostics_entry.h"
#include "rostest_util.h"
#include "text_amcl_listener.h"

namespace doorplate_localization {
namespace {

using rostest_util::DiagnosticsEntry;
using rostest_util::WaitFor;

double DegreesBetween(double a_rad, double b_rad) {
  return std::fabs(std::remainder(a_rad - b_rad, 2.0 * M_PI)) * 180.0 / M_PI;
}

Listener* listener = nullptr;

// The nodelet, in the manager.
TEST(TextAmclNodelet, OffersAmclsServicesAndLatchedTopicsAndTheTextLandmarks) {
  for (const char* service : {"global_localization", "request_nomotion_update", "set_map"}) {
    EXPECT_TRUE(ros::service::waitForService(service, ros::Duration(60.0))) << service;
  }
  ASSERT_TRUE(WaitFor([] { return listener->markers && listener->cloud && listener->pose && !listener->state.empty(); },
                      60.0));
  int landmark_count = 0;
  ASSERT_TRUE(ros::NodeHandle("~").getParam("landmark_count", landmark_count));
  const auto& markers = listener->markers->markers;
  ASSERT_EQ(static_cast<int>(markers.size()), 1 + 2 * landmark_count);
  EXPECT_EQ(markers[0].action, visualization_msgs::Marker::DELETEALL);
  std::set<std::string> texts;
  for (const auto& m : markers) {
    if (m.type == visualization_msgs::Marker::TEXT_VIEW_FACING) texts.insert(m.text);
    if (m.action == visualization_msgs::Marker::ADD) {
      EXPECT_EQ(m.header.frame_id, "map");
    }
  }
  EXPECT_EQ(texts, (std::set<std::string>{"101", "102", "103", "104", "105", "106", "107", "108", "109", "110"}));
  EXPECT_EQ(listener->cloud->poses.size(), 5000u);  // started at ~initial_pose_* with max_particles
  EXPECT_EQ(listener->cloud->header.frame_id, "map");
  EXPECT_EQ(listener->pose->header.frame_id, "map");
}

TEST(TextAmclNodelet, ReportsBadInputNamingTheTopicAndKeepsRunning) {
  ros::NodeHandle nh;
  ros::Publisher scan_pub = nh.advertise<sensor_msgs::LaserScan>("scan", 1);
  ros::Publisher pose_pub = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("initialpose", 1);
  ros::Publisher text_pub = nh.advertise<TextDetectionArray>("text_detections", 1);
  ASSERT_TRUE(WaitFor([] { return ros::Time::now().toSec() > 2.0; }, 60.0)) << "no sim clock";
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = "laser";
  scan.header.stamp = ros::Time::now();
  scan.angle_min = -M_PI;
  scan.angle_increment = std::numeric_limits<float>::quiet_NaN();
  scan.range_min = 0.15f;
  scan.range_max = 12.0f;
  scan.ranges.assign(360, 1.0f);
  scan.angle_max = static_cast<float>(-M_PI + 359 * (2 * M_PI / 360));
  EXPECT_TRUE(WaitFor([] { return listener->Warned("/scan", "angle_increment must be finite"); }, 30.0,
                      [&] { scan_pub.publish(scan); }));
  scan.angle_increment = 2 * M_PI / 360;
  // 10 ranges whose angles say a full turn of 1-degree beams (issue 18): refused naming the topic.
  sensor_msgs::LaserScan short_scan = scan;
  short_scan.ranges.resize(10);
  EXPECT_TRUE(WaitFor([] { return listener->Warned("/scan: 10 ranges, but angle_min", "make 360 beams"); }, 30.0,
                      [&] {
                        short_scan.header.stamp = ros::Time::now();
                        scan_pub.publish(short_scan);
                      }));
  // Older than the simulator's latest scan (10 Hz) but within tf's cache, so only the order is wrong (a stamp
  // before the nodelet's tf listener started gave "no tf" on a loaded machine instead).
  EXPECT_TRUE(WaitFor([] { return listener->Warned("/scan", "time went backwards"); }, 30.0, [&] {
    scan.header.stamp = ros::Time::now() - ros::Duration(0.3);
    scan_pub.publish(scan);
  }));
  // A frame tf never has: the scan waits in the tf filter until newer scans push it out, then is dropped.
  sensor_msgs::LaserScan lost = scan;
  lost.header.frame_id = "nowhere";
  EXPECT_TRUE(WaitFor([] { return listener->Warned("/scan: no tf from 'nowhere' to 'odom'", "scan ignored"); },
                      30.0, [&] {
                        lost.header.stamp = ros::Time::now();
                        scan_pub.publish(lost);
                      }));
  geometry_msgs::PoseWithCovarianceStamped initial;
  initial.header.frame_id = "odom";
  initial.pose.pose.orientation.w = 1.0;
  EXPECT_TRUE(WaitFor([] { return listener->Warned("/initialpose", "expected 'map'"); }, 30.0,
                      [&] { pose_pub.publish(initial); }));
  TextDetectionArray detections;
  detections.header.frame_id = "nowhere";
  detections.detections.resize(1);
  detections.detections[0].text = "105";
  detections.detections[0].confidence = 0.9f;
  detections.detections[0].crossed_center = true;
  EXPECT_TRUE(WaitFor([] { return listener->Warned("/text_detections", "no tf from 'nowhere'"); }, 30.0,
                      [&] { text_pub.publish(detections); }));
  detections.header.frame_id = "camera_optical";
  detections.detections[0].text = "999";
  EXPECT_TRUE(WaitFor([] { return listener->Warned("/text_detections", "room '999' is not in the text map"); }, 30.0,
                      [&] { text_pub.publish(detections); }));
  // Still alive: a no-motion update makes the next scan publish a new estimate.
  const int before = listener->poses;
  std_srvs::Empty empty;
  EXPECT_TRUE(WaitFor([&] { return listener->poses > before; }, 30.0,
                      [&] { ros::service::call("request_nomotion_update", empty); }));
  EXPECT_EQ(listener->state.rfind("lost", 0), std::string::npos) << listener->state;
}

TEST(TextAmclNodelet, GlobalLocalizationConvergesOnTheTruePoseWhileFollowingTheCorridor) {
  ros::NodeHandle nh, pnh("~");
  double max_position_error_m = 0.0, max_heading_error_deg = 0.0;
  ASSERT_TRUE(pnh.getParam("max_position_error_m", max_position_error_m));
  ASSERT_TRUE(pnh.getParam("max_heading_error_deg", max_heading_error_deg));
  std_srvs::Empty empty;
  ASSERT_TRUE(ros::service::call("global_localization", empty));
  // The next cloud of max_particles spread along the corridor (clouds of earlier updates may still arrive).
  const auto spread_m = [] {
    double min_x = 1e9, max_x = -1e9;
    for (const auto& p : listener->cloud->poses) {
      min_x = std::min(min_x, p.position.x);
      max_x = std::max(max_x, p.position.x);
    }
    return max_x - min_x;
  };
  EXPECT_TRUE(WaitFor([&] { return listener->cloud->poses.size() == 5000u && spread_m() > 12.0; }))
      << "global localization spreads max_particles along the 15.5 m corridor; last cloud: "
      << listener->cloud->poses.size() << " poses over " << spread_m() << " m";
  // ~state leaves converged (the restart's waiting_for_scan, then tracking: no plate read yet). Waited for:
  // the state arrives on its own connection, possibly after the cloud.
  ASSERT_TRUE(WaitFor([] { return listener->state != "converged"; })) << "still converged after global_localization";

  ros::ServiceClient enable = nh.serviceClient<std_srvs::SetBool>("corridor_follower/enable");
  ASSERT_TRUE(enable.waitForExistence(ros::Duration(30.0)));
  std_srvs::SetBool drive;
  drive.request.data = true;
  ASSERT_TRUE(enable.call(drive));
  ASSERT_TRUE(WaitFor([] { return listener->state == "converged"; }, 300.0)) << "state " << listener->state;
  const auto estimate = listener->pose;  // published just before the state changed
  ASSERT_TRUE(WaitFor([&] { return listener->TruthAt(estimate->header.stamp) != nullptr; }, 10.0));
  const auto truth = listener->TruthAt(estimate->header.stamp);
  const double error_m = std::hypot(estimate->pose.pose.position.x - truth->pose.pose.position.x,
                                    estimate->pose.pose.position.y - truth->pose.pose.position.y);
  const double error_deg =
      DegreesBetween(tf2::getYaw(estimate->pose.pose.orientation), tf2::getYaw(truth->pose.pose.orientation));
  std::printf("converged at %.2f s: estimate (%.3f, %.3f), truth (%.3f, %.3f): %.3f m, %.2f deg\n",
              estimate->header.stamp.toSec(), estimate->pose.pose.position.x, estimate->pose.pose.position.y,
              truth->pose.pose.position.x, truth->pose.pose.position.y, error_m, error_deg);
  std::fflush(stdout);
  ROS_INFO("converged: %.3f m, %.2f deg from the truth", error_m, error_deg);
  EXPECT_LT(error_m, max_position_error_m);
  EXPECT_LT(error_deg, max_heading_error_deg);
  EXPECT_GT(estimate->pose.covariance[0], 0.0);

  // tf map -> odom -> base_link agrees with the truth too (at the latest common time).
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener tf_listener(buffer);
  geometry_msgs::TransformStamped map_to_base;
  ASSERT_TRUE(WaitFor([&] {
    try {
      map_to_base = buffer.lookupTransform("map", "base_link", ros::Time(0));
      return listener->TruthAt(map_to_base.header.stamp) != nullptr;
    } catch (const tf2::TransformException&) {
      return false;
    }
  }));
  const auto truth_tf = listener->TruthAt(map_to_base.header.stamp);
  EXPECT_LT(std::hypot(map_to_base.transform.translation.x - truth_tf->pose.pose.position.x,
                       map_to_base.transform.translation.y - truth_tf->pose.pose.position.y),
            max_position_error_m);
  EXPECT_LT(DegreesBetween(tf2::getYaw(map_to_base.transform.rotation), tf2::getYaw(truth_tf->pose.pose.orientation)),
            max_heading_error_deg);

  // The particle cloud has gathered around the estimate.
  const int clouds_now = listener->clouds;
  ASSERT_TRUE(WaitFor([&] { return listener->clouds > clouds_now; }, 60.0));
  int near = 0;
  const auto& cloud = listener->cloud->poses;
  for (const auto& p : cloud) {
    near += std::hypot(p.position.x - estimate->pose.pose.position.x, p.position.y - estimate->pose.pose.position.y) <
            1.0;
  }
  EXPECT_GT(near, 0.8 * cloud.size());
}

TEST(TextAmclNodelet, SavesTheEstimateAsTheInitialPoseAndSetMapRestartsAtTheGivenPose) {
  ros::NodeHandle nh;
  ASSERT_FALSE(listener->truth.empty());
  // ~save_pose_rate (0.5 Hz): the converged estimate is written back to ~initial_pose_*.
  double saved_x = -100.0;
  EXPECT_TRUE(WaitFor([&] {
    return nh.getParam("amcl/initial_pose_x", saved_x) &&
           std::fabs(saved_x - listener->truth.back()->pose.pose.position.x) < 0.5;
  })) << "saved initial_pose_x " << saved_x;

  nav_msgs::OccupancyGrid::ConstPtr map;
  ros::Subscriber map_sub =
      nh.subscribe<nav_msgs::OccupancyGrid>("map", 1, [&](const nav_msgs::OccupancyGrid::ConstPtr& m) { map = m; });
  ASSERT_TRUE(WaitFor([&] { return map != nullptr; })) << "the ~map_file map is latched on map";
  nav_msgs::SetMap set_map;
  set_map.request.map = *map;
  set_map.request.map.data.resize(3);
  ASSERT_TRUE(ros::service::call("set_map", set_map));
  EXPECT_FALSE(set_map.response.success) << "a map whose data does not match its size is refused";
  EXPECT_TRUE(WaitFor([] { return listener->Warned("/set_map", "data has 3 cells"); }));

  // Issue 18: an all-occupied 100 x 100 map used to throw inside the filter and end localization. Now it is
  // refused before anything changes: success false, the reason logged, amcl_pose flowing, ~state and the
  // latched map as they were.
  const std::string state_before = listener->state;
  listener->states_seen.clear();
  const unsigned width_before = map->info.width;
  set_map.request.map = *map;
  set_map.request.map.info.width = set_map.request.map.info.height = 100;
  set_map.request.map.data.assign(100 * 100, 100);
  set_map.request.initial_pose.header.frame_id = "map";
  set_map.request.initial_pose.pose.pose = listener->truth.back()->pose.pose;
  ASSERT_TRUE(ros::service::call("set_map", set_map));
  EXPECT_FALSE(set_map.response.success) << "a map without a free cell is refused";
  EXPECT_TRUE(WaitFor([] { return listener->Warned("/set_map", "no free cell: all 10000 cells"); }));
  EXPECT_TRUE(WaitFor([] { return listener->Warned("the map in force", "is kept"); }));
  EXPECT_EQ(listener->state, state_before);
  const int poses_after_refusal = listener->poses;
  EXPECT_TRUE(WaitFor([&] { return listener->poses > poses_after_refusal + 3; }, 60.0))
      << "amcl_pose stopped after a refused set_map";
  for (const std::string& seen : listener->states_seen) {  // no restart, no error since the call
    EXPECT_TRUE(seen == "converged" || seen == "tracking") << seen;
  }
  nav_msgs::OccupancyGrid::ConstPtr map_now;
  ros::Subscriber map_again =
      nh.subscribe<nav_msgs::OccupancyGrid>("map", 1, [&](const nav_msgs::OccupancyGrid::ConstPtr& m) { map_now = m; });
  ASSERT_TRUE(WaitFor([&] { return map_now != nullptr; }));
  EXPECT_EQ(map_now->info.width, width_before) << "the latched map is still the one in force";
  set_map.request.initial_pose = geometry_msgs::PoseWithCovarianceStamped();

  const auto truth = listener->truth.back();
  set_map.request.map = *map;
  set_map.request.initial_pose.header.frame_id = "map";
  set_map.request.initial_pose.pose.pose = truth->pose.pose;
  set_map.request.initial_pose.pose.covariance[0] = set_map.request.initial_pose.pose.covariance[7] = 0.01;
  set_map.request.initial_pose.pose.covariance[35] = 0.01;
  const int clouds_before = listener->clouds;
  ASSERT_TRUE(ros::service::call("set_map", set_map));
  EXPECT_TRUE(set_map.response.success);
  // The filter restarts with max_particles around the given pose.
  const auto near_truth = [&] {
    int near = 0;
    for (const auto& p : listener->cloud->poses) {
      near += std::hypot(p.position.x - truth->pose.pose.position.x, p.position.y - truth->pose.pose.position.y) < 0.5;
    }
    return near;
  };
  EXPECT_TRUE(WaitFor([&] {
    return listener->clouds > clouds_before && listener->cloud->poses.size() == 5000u && near_truth() > 4500;
  })) << listener->cloud->poses.size() << " poses, " << near_truth() << " within 0.5 m of the given pose";
}

// /diagnostics: the localizer's entry says what ~state says, with the scan rate and the map in force.
TEST(TextAmclNodelet, PublishesItsHealthOnDiagnostics) {
  const DiagnosticsEntry entry("/amcl: localization");
  const diagnostic_msgs::DiagnosticStatus& status = entry.status();
  const auto value = [&entry](const std::string& key) { return entry.Value(key); };
  ASSERT_TRUE(WaitFor([&] {
    return entry.seen() && value("scan rate (Hz)") != "0.0" && status.message.rfind(listener->state, 0) == 0;
  }, 30.0)) << "no /amcl diagnostics, or they disagree with ~state '" << listener->state << "': " << status.message;
  EXPECT_NE(value("map in force").find(" x "), std::string::npos) << value("map in force");
  EXPECT_GT(std::stod(value("scan rate (Hz)")), 1.0);
  EXPECT_NE(value("odometry tf age (s)"), "no transform");
  EXPECT_EQ(value("last error"), "none");
  EXPECT_GT(std::stoll(value("scans dropped")), 0) << "the broken scans of ReportsBadInput... count";
}

// Issue 19 (an amcl habit): global_localization before the map has arrived is queued, and the first map
// starts with global localization (not at ~initial_pose_*), said in the log and on /diagnostics.
TEST(TextAmclNodelet, GlobalLocalizationBeforeAMapIsQueuedUntilOneArrives) {
  ros::NodeHandle nh;
  std::string state;
  std::set<std::string> states;
  geometry_msgs::PoseArray::ConstPtr cloud;
  const DiagnosticsEntry late_diagnostics("/late/late_amcl: localization");
  const auto queued_on_diagnostics = [&late_diagnostics] {
    return late_diagnostics.status().message.find("queued") != std::string::npos;
  };
  ros::Subscriber subs[2] = {
      nh.subscribe<std_msgs::String>("late/late_amcl/state", 10,
                                     [&](const std_msgs::String::ConstPtr& m) {
                                       state = m->data;
                                       states.insert(m->data);
                                     }),
      nh.subscribe<geometry_msgs::PoseArray>("late/particlecloud", 2,
                                             [&](const geometry_msgs::PoseArray::ConstPtr& m) { cloud = m; })};
  ASSERT_TRUE(ros::service::waitForService("late/global_localization", ros::Duration(60.0)));
  ASSERT_TRUE(WaitFor([&] { return state == "waiting_for_map"; })) << "state '" << state << "'";
  std_srvs::Empty empty;
  ASSERT_TRUE(ros::service::call("late/global_localization", empty));
  EXPECT_TRUE(WaitFor([] { return listener->Warned("/late/global_localization", "queued"); }));
  EXPECT_TRUE(WaitFor(queued_on_diagnostics)) << "/diagnostics does not say it is queued";
  EXPECT_EQ(state, "waiting_for_map");

  // The map arrives (the corridor /amcl latches): the filter starts spread over it.
  nav_msgs::OccupancyGrid::ConstPtr map;
  ros::Subscriber map_sub =
      nh.subscribe<nav_msgs::OccupancyGrid>("map", 1, [&](const nav_msgs::OccupancyGrid::ConstPtr& m) { map = m; });
  ASSERT_TRUE(WaitFor([&] { return map != nullptr; }));
  ros::Publisher late_map = nh.advertise<nav_msgs::OccupancyGrid>("late/map", 1, /*latch=*/true);
  late_map.publish(*map);
  const auto spread_m = [&] {
    double lo = 1e9, hi = -1e9;
    for (const auto& p : cloud->poses) {
      lo = std::min(lo, p.position.x);
      hi = std::max(hi, p.position.x);
    }
    return hi - lo;
  };
  EXPECT_TRUE(WaitFor([&] { return cloud && cloud->poses.size() == 500u && spread_m() > 12.0; }, 60.0))
      << "the queued global localization did not spread the particles over the corridor";
  // No scan reaches /late: it says so, and never converged.
  EXPECT_TRUE(WaitFor([&] { return state == "waiting_for_scan"; })) << "state '" << state << "'";
  EXPECT_EQ(states.count("converged"), 0u);
}

}  // namespace
}  // namespace doorplate_localization

int main(int argc, char** argv) {
  return doorplate_localization::rostest_util::RunCheckerTests(argc, argv, "text_amcl_checker", [] {
    doorplate_localization::Listener listener;  // after ros::init: it subscribes
    doorplate_localization::listener = &listener;
    return RUN_ALL_TESTS();
  });
}

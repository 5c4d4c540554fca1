// The text_amcl_nodelet checker's view of the graph (text_amcl_nodelet_rostest.cpp): what Text AMCL publishes
// (state, amcl_pose, particlecloud, text_landmarks), the simulator's ground truth and the WARN+ rosout lines.
// Construct after ros::init: it subscribes.
#pragma once

#include <cstddef>
#include <deque>
#include <limits>
#include <set>
#include <string>

#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <std_msgs/String.h>
#include <visualization_msgs/MarkerArray.h>

#include "rostest_util.h"

namespace doorplate_localization {

// Everything the nodelet publishes, and the simulator's ground truth, as the checker sees it.
struct Listener {
  ros::NodeHandle nh;
  std::string state;
  std::set<std::string> states_seen;
  geometry_msgs::PoseWithCovarianceStamped::ConstPtr pose;
  geometry_msgs::PoseArray::ConstPtr cloud;
  int clouds = 0;
  int poses = 0;
  visualization_msgs::MarkerArray::ConstPtr markers;
  std::deque<nav_msgs::Odometry::ConstPtr> truth;  // the last ~40 s
  // WARN and above from /rosout, all of them.
  rostest_util::RosoutLog warnings{rosgraph_msgs::Log::WARN, std::numeric_limits<std::size_t>::max()};
  ros::Subscriber subs[5];

  Listener() {
    subs[0] = nh.subscribe<std_msgs::String>("amcl/state", 10, [this](const std_msgs::String::ConstPtr& m) {
      state = m->data;
      states_seen.insert(m->data);
    });
    subs[1] = nh.subscribe<geometry_msgs::PoseWithCovarianceStamped>(
        "amcl_pose", 10, [this](const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& m) {
          pose = m;
          ++poses;
        });
    subs[2] = nh.subscribe<geometry_msgs::PoseArray>("particlecloud", 2, [this](const geometry_msgs::PoseArray::ConstPtr& m) {
      cloud = m;
      ++clouds;
    });
    subs[3] = nh.subscribe<visualization_msgs::MarkerArray>(
        "text_landmarks", 1, [this](const visualization_msgs::MarkerArray::ConstPtr& m) { markers = m; });
    subs[4] = nh.subscribe<nav_msgs::Odometry>("base_pose_ground_truth", 100, [this](const nav_msgs::Odometry::ConstPtr& m) {
      truth.push_back(m);
      if (truth.size() > 2000) truth.pop_front();
    });
  }

  bool Warned(const std::string& a, const std::string& b) const { return warnings.Has(a, b); }

  nav_msgs::Odometry::ConstPtr TruthAt(const ros::Time& stamp) const { return rostest_util::TruthNear(truth, stamp); }
};

}  // namespace doorplate_localization

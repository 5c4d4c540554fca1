// Helpers of the tests that write a bag from the simulator core with the rosbag API
// (slam_mapping_map_bag_test, slam_mapping_bag_replay_rostest): the tf messages a recorded run holds.
// Header-only. Frames: odom, base_link, laser, camera_optical.
#pragma once

#include <cmath>

#include <string>

#include <boost/make_shared.hpp>
#include <geometry_msgs/TransformStamped.h>
#include <ros/message_traits.h>
#include <ros/time.h>
#include <rosbag/bag.h>
#include <tf2_msgs/TFMessage.h>

#include "doorplate_localization/ros/sim_conversions.h"
#include "doorplate_localization/sim/simulator.h"

namespace doorplate_localization::test {

// One transform as a /tf message.
inline tf2_msgs::TFMessage Tf(const geometry_msgs::TransformStamped& t) {
  tf2_msgs::TFMessage msg;
  msg.transforms.push_back(t);
  return msg;
}

// The /tf_static message at `stamp`: base_link -> laser (the simulator's mount, 0.25 m up) and
// base_link -> camera_optical, an optical frame looking left, upright (z -> +y, x -> +x, y -> -z).
inline tf2_msgs::TFMessage SimStaticTf(const Simulator& sim, const ros::Time& stamp) {
  tf2_msgs::TFMessage statics;
  statics.transforms.push_back(ToTransformStampedMsg(sim.laser().MountPose(), "base_link", "laser", stamp, 0.25));
  geometry_msgs::TransformStamped camera;
  camera.header.frame_id = "base_link";
  camera.header.stamp = stamp;
  camera.child_frame_id = "camera_optical";
  camera.transform.rotation.x = -std::sqrt(0.5);
  camera.transform.rotation.w = std::sqrt(0.5);
  statics.transforms.push_back(camera);
  return statics;
}

// Writes /tf_static as `rosbag record` does: on a latched connection, so that rosbag play latches it and a
// node whose tf listener connects after the first message still gets the mountings (without the flag, play
// publishes it once, 0.2 s after advertising, and a late subscriber never sees the static frames).
inline void WriteStaticTf(rosbag::Bag* bag, const ros::Time& stamp, const tf2_msgs::TFMessage& statics) {
  auto header = boost::make_shared<ros::M_string>();
  (*header)["callerid"] = "/doorplate_test_recorder";
  (*header)["latching"] = "1";
  (*header)["type"] = ros::message_traits::datatype(statics);
  (*header)["md5sum"] = ros::message_traits::md5sum(statics);
  (*header)["message_definition"] = ros::message_traits::definition(statics);
  bag->write("/tf_static", stamp, statics, header);
}

}  // namespace doorplate_localization::test

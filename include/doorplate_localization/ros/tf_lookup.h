// The one way the nodelets and the bag tools read tf: a transform or a planar pose, with the same timeout rule and
// the same problem text everywhere ("no tf from '<source>' to '<target>': <tf2's reason>"). Library
// doorplate_ros_conversions. Units: metres, radians, seconds.
#pragma once

#include <optional>
#include <string>

#include <geometry_msgs/Transform.h>
#include <ros/time.h>
#include <tf2/buffer_core.h>
#include <tf2_ros/buffer.h>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

// `source` in `target` (target_T_source) at `stamp` (0: the latest), waiting up to `timeout_s` for it (a live
// buffer). nullopt with *problem = "no tf from '<source>' to '<target>': <reason>" when tf has none (frame
// names and reason cut for the log, limits::TruncateForLog).
std::optional<geometry_msgs::Transform> LookupTransform(const tf2_ros::Buffer& buffer, const std::string& target,
                                                        const std::string& source, const ros::Time& stamp,
                                                        double timeout_s, std::string* problem);
// The same from a buffer that will not change (a bag's tf read up front, doorplate_map_bag): no waiting.
std::optional<geometry_msgs::Transform> LookupTransform(const tf2::BufferCore& buffer, const std::string& target,
                                                        const std::string& source, const ros::Time& stamp,
                                                        std::string* problem);

// LookupTransform as a planar pose (ToPose2D). nullopt with *problem set when tf has none or the transform is
// not finite ("tf from 'a' to 'b': <reason>").
std::optional<Pose2D> LookupPlanarPose(const tf2_ros::Buffer& buffer, const std::string& target,
                                       const std::string& source, const ros::Time& stamp, double timeout_s,
                                       std::string* problem);

// The LATEST transform `source` in `target` as a planar pose, for a loop that steers on the newest odometry rather
// than wait for tf at a sensor reading's stamp, but refused when it is older than `needed_at` by more than
// `max_lag_s`: *problem = "the latest tf from 'base_link' to 'odom' is 0.500 s older than needed (at 11.500 s;
// limit 0.300 s)". A turn measured on odometry that stood still while the robot kept turning overshoots (tf's
// listener thread starved on a loaded machine: a sweep turned ~4 rad instead of pi and ended facing a wall).
// No tf at all within `timeout_s` (waited for at the start, when none has come yet), or a non-finite one:
// nullopt with LookupPlanarPose's problem.
std::optional<Pose2D> LookupLatestPlanarPose(const tf2_ros::Buffer& buffer, const std::string& target,
                                             const std::string& source, const ros::Time& needed_at, double max_lag_s,
                                             double timeout_s, std::string* problem);

}  // namespace doorplate_localization

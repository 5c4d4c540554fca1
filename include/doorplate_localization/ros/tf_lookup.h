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

}  // namespace doorplate_localization

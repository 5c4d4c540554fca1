// A planar pose from tf, shared by the nodelets that read the robot's pose or a sensor mount from a tf2
// buffer (Text AMCL, go-to-room). Library doorplate_ros_conversions. Units: metres, radians.
#pragma once

#include <optional>
#include <string>

#include <ros/time.h>
#include <tf2_ros/buffer.h>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

// `source` in `target` (target_T_source) at `stamp` (0: the latest) as a planar pose (ToPose2D), waiting
// up to `timeout_s` for it. nullopt with *problem set when tf has none ("no tf from 'laser' to 'base_link':
// <tf2's reason>") or it is not finite ("tf from 'a' to 'b': <reason>").
std::optional<Pose2D> LookupPlanarPose(const tf2_ros::Buffer& buffer, const std::string& target,
                                       const std::string& source, const ros::Time& stamp, double timeout_s,
                                       std::string* problem);

}  // namespace doorplate_localization

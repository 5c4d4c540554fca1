// Parameters of WallFollowerNodelet, read and validated once from its private namespace.
#pragma once

#include <string>

#include <ros/node_handle.h>

#include "doorplate_localization/behaviour/wall_follower.h"
#include "doorplate_localization/ros/param_reader.h"

namespace doorplate_localization {

struct WallFollowerNodeOptions {
  WallFollowerOptions follower;      // ~wall_side, ~wall_distance_m, ~cruise_speed_mps, ... (same names)
  std::string base_frame_id = "base_link";
  double scan_timeout_s = 0.5;       // no valid scan for this long (ROS time): publish a stop
  bool enabled = true;               // ~enabled: start driving at once (else wait for ~enable)
};

// Throws ParameterError naming the parameter, e.g. "/follower/wall_side must be 'left' or 'right', got up".
WallFollowerNodeOptions LoadWallFollowerOptions(const ros::NodeHandle& private_nh);

}  // namespace doorplate_localization

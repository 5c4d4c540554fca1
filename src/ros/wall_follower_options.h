// Parameters of WallFollowerNodelet, read and validated once from its private namespace.
#pragma once

#include <string>

#include <ros/node_handle.h>

#include "doorplate_localization/behaviour/corridor_sweep.h"
#include "doorplate_localization/behaviour/floor_explorer.h"
#include "doorplate_localization/behaviour/wall_follower.h"
#include "doorplate_localization/ros/param_reader.h"

namespace doorplate_localization {

// What the nodelet drives: "follow" one wall to the corridor's end and stop; "sweep" the paper's mapping
// path (follow out, turn around, follow the other wall back, stop); "patrol" sweep again and again (the
// search strategy of global localization and long runs); "explore" a whole floor (FloorExplorer: follow one
// wall wherever it leads, turn round, follow the other; each pass ends on plates read again, so the
// nodelet also subscribes text_detections).
enum class CorridorDriveMode { kFollow, kSweep, kPatrol, kExplore };

struct WallFollowerNodeOptions {
  WallFollowerOptions follower;      // ~wall_side, ~wall_distance_m, ~cruise_speed_mps, ... (same names)
  CorridorDriveMode mode = CorridorDriveMode::kFollow;  // ~mode: follow | sweep | patrol
  CorridorSweepOptions sweep;        // sweep.follower = follower; ~turn_speed_rps
  // explore: steering.wall_side / wall_distance_m / cruise_speed_mps / max_angular_speed_rps = the
  // follower's; ~explore/passes, ~explore/revisit_plates, ~explore/min_revisit_travel_m,
  // ~explore/max_pass_distance_m; turn_speed_rps as for sweep.
  FloorExplorerOptions explore;
  std::string odom_frame_id = "odom";  // sweep/patrol measure the turn with the odom→base_link yaw
  std::string base_frame_id = "base_link";
  double scan_timeout_s = 0.5;       // no valid scan for this long (ROS time): publish a stop
  bool enabled = true;               // ~enabled: start driving at once (else wait for ~enable)
};

// Throws ParameterError naming the parameter, e.g. "/follower/wall_side must be 'left' or 'right', got up".
WallFollowerNodeOptions LoadWallFollowerOptions(const ros::NodeHandle& private_nh);

}  // namespace doorplate_localization

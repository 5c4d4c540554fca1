// Parameters of WallFollowerNodelet, read and validated once from its private namespace; one table
// (WallFollowerParamTable) is the loader, the docs/parameters.md table and the config/wall_follower.yaml check.
#pragma once

#include <string>

#include <ros/node_handle.h>

#include "doorplate_localization/behaviour/contour_steering.h"
#include "doorplate_localization/behaviour/corridor_sweep.h"
#include "doorplate_localization/behaviour/floor_explorer.h"
#include "doorplate_localization/behaviour/wall_follower.h"
#include "doorplate_localization/ros/param_reader.h"
#include "doorplate_localization/ros/param_table.h"

namespace doorplate_localization {

// What the nodelet drives: "follow" one wall to the corridor's end and stop; "sweep" the paper's mapping
// path (follow out, turn around, follow the other wall back, stop); "patrol" sweep again and again (the
// search strategy of global localization and long runs); "explore" a whole floor (FloorExplorer: follow one
// wall wherever it leads, turn round, follow the other; each pass ends on plates read again, so the
// nodelet also subscribes text_detections); "roam" follow one wall wherever it leads, for ever (the search
// drive of global localization on a whole floor: ContourSteering, as explore's passes but without an end).
enum class CorridorDriveMode { kFollow, kSweep, kPatrol, kExplore, kRoam };

struct WallFollowerNodeOptions {
  WallFollowerOptions follower;      // ~wall_side, ~wall_distance_m, ~cruise_speed_mps, ... (same names)
  CorridorDriveMode mode = CorridorDriveMode::kFollow;  // ~mode: follow | sweep | patrol | explore | roam
  CorridorSweepOptions sweep;        // sweep.follower = follower; ~turn_speed_rps
  // explore: steering.wall_side / wall_distance_m / cruise_speed_mps / max_angular_speed_rps = the
  // follower's; ~explore/passes, ~explore/revisit_plates, ~explore/min_revisit_travel_m,
  // ~explore/max_pass_distance_m; turn_speed_rps as for sweep.
  FloorExplorerOptions explore;
  std::string odom_frame_id = "odom";  // sweep/patrol measure the turn with the odom→base_link yaw
  std::string base_frame_id = "base_link";
  double scan_timeout_s = 0.5;       // no valid scan for this long (ROS time): publish a stop
  // sweep/patrol/explore steer on the latest odom→base_link; older than the scan by more than this: stop.
  double max_odom_lag_s = 0.2;
  bool enabled = true;               // ~enabled: start driving at once (else wait for ~enable)
};

// Every parameter: name, field, default, rule, doc line.
const ParamTable<WallFollowerNodeOptions>& WallFollowerParamTable();

// The options from `source` over the defaults, the follower's values copied into sweep and explore, checked
// by the core objects the mode runs. Throws ParameterError naming the parameter, e.g.
// "/follower/wall_side must be 'left' or 'right', got up". ROS-free (the tests read YAML).
WallFollowerNodeOptions WallFollowerOptionsFrom(const ParamSource& source);

// WallFollowerOptionsFrom(the parameters under `private_nh`).
WallFollowerNodeOptions LoadWallFollowerOptions(const ros::NodeHandle& private_nh);

}  // namespace doorplate_localization

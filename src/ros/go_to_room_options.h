// Parameters of GoToRoomNodelet, read and validated once from its private namespace; one table
// (GoToRoomParamTable) is the loader, the docs/parameters.md table and the config/go_to_room.yaml check.
#pragma once

#include <memory>
#include <string>

#include <ros/node_handle.h>

#include "doorplate_localization/behaviour/floor_go_to_room.h"
#include "doorplate_localization/behaviour/go_to_room.h"
#include "doorplate_localization/behaviour/room_goal_planner.h"
#include "doorplate_localization/maps/building_map.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/ros/param_reader.h"
#include "doorplate_localization/ros/param_table.h"

namespace doorplate_localization {

struct GoToRoomNodeOptions {
  std::string text_map_file;        // ~text_map_file (required): the doorplates, docs/text-map-format.md
  TextMap text_map;                 // loaded from it
  // ~duplicate_rule; planner.wall_distance_m is the follower's ~wall_distance_m (the goal is where the
  // wall following brings the robot).
  RoomGoalPlannerOptions planner;
  // ~approach_sector_max_deg, ~approach_tolerance_m, ~turn_speed_rps, ~align_tolerance_rad, ~arrive_tolerance_m, ~approach_gain_per_s,
  // ~min_approach_speed_mps, ~face_gain_per_s, ~face_tolerance_rad, and the WallFollowerNodelet's follower
  // parameters under the same names (~wall_distance_m, ~cruise_speed_mps, ...; no ~wall_side: the goal's
  // wall is followed).
  GoToRoomOptions controller;
  // ~route: "corridor" (the paper's: wall following along the goal's corridor, eq. 15 fallback) or "grid"
  // (a whole floor: FloorGoToRoom plans over the `map` topic's grid, round corners, and follows the path
  // with the map pose; no eq. 15 fallback). Grid mode takes ~cruise_speed_mps, ~max_angular_speed_rps,
  // ~turn_speed_rps, ~face_tolerance_rad from the same parameters as the corridor controller.
  std::string route = "corridor";
  FloorGoToRoomOptions floor;
  // ~building_file: a building of several floors (a maps building file, docs/building-format.md); its floors'
  // grids and text maps and its lifts replace ~text_map_file and the map topic, the route is grid, and a room
  // is planned from the localizer's floor (topics amcl/floor and amcl/state), via a lift when it is on another
  // (building_goal.h). text_map holds the first floor's text map.
  std::string building_file;
  std::shared_ptr<const BuildingMaps> building;
  // ~search_enable_service: the search drive's std_srvs/SetBool (WallFollowerNodelet ~mode roam: ~enable),
  // on while a building goal waits for the localizer to converge (at first, and after a lift ride), off
  // before it drives; "": none (something else must move the robot to read plates).
  std::string search_enable_service = "corridor_follower/enable";
  // The localizer's frame: pose = tf map -> base_link (~global_frame_id, amcl's name; ~map_frame_id deprecated).
  std::string global_frame_id = "map";
  std::string odom_frame_id = "odom";      // the eq. 15 fallback drives in this frame
  std::string base_frame_id = "base_link";
  double scan_timeout_s = 0.5;             // no valid scan for this long (ROS time) while driving: stop
  double tf_timeout_s = 0.1;               // wait this long for a tf at a scan's stamp
  bool text_fallback = true;               // eq. 15 from text_detections while there is no map pose
  double reading_max_age_s = 60.0;         // a plate read longer ago than this is not used for eq. 15
};

// Every parameter: name, field, default, rule, doc line.
const ParamTable<GoToRoomNodeOptions>& GoToRoomParamTable();

// The options from `source` over the defaults, the text map loaded, checked by the core. Throws
// ParameterError naming the parameter, e.g. "/go_to_room/text_map_file = 'x.yaml' cannot be used: x.yaml:
// cannot open ...", "/go_to_room/duplicate_rule must be 'nearest' or 'refuse', got first". ROS-free.
GoToRoomNodeOptions GoToRoomOptionsFrom(const ParamSource& source);

// GoToRoomOptionsFrom(the parameters under `private_nh`).
GoToRoomNodeOptions LoadGoToRoomOptions(const ros::NodeHandle& private_nh);

}  // namespace doorplate_localization

// Parameters of SlamMappingNodelet, read and validated once from its private namespace.
// Two kinds of names (docs/parameters.md, section SlamMappingNodelet):
//  - gmapping's names and defaults where they mean the same thing in our filter: particles, linearUpdate,
//    angularUpdate, temporalUpdate, resampleThreshold, maxUrange, maxRange, delta, srr, srt, str, stt,
//    map_update_interval, transform_publish_period, throttle_scans, base_frame, odom_frame, map_frame;
//  - every option of the SLAM core by its name in the one option table (slam/rbpf_slam_options.h:
//    TextSlamOptionNames(), the names doorplate_map_log / doorplate_map_bag take with --set), with `/`
//    for `.`: ~num_particles, ~matcher/field_sigma_m, ~text/plate_sigma_m, ...;
//  - ~room_pattern: the building's room identifier format (TextSlamOptions::room_pattern), the same
//    parameter name as the text extractor's.
// A gmapping name and its core name are the same option: setting both is an error. gmapping parameters
// that have no counterpart here (sigma, lstep, ogain, xmin, ...) are reported in `ignored_parameters`.
// One table (SlamMappingParamTable: gmapping's names and ours) is the loader, the docs/parameters.md table
// and the config/mapping.yaml check; the core's names come from the core's own option table.
#pragma once

#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "doorplate_localization/ros/param_reader.h"
#include "doorplate_localization/ros/param_table.h"
#include "doorplate_localization/slam/mapping_session.h"
#include "doorplate_localization/slam/text_slam.h"

namespace doorplate_localization {

// The core's options with gmapping's defaults for gmapping's names (particles 30, linearUpdate 1.0, ...).
TextSlamOptions GmappingDefaultSlamOptions();

struct SlamMappingNodeOptions {
  TextSlamOptions slam = GmappingDefaultSlamOptions();  // the core's options (gmapping names mapped onto them);
                                            // slam.room_pattern is ~room_pattern (written into the text map)
  std::string base_frame = "base_link";     // ~base_frame
  std::string odom_frame = "odom";          // ~odom_frame
  std::string map_frame = "map";            // ~map_frame
  double map_update_interval_s = 5.0;       // ~map_update_interval: solve and republish the map this often (scan stamps)
  double map_update_max_solve_share = 0.3;  // ~map_update_max_solve_share: periodic solves take at most this share of
                                            // the wall clock (MappingSessionOptions; 0: off)
  double temporal_update_s = -1.0;          // ~temporalUpdate: also process a scan this long after the last one (<= 0: off)
  double transform_publish_period_s = 0.05; // ~transform_publish_period: map -> odom period; 0 = never
  double max_range_m = 0.0;                 // ~maxRange: readings >= this are no-echo; 0 = scan's range_max
  int throttle_scans = 1;                   // ~throttle_scans: use every n-th scan
  int min_valid_beams = 10;                 // ~min_valid_beams: scans with fewer finite returns are dropped
  double tf_timeout_s = 0.2;                // ~tf_timeout_s: wait this long for a tf (scans, detections)
  bool use_text = true;                     // ~use_text: subscribe text_detections and map plates
  double camera_wait_s = kDefaultCameraWaitS;  // ~camera_wait_s: scans wait this long at most for the camera's arrays
                                            // (MappingSessionOptions::camera_wait_s; 0 without use_text)
  std::string map_output_dir;               // ~map_output_dir: "" = $ROS_HOME/doorplate_maps (~/.ros/...)
  std::string map_name = "map";             // ~map_name: <dir>/<name>.pgm, .yaml, .text_map.yaml
  bool save_on_shutdown = true;             // ~save_on_shutdown
  std::vector<std::string> ignored_parameters;  // gmapping parameters set but not used (warned at start)
};

// The mapping session's options from the node's (slam, throttle_scans, temporal_update_s,
// map_update_interval_s, map_update_max_solve_share, camera_wait_s if use_text; the session's own defaults
// for the rest).
MappingSessionOptions ToMappingSessionOptions(const SlamMappingNodeOptions& options);

// Every parameter of the table: name, field, default, rule, doc line.
const ParamTable<SlamMappingNodeOptions>& SlamMappingParamTable();

// The options from `source`: the table, then the core's option names, checked by the core. Throws
// ParameterError naming the resolved parameter ("/slam_mapping/throttle_scans must be >= 1, got 0",
// "/slam_mapping/particles = 0.0: refused by the core options: ..."). ROS-free.
SlamMappingNodeOptions SlamMappingOptionsFrom(const ParamSource& source);

// SlamMappingOptionsFrom(the parameters under `private_nh`).
SlamMappingNodeOptions LoadSlamMappingOptions(const ros::NodeHandle& private_nh);

// The ROS parameter name of a core option name: "matcher.field_sigma_m" -> "matcher/field_sigma_m".
std::string SlamOptionParamName(const std::string& option_name);

}  // namespace doorplate_localization

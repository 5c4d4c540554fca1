// Parameters of TextAmclNodelet, read and validated once from its private namespace. amcl's parameter
// names, meanings and defaults (an amcl launch file works by changing the node type), with two
// documented differences: recovery_alpha_slow/fast default to 0.001/0.1 (amcl: 0/0, recovery off), and
// odom_model_type "omni"/"omni-corrected" and selective_resampling true are refused (not provided).
// Our own parameters: ~map_file, ~text_map_file, ~use_text, ~seed, ~tf_timeout_s, ~text_* (doorplates),
// ~converged_* / ~lost_likelihood_ratio (the ~state health rules) and ~building_file, ~start_floor,
// ~floor_* (several floors: mcl/building_session.h). One table (TextAmclParamTable) is
// the loader, the docs/parameters.md table and the config/text_amcl.yaml check.
#pragma once

#include <memory>
#include <string>

#include <ros/node_handle.h>

#include "doorplate_localization/maps/building_map.h"
#include "doorplate_localization/mcl/floor_belief.h"
#include "doorplate_localization/mcl/text_amcl_session.h"
#include "doorplate_localization/ros/param_reader.h"
#include "doorplate_localization/ros/param_table.h"

namespace doorplate_localization {

// The session's options with amcl's defaults where the core's differ: laser_max_beams 30 (core: 60) and
// odom_model_type diff (core: diff-corrected). config/text_amcl.yaml sets the core's for the corridors.
TextAmclSessionOptions AmclDefaultSessionOptions();

struct TextAmclNodeOptions {
  // What the session runs: the filter and its models (min_particles, laser_*, odom_*, recovery_*, text_*),
  // the start (~initial_pose_*, ~initial_cov_*, ~start_with_global_localization) and the plate range rule.
  TextAmclSessionOptions session = AmclDefaultSessionOptions();
  // Frames (amcl's names).
  std::string base_frame_id = "base_link";
  std::string odom_frame_id = "odom";
  std::string global_frame_id = "map";
  bool tf_broadcast = true;
  double transform_tolerance_s = 0.1;   // ~transform_tolerance: map -> odom is stamped scan stamp + this
  double gui_publish_rate_hz = -1.0;    // ~gui_publish_rate: particlecloud at most this often; <= 0: every update
  double save_pose_rate_hz = 0.5;       // ~save_pose_rate: the estimate back into ~initial_pose_*; <= 0: never
  // Map source, in this order: ~map_file (a map_server YAML, loaded directly and republished latched on
  // `map`), else the `map` topic if ~use_map_topic, else the static_map service (amcl's default).
  std::string map_file;
  bool use_map_topic = false;
  bool first_map_only = false;
  // ~text_map_file: the doorplate map (maps/text_map.h). "" or unusable: laser only (an error names the file).
  std::string text_map_file;
  // ~building_file: a building of several floors (maps building file, docs/building-format.md); when set,
  // every floor's occupancy_map and text_map come from it instead of the map sources and ~text_map_file.
  std::string building_file;
  std::shared_ptr<const BuildingMaps> building;  // loaded from building_file (null without one)
  // ~start_floor: the floor the robot starts on ("" = unknown: the plates decide). Without ~building_file the
  // map is a one-floor building whose floor id is this.
  std::string start_floor;
  // ~floor_misread_probability, ~floor_change_probability, ~floor_certain_probability (mcl/floor_belief.h).
  FloorBeliefOptions floor_belief;
  double tf_timeout_s = 0.1;            // ~tf_timeout_s (deprecated ~tf_timeout): how long a callback waits for tf
  // ~scan_timeout_s: no scan taken for this long (ROS time) and ~state says waiting_for_scan (no estimate is
  // being published); <= 0: never.
  double scan_timeout_s = 2.0;
  double odom_alpha5 = 0.2;             // amcl's omni-only alpha: validated, unused by the diff models
  bool selective_resampling = false;    // amcl's; true is refused (not provided)
};

// Every parameter: name, field, default, rule, doc line.
const ParamTable<TextAmclNodeOptions>& TextAmclParamTable();

// Reads every parameter of `source` over the defaults above and validates each, then the whole set
// against the core (a TextAmclSession on a small synthetic map), and loads ~building_file
// (text_amcl_building.h). Throws ParameterError naming the resolved parameter, e.g. "/amcl/kld_err must be
// finite and > 0, got 0", "/amcl/odom_model_type must be 'diff' or 'diff-corrected', got omni". ROS-free.
TextAmclNodeOptions TextAmclOptionsFrom(const ParamSource& source);

// The rules between parameters (laser ranges, frames) and the whole set against the core, as
// TextAmclOptionsFrom checks them after reading each value (also every dynamic_reconfigure request,
// text_amcl_reconfigure.h). Throws ParameterError naming the parameters with their values.
void CheckTextAmclOptions(const TextAmclNodeOptions& options, const ParamSource& source);

// TextAmclOptionsFrom(the parameters under `private_nh`).
TextAmclNodeOptions LoadTextAmclOptions(const ros::NodeHandle& private_nh);

}  // namespace doorplate_localization

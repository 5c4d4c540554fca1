// Parameters of TextAmclNodelet, read and validated once from its private namespace. amcl's parameter
// names, meanings and defaults (an amcl launch file works by changing the node type), with two
// documented differences: recovery_alpha_slow/fast default to 0.001/0.1 (amcl: 0/0, recovery off), and
// odom_model_type "omni"/"omni-corrected" and selective_resampling true are refused (not provided).
// Our own parameters: ~map_file, ~text_map_file, ~use_text, ~seed, ~text_* (doorplates) and
// ~converged_* / ~lost_likelihood_ratio (the ~state health rules). Full table: docs/parameters.md.
#pragma once

#include <string>

#include <Eigen/Core>
#include <ros/node_handle.h>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/mcl/text_amcl_session.h"
#include "doorplate_localization/mcl/text_amcl_setup.h"
#include "doorplate_localization/ros/param_reader.h"

namespace doorplate_localization {

struct TextAmclNodeOptions {
  // The filter and its models (min_particles, laser_*, odom_*, recovery_*, text_*, ...).
  TextAmclSetupOptions setup;
  // Frames (amcl's names).
  std::string base_frame_id = "base_link";
  std::string odom_frame_id = "odom";
  std::string global_frame_id = "map";
  bool tf_broadcast = true;
  double transform_tolerance_s = 0.1;   // ~transform_tolerance: map -> odom is stamped scan stamp + this
  // ~initial_pose_x/y/a and ~initial_cov_xx/yy/aa: the filter starts there (amcl's defaults: 0 pose,
  // 0.25 m², 0.25 m², (pi/12)² rad²).
  Pose2D initial_pose;
  // ~start_with_global_localization: on a new map, spread the particles over the free space instead (as if
  // global_localization were called; the robot's pose is unknown).
  bool start_with_global_localization = false;
  Eigen::Matrix3d initial_covariance = Eigen::Vector3d(0.25, 0.25, (M_PI / 12.0) * (M_PI / 12.0)).asDiagonal();
  double gui_publish_rate_hz = -1.0;    // ~gui_publish_rate: particlecloud at most this often; <= 0: every update
  double save_pose_rate_hz = 0.5;       // ~save_pose_rate: the estimate back into ~initial_pose_*; <= 0: never
  // Map source, in this order: ~map_file (a map_server YAML, loaded directly and republished latched on
  // `map`), else the `map` topic if ~use_map_topic, else the static_map service (amcl's default).
  std::string map_file;
  bool use_map_topic = false;
  bool first_map_only = false;
  // ~text_map_file: the doorplate map (maps/text_map.h). "" or unusable: laser only (an error names the file).
  std::string text_map_file;
  // Doorplate readings: the range to the plate from the latest scan's beam along the reading's bearing.
  bool text_use_laser_range = true;
  double text_range_max_bearing_error_rad = 0.03;
  double text_range_max_scan_age_s = 0.5;  // the latest scan gives a range only if this close in time to the reading
  double tf_timeout_s = 0.1;            // ~tf_timeout: how long a callback waits for a transform
};

// Reads every parameter of `private_nh` over the defaults above and validates each, then the whole set
// against the core (MakeTextAmcl on a small synthetic map). Throws ParameterError naming the resolved
// parameter, e.g. "/amcl/kld_err must be finite and > 0, got 0", "/amcl/odom_model_type must be
// 'diff' or 'diff-corrected', got omni".
TextAmclNodeOptions LoadTextAmclOptions(const ros::NodeHandle& private_nh);

// The session's options from the node's: the filter, the start pose and the plate range rule.
TextAmclSessionOptions ToSessionOptions(const TextAmclNodeOptions& options);

}  // namespace doorplate_localization

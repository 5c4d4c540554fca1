#include "doorplate_localization/slam/rbpf_slam_options.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

// One option: where it lives in RbpfSlamOptions, as a double or as an integer.
struct Field {
  const char* name;
  double* (*real)(RbpfSlamOptions&);
  int* (*whole)(RbpfSlamOptions&);
};

using O = RbpfSlamOptions;
const Field kFields[] = {
    {"num_particles", nullptr, [](O& o) { return &o.num_particles; }},
    {"linear_update_m", [](O& o) { return &o.linear_update_m; }, nullptr},
    {"angular_update_rad", [](O& o) { return &o.angular_update_rad; }, nullptr},
    {"resample_neff_ratio", [](O& o) { return &o.resample_neff_ratio; }, nullptr},
    {"likelihood_gain", [](O& o) { return &o.likelihood_gain; }, nullptr},
    {"max_usable_range_m", [](O& o) { return &o.max_usable_range_m; }, nullptr},
    {"no_return_clear_range_m", [](O& o) { return &o.no_return_clear_range_m; }, nullptr},
    {"mean_trajectory_radius_m", [](O& o) { return &o.mean_trajectory_radius_m; }, nullptr},
    {"degenerate_min_points", [](O& o) { return &o.degenerate_min_points; }, nullptr},
    {"max_match_range_m", [](O& o) { return &o.max_match_range_m; }, nullptr},
    {"grid.resolution_m", [](O& o) { return &o.grid.resolution_m; }, nullptr},
    {"grid.hit_log_odds", [](O& o) { return &o.grid.hit_log_odds; }, nullptr},
    {"grid.miss_log_odds", [](O& o) { return &o.grid.miss_log_odds; }, nullptr},
    {"grid.min_log_odds", [](O& o) { return &o.grid.min_log_odds; }, nullptr},
    {"grid.max_log_odds", [](O& o) { return &o.grid.max_log_odds; }, nullptr},
    {"grid.occupied_log_odds", [](O& o) { return &o.grid.occupied_log_odds; }, nullptr},
    {"grid.cleared_log_odds", [](O& o) { return &o.grid.cleared_log_odds; }, nullptr},
    {"grid.distance_field_radius_m", [](O& o) { return &o.grid.distance_field_radius_m; }, nullptr},
    {"matcher.field_sigma_m", [](O& o) { return &o.matcher.field_sigma_m; }, nullptr},
    {"matcher.likelihood_floor", [](O& o) { return &o.matcher.likelihood_floor; }, nullptr},
    {"matcher.search_sigmas", [](O& o) { return &o.matcher.search_sigmas; }, nullptr},
    {"matcher.min_search_linear_m", [](O& o) { return &o.matcher.min_search_linear_m; }, nullptr},
    {"matcher.max_search_linear_m", [](O& o) { return &o.matcher.max_search_linear_m; }, nullptr},
    {"matcher.min_search_angular_rad", [](O& o) { return &o.matcher.min_search_angular_rad; }, nullptr},
    {"matcher.max_search_angular_rad", [](O& o) { return &o.matcher.max_search_angular_rad; }, nullptr},
    {"matcher.search_angular_step_rad", [](O& o) { return &o.matcher.search_angular_step_rad; }, nullptr},
    {"matcher.matched_distance_m", [](O& o) { return &o.matcher.matched_distance_m; }, nullptr},
    {"matcher.min_matched_fraction", [](O& o) { return &o.matcher.min_matched_fraction; }, nullptr},
    {"matcher.jump_guard_margin_m", [](O& o) { return &o.matcher.jump_guard_margin_m; }, nullptr},
    {"matcher.jump_guard_margin_rad", [](O& o) { return &o.matcher.jump_guard_margin_rad; }, nullptr},
    {"matcher.score_to_log_likelihood", [](O& o) { return &o.matcher.score_to_log_likelihood; }, nullptr},
    {"matcher.prior_huber_sigmas", [](O& o) { return &o.matcher.prior_huber_sigmas; }, nullptr},
    {"motion.trans_noise_from_trans", [](O& o) { return &o.motion.trans_noise_from_trans; }, nullptr},
    {"motion.trans_noise_from_rot", [](O& o) { return &o.motion.trans_noise_from_rot; }, nullptr},
    {"motion.rot_noise_from_trans", [](O& o) { return &o.motion.rot_noise_from_trans; }, nullptr},
    {"motion.rot_noise_from_rot", [](O& o) { return &o.motion.rot_noise_from_rot; }, nullptr},
    {"motion.min_translation_for_heading_m", [](O& o) { return &o.motion.min_translation_for_heading_m; }, nullptr},
    {"max_match_points", nullptr, [](O& o) { return &o.max_match_points; }},
    {"matcher.refine_halvings", nullptr, [](O& o) { return &o.matcher.refine_halvings; }},
};

const Field& Find(const std::string& name) {
  for (const Field& f : kFields) {
    if (name == f.name) return f;
  }
  throw std::invalid_argument("unknown SLAM option '" + name + "'");
}

// `value` as an int, or std::invalid_argument naming option `name` if it is not a whole number.
int WholeNumber(const std::string& name, double value) {
  if (value != std::floor(value) || std::abs(value) > 1e9) {
    throw std::invalid_argument("SLAM option '" + name + "' must be a whole number, got " + std::to_string(value));
  }
  return static_cast<int>(value);
}

using T = TextSlamOptions;
// A text SLAM option: a double, a whole number or a flag (0 / 1).
struct TextField {
  const char* name;
  double* (*real)(TextSlamOptions&);
  int* (*whole)(TextSlamOptions&) = nullptr;
  bool* (*flag)(TextSlamOptions&) = nullptr;
};
const TextField kTextFields[] = {
    {"text.min_confidence", [](T& o) { return &o.min_confidence; }},
    {"text.min_plate_range_m", [](T& o) { return &o.min_plate_range_m; }},
    {"text.max_plate_range_m", [](T& o) { return &o.max_plate_range_m; }},
    {"text.range_beam_window_rad", [](T& o) { return &o.plate_range.beam_window_rad; }},
    {"text.occluded_plate_margin_m", [](T& o) { return &o.plate_range.occluded_margin_m; }},
    {"text.wall_range.window_rad", [](T& o) { return &o.plate_range.wall.window_rad; }},
    {"text.wall_range.inlier_m", [](T& o) { return &o.plate_range.wall.inlier_m; }},
    {"text.wall_range.min_inliers", nullptr, [](T& o) { return &o.plate_range.wall.min_inliers; }},
    {"text.wall_range.min_length_m", [](T& o) { return &o.plate_range.wall.min_length_m; }},
    {"text.wall_range.max_incidence_rad", [](T& o) { return &o.plate_range.wall.max_incidence_rad; }},
    {"text.plate_sigma_m", [](T& o) { return &o.plate_sigma_m; }},
    {"text.association_radius_m", [](T& o) { return &o.association_radius_m; }},
    {"text.text_likelihood_gain", [](T& o) { return &o.text_likelihood_gain; }},
    {"text.max_odometry_gap_m", [](T& o) { return &o.max_odometry_gap_m; }},
    {"back_end.enabled", nullptr, nullptr, [](T& o) { return &o.back_end.enabled; }},
    {"back_end.max_sequential_offset", nullptr, [](T& o) { return &o.back_end.max_sequential_offset; }},
    {"back_end.max_alignment_distance_m", [](T& o) { return &o.back_end.max_alignment_distance_m; }},
    {"back_end.loop_closure_radius_m", [](T& o) { return &o.back_end.loop_closure_radius_m; }},
    {"back_end.loop_closure_min_separation", nullptr, [](T& o) { return &o.back_end.loop_closure_min_separation; }},
    {"back_end.loop_closure_max_rms_m", [](T& o) { return &o.back_end.loop_closure_max_rms_m; }},
    {"back_end.sequential_gate_sigmas", [](T& o) { return &o.back_end.sequential_gate_sigmas; }},
    {"back_end.front_end_history_sigma_m", [](T& o) { return &o.back_end.front_end_history_sigma_m; }},
    {"back_end.front_end_history_sigma_rad", [](T& o) { return &o.back_end.front_end_history_sigma_rad; }},
    {"back_end.loop_closure_max_tries", nullptr, [](T& o) { return &o.back_end.loop_closure_max_tries; }},
    {"back_end.loop_closures_per_node", nullptr, [](T& o) { return &o.back_end.loop_closures_per_node; }},
    {"back_end.front_end_pinned_neighbours", nullptr, [](T& o) { return &o.back_end.front_end_pinned_neighbours; }},
    {"back_end.loop_closure_max_residual_sigmas", [](T& o) { return &o.back_end.loop_closure_max_residual_sigmas; }},
    {"back_end.loop_closure_check_rounds", nullptr, [](T& o) { return &o.back_end.loop_closure_check_rounds; }},
    {"back_end.sequential_max_residual_sigmas", [](T& o) { return &o.back_end.sequential_max_residual_sigmas; }},
    {"back_end.loop_closure_proposal_order", nullptr, [](T& o) { return &o.back_end.loop_closure_proposal_order; }},
    {"back_end.max_nodes_per_place", nullptr, [](T& o) { return &o.back_end.max_nodes_per_place; }},
    {"back_end.place_radius_m", [](T& o) { return &o.back_end.place_radius_m; }},
    {"back_end.place_max_heading_diff_rad", [](T& o) { return &o.back_end.place_max_heading_diff_rad; }},
    {"back_end.place_max_odometry_displacement_fraction",
     [](T& o) { return &o.back_end.place_max_odometry_displacement_fraction; }},
    {"back_end.place_turn_around_rad", [](T& o) { return &o.back_end.place_turn_around_rad; }},
    {"back_end.odometry_trans_m2_per_m", [](T& o) { return &o.back_end.odometry_trans_m2_per_m; }},
    {"back_end.odometry_trans_m2_per_rad", [](T& o) { return &o.back_end.odometry_trans_m2_per_rad; }},
    {"back_end.odometry_rot_rad2_per_m", [](T& o) { return &o.back_end.odometry_rot_rad2_per_m; }},
    {"back_end.odometry_rot_rad2_per_rad", [](T& o) { return &o.back_end.odometry_rot_rad2_per_rad; }},
    {"back_end.node_fusion.scans_before", nullptr, [](T& o) { return &o.back_end.node_fusion.scans_before; }},
    {"back_end.node_fusion.scans_after", nullptr, [](T& o) { return &o.back_end.node_fusion.scans_after; }},
    {"back_end.node_fusion.max_distance_m", [](T& o) { return &o.back_end.node_fusion.max_distance_m; }},
    {"back_end.node_fusion.max_rotation_rad", [](T& o) { return &o.back_end.node_fusion.max_rotation_rad; }},
    {"back_end.node_fusion.radius_m", [](T& o) { return &o.back_end.node_fusion.radius_m; }},
    {"back_end.node_fusion.radius_per_m", [](T& o) { return &o.back_end.node_fusion.radius_per_m; }},
    {"back_end.node_fusion.min_neighbours", nullptr, [](T& o) { return &o.back_end.node_fusion.min_neighbours; }},
    {"back_end.node_fusion.max_residual_m", [](T& o) { return &o.back_end.node_fusion.max_residual_m; }},
    {"back_end.node_fusion.max_residual_per_m", [](T& o) { return &o.back_end.node_fusion.max_residual_per_m; }},
    {"back_end.icp.point_sigma_m", [](T& o) { return &o.back_end.icp.point_sigma_m; }},
    {"back_end.icp.effective_points", [](T& o) { return &o.back_end.icp.effective_points; }},
    {"back_end.icp.min_inlier_fraction", [](T& o) { return &o.back_end.icp.min_inlier_fraction; }},
    {"back_end.icp.normal_neighbours", nullptr, [](T& o) { return &o.back_end.icp.normal_neighbours; }},
    {"back_end.icp.normal_gap_per_m", [](T& o) { return &o.back_end.icp.normal_gap_per_m; }},
    {"back_end.icp.degenerate_min_fraction", [](T& o) { return &o.back_end.icp.degenerate_min_fraction; }},
    {"back_end.icp.share_reference_points", nullptr, nullptr,
     [](T& o) { return &o.back_end.icp.share_reference_points; }},
    {"back_end.icp.skip_points_nearest_no_line", nullptr, nullptr,
     [](T& o) { return &o.back_end.icp.skip_points_nearest_no_line; }},
    {"back_end.graph.scale_prior_sigma", [](T& o) { return &o.back_end.graph.scale_prior_sigma; }},
    {"back_end.graph.max_iterations", nullptr, [](T& o) { return &o.back_end.graph.max_iterations; }},
    {"back_end.graph.min_step_m", [](T& o) { return &o.back_end.graph.min_step_m; }},
    {"back_end.graph.min_step_rad", [](T& o) { return &o.back_end.graph.min_step_rad; }},
    {"back_end.graph.estimate_odometry_scale", nullptr, nullptr, [](T& o) { return &o.back_end.graph.estimate_odometry_scale; }},
    {"back_end.graph.heading_drift_prior_sigma_rad_per_m",
     [](T& o) { return &o.back_end.graph.heading_drift_prior_sigma_rad_per_m; }},
    {"back_end.graph.estimate_odometry_heading_drift", nullptr, nullptr,
     [](T& o) { return &o.back_end.graph.estimate_odometry_heading_drift; }},
};

const TextField* FindText(const std::string& name) {
  for (const TextField& f : kTextFields) {
    if (name == f.name) return &f;
  }
  return nullptr;
}

}  // namespace

std::vector<std::string> TextSlamOptionNames() {
  std::vector<std::string> names = RbpfSlamOptionNames();
  for (const TextField& f : kTextFields) names.push_back(f.name);
  return names;
}

void SetTextSlamOption(const std::string& name, double value, TextSlamOptions* options) {
  if (const TextField* f = FindText(name)) {
    if (f->real) {
      *f->real(*options) = value;
    } else if (f->whole) {
      *f->whole(*options) = WholeNumber(name, value);
    } else {
      if (value != 0.0 && value != 1.0) {
        throw std::invalid_argument("SLAM option '" + name + "' must be 0 or 1, got " + std::to_string(value));
      }
      *f->flag(*options) = value == 1.0;
    }
    return;
  }
  SetRbpfSlamOption(name, value, &options->slam);
}

double GetTextSlamOption(const std::string& name, const TextSlamOptions& options) {
  if (const TextField* f = FindText(name)) {
    TextSlamOptions copy = options;
    if (f->real) return *f->real(copy);
    if (f->whole) return *f->whole(copy);
    return *f->flag(copy) ? 1.0 : 0.0;
  }
  return GetRbpfSlamOption(name, options.slam);
}

std::vector<std::string> RbpfSlamOptionNames() {
  std::vector<std::string> names;
  for (const Field& f : kFields) names.push_back(f.name);
  return names;
}

void SetRbpfSlamOption(const std::string& name, double value, RbpfSlamOptions* options) {
  const Field& f = Find(name);
  if (f.real) {
    *f.real(*options) = value;
    return;
  }
  *f.whole(*options) = WholeNumber(name, value);
}

double GetRbpfSlamOption(const std::string& name, const RbpfSlamOptions& options) {
  const Field& f = Find(name);
  RbpfSlamOptions copy = options;
  return f.real ? *f.real(copy) : *f.whole(copy);
}

}  // namespace doorplate_localization

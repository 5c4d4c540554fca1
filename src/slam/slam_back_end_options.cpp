// Range checks of SlamBackEndOptions (slam_back_end.h), one message per field.
#include <stdexcept>
#include <string>

#include "doorplate_localization/slam/slam_back_end.h"

namespace doorplate_localization {

const SlamBackEndOptions& ValidatedSlamBackEndOptions(const SlamBackEndOptions& o) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("SlamBackEndOptions." + what); };
  try {
    ValidatedScanFusionOptions(o.node_fusion);
  } catch (const std::invalid_argument& e) {
    fail(std::string("node_fusion.") + (e.what() + std::string("ScanFusionOptions.").size()));
  }
  if (o.max_sequential_offset < 1) fail("max_sequential_offset: must be >= 1");
  if (!(o.max_alignment_distance_m > 0)) fail("max_alignment_distance_m: must be > 0");
  if (!(o.loop_closure_radius_m >= 0)) fail("loop_closure_radius_m: must be >= 0");
  if (o.loop_closure_min_separation < 1) fail("loop_closure_min_separation: must be >= 1");
  if (!(o.loop_closure_max_rms_m > 0)) fail("loop_closure_max_rms_m: must be > 0");
  if (o.loop_closure_max_tries < 1) fail("loop_closure_max_tries: must be >= 1");
  if (o.loop_closures_per_node < 1) fail("loop_closures_per_node: must be >= 1");
  if (!(o.sequential_gate_sigmas >= 0)) fail("sequential_gate_sigmas: must be >= 0 (0: off)");
  if (o.front_end_pinned_neighbours < 0) fail("front_end_pinned_neighbours: must be >= 0");
  if (!(o.loop_closure_max_residual_sigmas >= 0)) fail("loop_closure_max_residual_sigmas: must be >= 0 (0: off)");
  if (o.loop_closure_check_rounds < 0) fail("loop_closure_check_rounds: must be >= 0");
  if (!(o.sequential_max_residual_sigmas >= 0)) fail("sequential_max_residual_sigmas: must be >= 0 (0: off)");
  if (o.loop_closure_proposal_order < 0 || o.loop_closure_proposal_order > 2) {
    fail("loop_closure_proposal_order: must be 0 (auto), 1 (front end first) or 2 (first solve first)");
  }
  if (!(o.icp.min_inlier_fraction > 0 && o.icp.min_inlier_fraction <= 1)) fail("icp.min_inlier_fraction: must be in (0, 1]");
  for (double v : {o.odometry_trans_m2_per_m, o.odometry_trans_m2_per_rad, o.odometry_rot_rad2_per_m,
                   o.odometry_rot_rad2_per_rad}) {
    if (!(v >= 0)) fail("odometry_*: noise terms must be >= 0");
  }
  if (!(o.odometry_min_sigma_m > 0) || !(o.odometry_min_sigma_rad > 0)) fail("odometry_min_sigma_*: must be > 0");
  if (!(o.plate_sigma_m > 0)) fail("plate_sigma_m: must be > 0");
  if (!(o.front_end_history_sigma_m >= 0)) fail("front_end_history_sigma_m: must be >= 0 (0: off)");
  if (o.front_end_history_sigma_m > 0 && !(o.front_end_history_sigma_rad > 0)) {
    fail("front_end_history_sigma_rad: must be > 0 when front_end_history_sigma_m is");
  }
  if (o.max_nodes_per_place < 0) fail("max_nodes_per_place: must be >= 0 (0: off)");
  if (!(o.place_radius_m > 0)) fail("place_radius_m: must be > 0");
  if (!(o.place_max_heading_diff_rad > 0)) fail("place_max_heading_diff_rad: must be > 0");
  if (!(o.place_max_odometry_displacement_fraction >= 0 && o.place_max_odometry_displacement_fraction <= 1)) {
    fail("place_max_odometry_displacement_fraction: must be in [0, 1]");
  }
  if (!(o.place_turn_around_rad >= 0)) fail("place_turn_around_rad: must be >= 0 (0: off)");
  if (!(o.icp.point_sigma_m > 0) || !(o.icp.effective_points > 0)) fail("icp: point_sigma_m and effective_points must be > 0");
  if (!(o.icp.degenerate_min_fraction >= 0 && o.icp.degenerate_min_fraction < 1)) {
    fail("icp.degenerate_min_fraction: must be in [0, 1)");
  }
  if (!(o.graph.scale_prior_sigma > 0)) fail("graph.scale_prior_sigma: must be > 0");
  if (o.graph.max_iterations < 1) fail("graph.max_iterations: must be >= 1");
  if (!(o.graph.min_step_m > 0) || !(o.graph.min_step_rad > 0)) fail("graph.min_step_m, min_step_rad: must be > 0");
  if (!(o.graph.heading_drift_prior_sigma_rad_per_m > 0)) fail("graph.heading_drift_prior_sigma_rad_per_m: must be > 0");
  return o;
}

}  // namespace doorplate_localization

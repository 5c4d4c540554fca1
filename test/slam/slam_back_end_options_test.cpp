#include "doorplate_localization/slam/slam_back_end.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

// The constructor validates (ValidatedSlamBackEndOptions): a bad field throws naming it.
void ExpectThrowNaming(const SlamBackEndOptions& options, const std::string& field) {
  try {
    SlamBackEnd back_end(options);
    ADD_FAILURE() << "no exception for " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(field, 0), 0u) << e.what();
  }
}

TEST(SlamBackEndOptions, BadOptionsThrowNamingTheField) {
  EXPECT_NO_THROW(ValidatedSlamBackEndOptions(SlamBackEndOptions{}));
  EXPECT_NO_THROW(SlamBackEnd{SlamBackEndOptions{}});
  SlamBackEndOptions o;
  o.max_sequential_offset = 0;
  ExpectThrowNaming(o, "SlamBackEndOptions.max_sequential_offset");
  o = {};
  o.max_alignment_distance_m = 0;
  ExpectThrowNaming(o, "SlamBackEndOptions.max_alignment_distance_m");
  o = {};
  o.loop_closure_radius_m = -1;
  ExpectThrowNaming(o, "SlamBackEndOptions.loop_closure_radius_m");
  o = {};
  o.loop_closure_min_separation = 0;
  ExpectThrowNaming(o, "SlamBackEndOptions.loop_closure_min_separation");
  o = {};
  o.loop_closure_max_tries = 0;
  ExpectThrowNaming(o, "SlamBackEndOptions.loop_closure_max_tries");
  o = {};
  o.loop_closures_per_node = 0;
  ExpectThrowNaming(o, "SlamBackEndOptions.loop_closures_per_node");
  o = {};
  o.sequential_gate_sigmas = -1;
  ExpectThrowNaming(o, "SlamBackEndOptions.sequential_gate_sigmas");
  o = {};
  o.front_end_pinned_neighbours = -1;
  ExpectThrowNaming(o, "SlamBackEndOptions.front_end_pinned_neighbours");
  o = {};
  o.loop_closure_max_residual_sigmas = -1;
  ExpectThrowNaming(o, "SlamBackEndOptions.loop_closure_max_residual_sigmas");
  o = {};
  o.loop_closure_check_rounds = -1;
  ExpectThrowNaming(o, "SlamBackEndOptions.loop_closure_check_rounds");
  o = {};
  o.sequential_max_residual_sigmas = -1;
  ExpectThrowNaming(o, "SlamBackEndOptions.sequential_max_residual_sigmas");
  o = {};
  o.loop_closure_proposal_order = 3;
  ExpectThrowNaming(o, "SlamBackEndOptions.loop_closure_proposal_order");
  o = {};
  o.icp.degenerate_min_fraction = 1.0;
  ExpectThrowNaming(o, "SlamBackEndOptions.icp.degenerate_min_fraction");
  o = {};
  o.icp.min_inlier_fraction = 1.5;
  ExpectThrowNaming(o, "SlamBackEndOptions.icp.min_inlier_fraction");
  o = {};
  o.odometry_rot_rad2_per_m = -0.1;
  ExpectThrowNaming(o, "SlamBackEndOptions.odometry_");
  o = {};
  o.odometry_min_sigma_m = 0;
  ExpectThrowNaming(o, "SlamBackEndOptions.odometry_min_sigma");
  o = {};
  o.plate_sigma_m = std::nan("");
  ExpectThrowNaming(o, "SlamBackEndOptions.plate_sigma_m");
  o = {};
  o.icp.point_sigma_m = 0;
  ExpectThrowNaming(o, "SlamBackEndOptions.icp");
  o = {};
  o.graph.scale_prior_sigma = 0;
  ExpectThrowNaming(o, "SlamBackEndOptions.graph.scale_prior_sigma");
  o = {};
  o.graph.min_step_m = 0;
  ExpectThrowNaming(o, "SlamBackEndOptions.graph.min_step_m");
  o = {};
  o.graph.min_step_rad = std::nan("");
  ExpectThrowNaming(o, "SlamBackEndOptions.graph.min_step_m, min_step_rad");
  o = {};
  o.graph.max_iterations = 0;
  ExpectThrowNaming(o, "SlamBackEndOptions.graph.max_iterations");
  o = {};
  o.max_nodes_per_place = -1;
  ExpectThrowNaming(o, "SlamBackEndOptions.max_nodes_per_place");
  o = {};
  o.place_radius_m = 0;
  ExpectThrowNaming(o, "SlamBackEndOptions.place_radius_m");
  o = {};
  o.place_max_heading_diff_rad = std::nan("");
  ExpectThrowNaming(o, "SlamBackEndOptions.place_max_heading_diff_rad");
  o = {};
  o.place_max_odometry_displacement_fraction = 1.5;
  ExpectThrowNaming(o, "SlamBackEndOptions.place_max_odometry_displacement_fraction");
  o = {};
  o.front_end_history_sigma_m = -0.01;
  ExpectThrowNaming(o, "SlamBackEndOptions.front_end_history_sigma_m");
  o = {};
  o.front_end_history_sigma_m = 0.005;
  ExpectThrowNaming(o, "SlamBackEndOptions.front_end_history_sigma_rad");
  o = {};
  o.node_fusion.scans_after = -1;
  ExpectThrowNaming(o, "SlamBackEndOptions.node_fusion.scans_after");
}

}  // namespace
}  // namespace doorplate_localization

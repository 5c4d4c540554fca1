#include "map_eval_json.h"

namespace doorplate_localization {
namespace {

Json CorridorJson(const CorridorAccuracy& c) {
  Json j;
  j["id"] = c.id;
  j["ok"] = c.ok;
  j["length_true_m"] = c.truth.length_m;
  j["length_est_m"] = c.mapped.length_m;
  j["length_accuracy"] = c.length_accuracy;
  j["width_true_m"] = c.truth.width_m;
  j["width_est_m"] = c.mapped.width_m;
  j["width_accuracy"] = c.width_accuracy;
  j["cross_sections_used"] = c.mapped.cross_sections_used;
  return j;
}

}  // namespace

Json MapEvalJson(const MapEvalResult& r, const MapEvalRunInfo& info) {
  Json j;
  j["experiment"] = "map";
  j["command_line"] = info.command_line;
  j["world"] = r.world_name;
  j["world_path"] = info.world_path;
  j["method"] = MapMethodName(info.method);
  j["seed"] = info.seed;
  j["particles"] = info.particles;
  j["drive"] = MapDriveName(info.drive);
  j["sweep_done"] = r.sweep_done;
  j["sweeps_done"] = r.sweeps_done;
  j["distance_m"] = r.distance_m;
  j["pass_ends"] = Json::array();
  for (std::size_t i = 0; i < r.pass_ends.size(); ++i) {
    Json end = {{"why", r.pass_ends[i]}, {"scan", r.pass_end_scans[i]}};
    if (i < r.pass_end_errors_m.size()) end["trajectory_error_m"] = r.pass_end_errors_m[i];
    j["pass_ends"].push_back(end);
  }
  j["length_true_m"] = r.truth.length_m;
  j["length_est_m"] = r.estimate.length_m;
  j["length_accuracy"] = r.length_accuracy;
  j["width_true_m"] = r.truth.width_m;
  j["width_est_m"] = r.estimate.width_m;
  j["width_accuracy"] = r.width_accuracy;
  j["extent_measured"] = r.estimate.ok;
  j["plates_true"] = r.plates.plates_true;
  j["plates_in_map"] = r.plates.plates_in_map;
  j["plates_mapped"] = r.plates.plates_mapped;
  const bool mapped = r.plates.plates_mapped > 0;
  j["plate_position_rmse_m"] = mapped ? Json(r.plates.rmse_m) : Json(nullptr);
  j["plate_max_error_m"] = mapped ? Json(r.plates.max_error_m) : Json(nullptr);
  if (r.plate_fit.ok) {
    j["plates_fitted_rmse_m"] = r.plates_fitted.rmse_m;
    j["plates_fitted_max_error_m"] = r.plates_fitted.max_error_m;
  }
  j["corridors"] = Json::array();
  for (const CorridorAccuracy& c : r.corridors) j["corridors"].push_back(CorridorJson(c));
  j["plate_reports"] = r.plate_reports;
  j["plate_reports_used"] = r.plate_reports_used;
  j["plate_ranges_from_wall"] = r.plate_ranges_from_wall;
  j["final_position_error_m"] = r.final_position_error_m;
  j["trajectory_rmse_m"] = r.trajectory_rmse_m;
  j["out_leg_true_m"] = r.out_leg.true_m;
  j["out_leg_est_m"] = r.out_leg.estimated_m;
  j["out_leg_accuracy"] = r.out_leg.accuracy;
  j["trajectory_max_error_m"] = r.trajectory_max_error_m;
  j["back_end_odometry_scale"] = r.odometry_scale;
  j["back_end_odometry_heading_drift_rad_per_m"] = r.odometry_heading_drift_rad_per_m;
  j["back_end_loop_closures"] = r.loop_closures;
  j["back_end_loop_closures_dropped"] = r.loop_closures_dropped;
  j["back_end_nodes_on_mapped_ground"] = r.nodes_on_mapped_ground;
  j["seconds"] = r.seconds;
  j["sim_seconds"] = r.sim_seconds;
  j["slam_seconds"] = r.slam_seconds;
  j["map_build_seconds"] = r.map_build_seconds;
  j["solves"] = Json::array();
  for (const MapEvalSolve& s : r.solves) {
    j["solves"].push_back({{"sim_time_s", s.sim_time_s},
                           {"wall_s", s.wall_s},
                           {"nodes", s.nodes},
                           {"nodes_on_mapped_ground", s.nodes_on_mapped_ground},
                           {"loop_closures", s.loop_closures},
                           {"loop_alignments_computed", s.loop_alignments_computed},
                           {"loop_alignments_reused", s.loop_alignments_reused}});
  }
  j["scans"] = r.scans;
  j["scans_processed"] = r.scans_processed;
  j["degenerate_scans"] = r.degenerate_scans;
  j["slam_ms_per_processed_scan"] = r.scans_processed > 0 ? 1000.0 * r.slam_seconds / r.scans_processed : 0.0;
  j["slam_real_time_factor"] = r.slam_seconds > 0 ? r.sim_seconds / r.slam_seconds : 0.0;
  j["peak_rss_mb"] = r.peak_rss_kb / 1024.0;
  j["plates"] = Json::array();
  for (std::size_t i = 0; i < r.text_map.landmarks.size(); ++i) {
    const TextLandmark& l = r.text_map.landmarks[i];
    const double e = i < r.plates.errors_m.size() ? r.plates.errors_m[i] : -1.0;
    j["plates"].push_back({{"text", l.text},
                           {"x_m", l.pose.x_m},
                           {"y_m", l.pose.y_m},
                           {"wall", l.wall},
                           {"observations", l.observations},
                           {"error_m", e >= 0 ? Json(e) : Json(nullptr)}});
  }
  return j;
}

}  // namespace doorplate_localization

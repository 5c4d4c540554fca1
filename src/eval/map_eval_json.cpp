#include "map_eval_json.h"

namespace doorplate_localization {

void WriteMapEvalJson(const MapEvalResult& r, const MapEvalRunInfo& info, JsonWriter* json) {
  JsonWriter& j = *json;
  j.BeginObject();
  j.Field("experiment", "map").Field("command_line", info.command_line).Field("world", r.world_name);
  j.Field("world_path", info.world_path).Field("method", MapMethodName(info.method)).Field("seed", info.seed);
  j.Field("particles", info.particles);
  j.Field("drive", MapDriveName(info.drive)).Field("sweep_done", r.sweep_done).Field("distance_m", r.distance_m);
  j.Key("pass_ends").BeginArray();
  for (std::size_t i = 0; i < r.pass_ends.size(); ++i) {
    j.BeginObject().Field("why", r.pass_ends[i]).Field("scan", r.pass_end_scans[i]);
    if (i < r.pass_end_errors_m.size()) j.Field("trajectory_error_m", r.pass_end_errors_m[i]);
    j.EndObject();
  }
  j.EndArray();
  j.Field("length_true_m", r.truth.length_m).Field("length_est_m", r.estimate.length_m);
  j.Field("length_accuracy", r.length_accuracy);
  j.Field("width_true_m", r.truth.width_m).Field("width_est_m", r.estimate.width_m);
  j.Field("width_accuracy", r.width_accuracy);
  j.Field("extent_measured", r.estimate.ok);
  j.Field("plates_true", r.plates.plates_true).Field("plates_in_map", r.plates.plates_in_map);
  j.Field("plates_mapped", r.plates.plates_mapped);
  if (r.plates.plates_mapped > 0) {
    j.Field("plate_position_rmse_m", r.plates.rmse_m).Field("plate_max_error_m", r.plates.max_error_m);
  } else {
    j.Key("plate_position_rmse_m").Null().Key("plate_max_error_m").Null();
  }
  if (r.plate_fit.ok) {
    j.Field("plates_fitted_rmse_m", r.plates_fitted.rmse_m).Field("plates_fitted_max_error_m", r.plates_fitted.max_error_m);
  }
  j.Key("corridors").BeginArray();
  for (const CorridorAccuracy& c : r.corridors) {
    j.BeginObject().Field("id", c.id).Field("ok", c.ok);
    j.Field("length_true_m", c.truth.length_m).Field("length_est_m", c.mapped.length_m);
    j.Field("length_accuracy", c.length_accuracy);
    j.Field("width_true_m", c.truth.width_m).Field("width_est_m", c.mapped.width_m);
    j.Field("width_accuracy", c.width_accuracy).Field("cross_sections_used", c.mapped.cross_sections_used);
    j.EndObject();
  }
  j.EndArray();
  j.Field("plate_reports", r.plate_reports).Field("plate_reports_used", r.plate_reports_used);
  j.Field("final_position_error_m", r.final_position_error_m);
  j.Field("trajectory_rmse_m", r.trajectory_rmse_m).Field("trajectory_max_error_m", r.trajectory_max_error_m);
  j.Field("back_end_odometry_scale", r.odometry_scale).Field("back_end_loop_closures", r.loop_closures);
  j.Field("seconds", r.seconds).Field("sim_seconds", r.sim_seconds).Field("slam_seconds", r.slam_seconds);
  j.Field("map_build_seconds", r.map_build_seconds);
  j.Field("scans", r.scans).Field("scans_processed", r.scans_processed);
  j.Field("degenerate_scans", r.degenerate_scans);
  j.Field("slam_ms_per_processed_scan", r.scans_processed > 0 ? 1000.0 * r.slam_seconds / r.scans_processed : 0.0);
  j.Field("slam_real_time_factor", r.slam_seconds > 0 ? r.sim_seconds / r.slam_seconds : 0.0);
  j.Field("peak_rss_mb", r.peak_rss_kb / 1024.0);
  j.Key("plates").BeginArray();
  for (std::size_t i = 0; i < r.text_map.landmarks.size(); ++i) {
    const TextLandmark& l = r.text_map.landmarks[i];
    j.BeginObject().Field("text", l.text).Field("x_m", l.pose.x_m).Field("y_m", l.pose.y_m);
    j.Field("wall", l.wall).Field("observations", l.observations);
    const double e = i < r.plates.errors_m.size() ? r.plates.errors_m[i] : -1.0;
    if (e >= 0) j.Field("error_m", e); else j.Key("error_m").Null();
    j.EndObject();
  }
  j.EndArray();
  j.EndObject();
}

}  // namespace doorplate_localization

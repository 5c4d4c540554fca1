#include "localize_eval_json.h"

#include <cmath>

namespace doorplate_localization {
namespace {

void WritePose(const std::string& key, const Pose2D& pose, JsonWriter* json) {
  json->Key(key).BeginArray().Value(pose.x_m).Value(pose.y_m).Value(pose.theta_rad).EndArray();
}

// `building`: a building of several floors; its fixes and trials also name the floors.
void WriteFix(const std::string& key, const LocalizeFix& fix, bool building, JsonWriter* json) {
  json->Key(key).BeginObject().Field("travel_m", fix.travel_m).Field("sim_time_s", fix.sim_time_s);
  if (building) json->Field("floor", fix.floor).Field("true_floor", fix.true_floor);
  WritePose("estimate", fix.estimate, json);
  WritePose("truth", fix.truth, json);
  json->Field("error_m", fix.error_m).Field("error_deg", fix.error_deg).Field("within_tolerance", fix.within_tolerance);
  json->EndObject();
}

void WriteTrial(const LocalizeTrial& t, bool kidnap, bool building, JsonWriter* json) {
  json->BeginObject().Field("index", t.index).Field("seed", t.seed);
  WritePose("start_pose", t.start_pose, json);
  if (building) json->Field("start_floor", t.start_floor).Field("floor_travel_m", t.floor_travel_m);
  json->Field("converged", t.converged).Field("success", t.Success()).Field("wrong_convergence", t.WrongConvergence());
  WriteFix(t.converged ? "convergence" : "end_of_search", t.fix, building, json);
  json->Field("plate_reports", t.plate_reports).Field("plate_updates", t.plate_updates).Field("laser_updates",
                                                                                              t.laser_updates);
  if (kidnap) {
    json->Field("kidnapped", t.kidnapped);
    if (t.kidnapped) {
      WritePose("kidnap_pose", t.kidnap_pose, json);
      if (building) json->Field("kidnap_floor", t.kidnap_floor).Field("kidnap_floor_travel_m", t.kidnap_floor_travel_m);
      json->Field("lost_detected", t.lost_detected);
      if (t.lost_detected) json->Field("lost_detected_travel_m", t.lost_detected_travel_m).Field("lost_reason", t.lost_reason);
      json->Field("recovered", t.recovered);
      WriteFix(t.recovered ? "recovery" : "end_of_kidnap_search", t.recovery, building, json);
    }
  }
  json->Field("sim_seconds", t.sim_seconds).Field("seconds", t.wall_seconds).EndObject();
}

void WriteOptions(const LocalizeEvalOptions& o, bool floor, JsonWriter* json) {
  const TextAmclOptions& f = o.filter.filter;
  json->Key("options")
      .BeginObject()
      .Field("max_travel_m", o.max_travel_m)
      .Field("speed_mps", o.speed_mps)
      .Field("success_distance_m", o.success_distance_m)
      .Field("success_angle_deg", o.success_angle_rad * 180.0 / M_PI)
      .Field("camera_rate_hz", o.camera_rate_hz)
      .Field("known_rooms", o.known_rooms)
      .Field("drive", ToString(o.drive))
      .Field("start_poses", floor ? "floor: the world's corridors, length-weighted" : "main corridor band")
      .Field("start_heading", floor ? "along the corridor's centreline (either way), uniform noise"
                                    : "along the corridor (+x or -x), uniform noise")
      .Field("start_heading_noise_deg", o.poses.heading_noise_rad * 180.0 / M_PI)
      .Field("min_kidnap_distance_m", o.poses.min_kidnap_distance_m)
      .Field("laser_model_type", ToString(o.filter.laser_model_type))
      .Field("min_particles", f.min_particles)
      .Field("max_particles", f.max_particles)
      .Field("converged_cluster_weight", f.converged_cluster_weight)
      .Field("converged_stddev_m", f.converged_stddev_m)
      .Field("converged_heading_stddev_rad", f.converged_heading_stddev_rad)
      .Field("text_reseed_fraction", f.text_reseed_fraction)
      .EndObject();
}

}  // namespace

void WriteLocalizeEvalJson(const LocalizeEvalResult& r, const LocalizeEvalRunInfo& info, JsonWriter* json) {
  const LocalizeSummary s = Summarize(r);
  json->BeginObject()
      .Field("command", "localize")
      .Field("command_line", info.command_line)
      .Field("world", r.world_name)
      .Field("world_file", info.world_file)
      .Field("map_file", info.map_file)
      .Field("method", ToString(r.method))
      .Field("kidnap", r.kidnap)
      .Field("seed", info.options.seed)
      .Field("trials", s.trials)
      .Field("successes", s.successes)
      .Field("success_rate", s.success_rate)
      .Field("wrong_convergences", s.wrong_convergences)
      .Field("not_converged", s.not_converged)
      .Field("not_converged_estimate_right", s.not_converged_estimate_right)
      .Field("median_travel_m", s.median_travel_m)
      .Field("longest_travel_m", s.longest_travel_m)
      .Field("median_final_error_m", s.median_final_error_m)
      .Field("median_final_error_deg", s.median_final_error_deg);
  if (r.kidnap) {
    json->Field("kidnaps", s.kidnaps)
        .Field("recoveries", s.recoveries)
        .Field("recovery_rate", s.recovery_rate)
        .Field("kidnap_lost_detected", s.kidnap_lost_detected)
        .Field("median_recovery_travel_m", s.median_recovery_travel_m);
  }
  const bool building = r.floors.size() > 1;
  if (building) {
    json->Key("floors").BeginArray();
    for (const std::string& id : r.floors) json->Value(id);
    json->EndArray().Field("wrong_floor", s.wrong_floor).Field("median_floor_travel_m", s.median_floor_travel_m);
  }
  json->Field("seconds", r.seconds);
  WriteOptions(info.options, r.floor_start_poses, json);
  json->Key("per_trial").BeginArray();
  for (const LocalizeTrial& t : r.trials) WriteTrial(t, r.kidnap, building, json);
  json->EndArray().EndObject();
}

}  // namespace doorplate_localization

#include "localize_eval_json.h"

#include <cmath>

namespace doorplate_localization {
namespace {

Json PoseJson(const Pose2D& pose) { return {pose.x_m, pose.y_m, pose.theta_rad}; }

// `building`: a building of several floors; its fixes and trials also name the floors.
Json FixJson(const LocalizeFix& fix, bool building) {
  Json json;
  json["travel_m"] = fix.travel_m;
  json["sim_time_s"] = fix.sim_time_s;
  if (building) {
    json["floor"] = fix.floor;
    json["true_floor"] = fix.true_floor;
  }
  json["estimate"] = PoseJson(fix.estimate);
  json["truth"] = PoseJson(fix.truth);
  json["error_m"] = fix.error_m;
  json["error_deg"] = fix.error_deg;
  json["within_tolerance"] = fix.within_tolerance;
  return json;
}

Json TrialJson(const LocalizeTrial& t, bool kidnap, bool building) {
  Json json;
  json["index"] = t.index;
  json["seed"] = t.seed;
  json["start_pose"] = PoseJson(t.start_pose);
  if (building) {
    json["start_floor"] = t.start_floor;
    json["floor_travel_m"] = t.floor_travel_m;
  }
  json["converged"] = t.converged;
  json["success"] = t.Success();
  json["wrong_convergence"] = t.WrongConvergence();
  json[t.converged ? "convergence" : "end_of_search"] = FixJson(t.fix, building);
  json["plate_reports"] = t.plate_reports;
  json["plate_updates"] = t.plate_updates;
  json["laser_updates"] = t.laser_updates;
  if (kidnap) {
    json["kidnapped"] = t.kidnapped;
    if (t.kidnapped) {
      json["kidnap_pose"] = PoseJson(t.kidnap_pose);
      if (building) {
        json["kidnap_floor"] = t.kidnap_floor;
        json["kidnap_floor_travel_m"] = t.kidnap_floor_travel_m;
      }
      json["lost_detected"] = t.lost_detected;
      if (t.lost_detected) {
        json["lost_detected_travel_m"] = t.lost_detected_travel_m;
        json["lost_reason"] = t.lost_reason;
      }
      json["recovered"] = t.recovered;
      json[t.recovered ? "recovery" : "end_of_kidnap_search"] = FixJson(t.recovery, building);
    }
  }
  json["sim_seconds"] = t.sim_seconds;
  json["seconds"] = t.wall_seconds;
  return json;
}

Json OptionsJson(const LocalizeEvalOptions& o, bool floor) {
  const TextAmclOptions& f = o.filter.filter;
  Json json;
  json["max_travel_m"] = o.max_travel_m;
  json["speed_mps"] = o.speed_mps;
  json["success_distance_m"] = o.success_distance_m;
  json["success_angle_deg"] = o.success_angle_rad * 180.0 / M_PI;
  json["camera_rate_hz"] = o.camera_rate_hz;
  json["known_rooms"] = o.known_rooms;
  json["drive"] = ToString(o.drive);
  json["start_poses"] = floor ? "floor: the world's corridors, length-weighted" : "main corridor band";
  json["start_heading"] = floor ? "along the corridor's centreline (either way), uniform noise"
                                : "along the corridor (+x or -x), uniform noise";
  json["start_heading_noise_deg"] = o.poses.heading_noise_rad * 180.0 / M_PI;
  json["min_kidnap_distance_m"] = o.poses.min_kidnap_distance_m;
  json["laser_model_type"] = ToString(o.filter.laser_model_type);
  json["min_particles"] = f.min_particles;
  json["max_particles"] = f.max_particles;
  json["converged_cluster_weight"] = f.converged_cluster_weight;
  json["converged_stddev_m"] = f.converged_stddev_m;
  json["converged_heading_stddev_rad"] = f.converged_heading_stddev_rad;
  json["text_reseed_fraction"] = f.text_reseed_fraction;
  return json;
}

}  // namespace

Json LocalizeEvalJson(const LocalizeEvalResult& r, const LocalizeEvalRunInfo& info) {
  const LocalizeSummary s = Summarize(r);
  Json json;
  json["command"] = "localize";
  json["command_line"] = info.command_line;
  json["world"] = r.world_name;
  json["world_file"] = info.world_file;
  json["map_file"] = info.map_file;
  json["method"] = ToString(r.method);
  json["kidnap"] = r.kidnap;
  json["seed"] = info.options.seed;
  json["trials"] = s.trials;
  json["successes"] = s.successes;
  json["success_rate"] = s.success_rate;
  json["wrong_convergences"] = s.wrong_convergences;
  json["not_converged"] = s.not_converged;
  json["not_converged_estimate_right"] = s.not_converged_estimate_right;
  json["median_travel_m"] = s.median_travel_m;
  json["longest_travel_m"] = s.longest_travel_m;
  json["median_final_error_m"] = s.median_final_error_m;
  json["median_final_error_deg"] = s.median_final_error_deg;
  if (r.kidnap) {
    json["kidnaps"] = s.kidnaps;
    json["recoveries"] = s.recoveries;
    json["recovery_rate"] = s.recovery_rate;
    json["kidnap_lost_detected"] = s.kidnap_lost_detected;
    json["median_recovery_travel_m"] = s.median_recovery_travel_m;
  }
  const bool building = r.floors.size() > 1;
  if (building) {
    json["floors"] = r.floors;
    json["wrong_floor"] = s.wrong_floor;
    json["median_floor_travel_m"] = s.median_floor_travel_m;
  }
  json["seconds"] = r.seconds;
  json["options"] = OptionsJson(info.options, r.floor_start_poses);
  json["per_trial"] = Json::array();
  for (const LocalizeTrial& t : r.trials) json["per_trial"].push_back(TrialJson(t, r.kidnap, building));
  return json;
}

}  // namespace doorplate_localization

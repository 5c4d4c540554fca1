// `doorplate_eval goto`: go to a random room from a random corridor pose on a floor (issue 17), driven by
// the Text AMCL estimate, or to a room on another floor of a building by lift (--building); a table of the
// trials and, with --json, the results as JSON.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "doorplate_localization/maps/map_io.h"
#include "building_input.h"
#include "eval_args.h"
#include "eval_commands.h"
#include "goto_eval.h"
#include "json_writer.h"

namespace doorplate_localization {
namespace {

constexpr double kDeg = 180.0 / M_PI;

std::vector<OptionSpec> GotoOptions() {
  return {
      {"world", "", "world file with `corridors` (worlds/*.yaml, docs/world-format.md); or --building"},
      {"building", "", "building file of worlds (worlds/*.building.yaml): start on a random floor, go to a room on "
                       "another floor by lift; the localizer finds the floor after the ride from the plates"},
      {"map", "", "text-map YAML (its occupancy_map names the grid) [<world dir>/../maps/<world name>.text_map.yaml]; "
                  "with --building the maps building file [<building dir>/../maps/<building name>.building.yaml]"},
      {"trials", "30", "number of trials (random start pose and room)"},
      {"seed", "1", "experiment seed; trial i runs with a seed derived from it"},
      {"first-trial", "0", "index of the first trial (to split a run: --first-trial 10 --trials 10 runs trials 10-19)"},
      {"json", "", "write the results as JSON to this file"},
      {"method", "text_amcl", "localizer: text_amcl (laser + camera plates) or amcl (laser only)"},
      {"camera-hz", "0", "camera rate, Hz (0: the world's)"},
      {"speed-mps", "0.4", "cruise speed of the path follower, m/s"},
      {"look-ahead-m", "0.8", "pure-pursuit look-ahead, m"},
      {"success-m", "0.3", "success: the true final position within this of the goal, m"},
  };
}

void PrintTable(const GotoEvalResult& r, const GotoEvalOptions& o) {
  std::printf("world %s, %d trial(s), seed %llu, %s, success within %.2f m\n", r.world_name.c_str(),
              static_cast<int>(r.trials.size()), static_cast<unsigned long long>(o.seed),
              o.use_text ? "text_amcl" : "amcl", o.success_distance_m);
  std::printf("  %2s %-22s %-6s %7s %7s %7s %7s %7s %6s %7s %6s %5s %2s  %s\n", "#", "start (x, y, deg)", "room",
              "plan m", "plan s", "dist m", "along", "across", "yaw d", "trav m", "sim s", "est m", "rp", "outcome");
  for (const GotoTrial& t : r.trials) {
    char start[32];
    std::snprintf(start, sizeof(start), "(%.2f, %.2f, %.0f)", t.start_pose.x_m, t.start_pose.y_m,
                  t.start_pose.theta_rad * kDeg);
    std::printf("  %2d %-22s %-6s %7.1f %7.3f %7.3f %7.3f %7.3f %6.1f %7.1f %6.0f %5.2f %2d  %s%s%s\n", t.index, start,
                t.room.c_str(), t.plan_length_m, t.plan_seconds, t.distance_m, t.along_m, t.across_m,
                t.yaw_error_rad * kDeg, t.travel_m, t.sim_seconds, t.estimate_error_m, t.replans,
                t.success ? "SUCCESS " : "FAIL ", t.bumped ? "(bumped) " : "", t.outcome.c_str());
    if (r.floors.size() > 1) {
      std::printf("      floor %s -> %s: %s; %s", t.start_floor.c_str(), t.room_floor.c_str(), t.instruction.c_str(),
                  t.rode ? "rode" : "did not ride");
      if (t.rode) {
        std::printf(" (%.2f m from the stop), searched %.1f m after the ride, %s", t.lift_stop_distance_m,
                    t.searched_m, t.found_floor ? "localized on the room's floor" : "NOT localized on the room's floor");
      }
      std::printf("\n");
    }
  }
  const GotoSummary s = Summarize(r);
  std::printf("  success %d/%d (arrived %d, bumped %d); distance to goal median %.3f m, max %.3f m; |yaw error| "
              "median %.1f deg; travel median %.1f m, sim time median %.0f s; plan time median %.3f s, max %.3f s; "
              "plan min clearance %.2f m; estimate error at the end median %.3f m; %.0f s\n",
              s.successes, s.trials, s.arrived, s.bumped, s.median_distance_m, s.max_distance_m,
              s.median_abs_yaw_rad * kDeg, s.median_travel_m, s.median_sim_s, s.median_plan_s, s.max_plan_s,
              s.min_plan_clearance_m, s.median_estimate_error_m, r.seconds);
  if (r.floors.size() > 1) {
    std::printf("  building of %zu floors: %d rides, %d localized on the room's floor after the ride; search after "
                "the ride median %.1f m, max %.1f m\n", r.floors.size(), s.rides, s.found_floor, s.median_searched_m,
                s.max_searched_m);
  }
}

void WritePose(JsonWriter* json, const std::string& key, const Pose2D& p) {
  json->Key(key).BeginObject().Field("x_m", p.x_m).Field("y_m", p.y_m).Field("theta_rad", p.theta_rad).EndObject();
}

void WriteJson(const GotoEvalResult& r, const GotoEvalOptions& o, const std::string& world_path,
               const std::string& map_path, const std::string& command_line, JsonWriter* json) {
  const GotoSummary s = Summarize(r);
  json->BeginObject();
  json->Field("experiment", "goto").Field("command_line", command_line).Field("world", world_path);
  json->Field("map", map_path).Field("world_name", r.world_name);
  json->Key("options").BeginObject();
  json->Field("trials", o.trials).Field("first_trial", o.first_trial).Field("seed", o.seed);
  json->Field("method", o.use_text ? "text_amcl" : "amcl").Field("camera_rate_hz", o.camera_rate_hz);
  json->Field("success_distance_m", o.success_distance_m).Field("initial_std_m", o.initial_std_m);
  json->Field("initial_std_rad", o.initial_std_rad).Field("cruise_speed_mps", o.go.follower.cruise_speed_mps);
  json->Field("look_ahead_m", o.go.follower.look_ahead_m).Field("clearance_m", o.go.planner.clearance_m);
  json->Field("preferred_clearance_m", o.go.planner.preferred_clearance_m);
  json->Field("wall_cost_weight", o.go.planner.wall_cost_weight);
  json->EndObject();
  json->Key("summary").BeginObject();
  json->Field("trials", s.trials).Field("successes", s.successes).Field("arrived", s.arrived);
  json->Field("bumped", s.bumped).Field("median_distance_m", s.median_distance_m);
  json->Field("max_distance_m", s.max_distance_m).Field("median_abs_yaw_rad", s.median_abs_yaw_rad);
  json->Field("median_travel_m", s.median_travel_m).Field("median_sim_s", s.median_sim_s);
  json->Field("median_plan_s", s.median_plan_s).Field("max_plan_s", s.max_plan_s);
  json->Field("min_plan_clearance_m", s.min_plan_clearance_m);
  json->Field("median_estimate_error_m", s.median_estimate_error_m).Field("seconds", r.seconds);
  if (r.floors.size() > 1) {
    json->Field("rides", s.rides).Field("found_floor", s.found_floor);
    json->Field("median_searched_m", s.median_searched_m).Field("max_searched_m", s.max_searched_m);
  }
  json->EndObject();
  json->Key("trials").BeginArray();
  for (const GotoTrial& t : r.trials) {
    json->BeginObject();
    json->Field("index", t.index).Field("seed", t.seed);
    WritePose(json, "start", t.start_pose);
    json->Field("room", t.room);
    if (r.floors.size() > 1) {
      json->Field("start_floor", t.start_floor).Field("room_floor", t.room_floor).Field("lift", t.lift);
      json->Field("instruction", t.instruction).Field("rode", t.rode);
      json->Field("lift_stop_distance_m", t.lift_stop_distance_m).Field("searched_m", t.searched_m);
      json->Field("found_floor", t.found_floor);
    }
    WritePose(json, "goal", t.goal);
    json->Field("success", t.success).Field("arrived", t.arrived).Field("outcome", t.outcome);
    json->Field("plan_length_m", t.plan_length_m).Field("plan_seconds", t.plan_seconds);
    json->Field("plan_min_clearance_m", t.plan_min_clearance_m);
    json->Field("plan_mean_clearance_m", t.plan_mean_clearance_m).Field("replans", t.replans);
    WritePose(json, "final_pose", t.final_pose);
    WritePose(json, "final_estimate", t.final_estimate);
    json->Field("distance_m", t.distance_m).Field("along_m", t.along_m).Field("across_m", t.across_m);
    json->Field("yaw_error_rad", t.yaw_error_rad).Field("estimate_error_m", t.estimate_error_m);
    json->Field("travel_m", t.travel_m).Field("sim_seconds", t.sim_seconds).Field("wall_seconds", t.wall_seconds);
    json->Field("bumped", t.bumped).Field("plate_updates", t.plate_updates);
    json->EndObject();
  }
  json->EndArray();
  json->EndObject();
}

}  // namespace

int RunGotoCommand(const std::vector<std::string>& args, const std::string& command_line) {
  EvalArgs parsed("goto", GotoOptions());
  parsed.Parse(args);
  if (parsed.help_requested()) {
    std::cout << "Go to a random room from a random corridor pose on a floor (grid path planner + pure pursuit on "
                 "the Text AMCL estimate).\n"
              << parsed.Usage();
    return 0;
  }
  GotoEvalOptions options;
  options.trials = parsed.Integer("trials", 1);
  options.first_trial = parsed.Integer("first-trial", 0);
  options.seed = parsed.Unsigned("seed");
  const std::string method = parsed.String("method");
  if (method != "text_amcl" && method != "amcl") {
    throw UsageError("goto: --method: '" + method + "' must be text_amcl or amcl");
  }
  options.use_text = method == "text_amcl";
  options.camera_rate_hz = parsed.Number("camera-hz");
  if (options.camera_rate_hz < 0.0) throw UsageError("goto: --camera-hz must be >= 0");
  options.go.follower.cruise_speed_mps = parsed.Number("speed-mps");
  if (options.go.follower.cruise_speed_mps <= 0.0) throw UsageError("goto: --speed-mps must be > 0");
  options.go.follower.look_ahead_m = parsed.Number("look-ahead-m");
  if (options.go.follower.look_ahead_m <= 0.0) throw UsageError("goto: --look-ahead-m must be > 0");
  options.success_distance_m = parsed.Number("success-m");
  if (options.success_distance_m <= 0.0) throw UsageError("goto: --success-m must be > 0");
  const std::string json_path = parsed.String("json");
  if (!json_path.empty()) {
    const std::filesystem::path parent = std::filesystem::path(json_path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent)) {
      throw UsageError("goto: --json: folder " + parent.string() + " does not exist");
    }
  }

  const std::string world_path = parsed.String("world");
  const std::string building_path = parsed.String("building");
  std::string map_path;
  const LocalizeBuilding building =
      LoadExperimentBuilding("goto", world_path, building_path, parsed.String("map"), &map_path);
  const GotoEvalResult result = RunGotoEval(building, options);
  PrintTable(result, options);
  if (!json_path.empty()) {
    std::ostringstream out;
    JsonWriter json(&out);
    WriteJson(result, options, building_path.empty() ? world_path : building_path, map_path, command_line, &json);
    out << "\n";
    WriteFileAtomically(json_path, out.str());
  }
  return 0;
}

}  // namespace doorplate_localization

// `doorplate_eval goto`: go to a random room from a random corridor pose on a floor (issue 17), driven by
// the Text AMCL estimate, or to a room on another floor of a building by lift (--building); a table of the
// trials and, with --json, the results as JSON.
#include <cstdio>
#include <memory>

#include "doorplate_localization/maps/map_io.h"
#include "building_input.h"
#include "cli_app.h"
#include "eval_args.h"
#include "eval_commands.h"
#include "goto_eval.h"
#include "output_guard.h"
#include "result_json.h"

namespace doorplate_localization {
namespace {

constexpr double kDeg = 180.0 / M_PI;

struct GotoArgs {
  std::string world, building, map, json, method = "text_amcl";
  GotoEvalOptions options;  // the numbers, bound directly
};

void AddGotoOptions(CLI::App* cmd, GotoArgs* a) {
  GotoEvalOptions& o = a->options;
  cmd->add_option("--world", a->world, "world file with `corridors` (worlds/*.yaml, docs/world-format.md); or --building");
  cmd->add_option("--building", a->building, "building file of worlds (worlds/*.building.yaml): start on a random floor, "
                  "go to a room on another floor by lift; the localizer finds the floor after the ride from the plates");
  cmd->add_option("--map", a->map, "text-map YAML (its occupancy_map names the grid) [<world dir>/../maps/<world name>"
                  ".text_map.yaml]; with --building the maps building file [<building dir>/../maps/<building name>"
                  ".building.yaml]");
  cmd->add_option("--trials", o.trials, "number of trials (random start pose and room)")->capture_default_str()
      ->transform(tools::WholeNumber(1));
  cmd->add_option("--seed", o.seed, "experiment seed; trial i runs with a seed derived from it")->capture_default_str()
      ->transform(tools::Seed());
  cmd->add_option("--first-trial", o.first_trial, "index of the first trial (to split a run: --first-trial 10 --trials "
                  "10 runs trials 10-19)")->capture_default_str()->transform(tools::WholeNumber(0));
  cmd->add_option("--json", a->json, "write the results as JSON to this file")->check(tools::InExistingFolder());
  cmd->add_option("--method", a->method, "localizer: text_amcl (laser + camera plates) or amcl (laser only)")
      ->capture_default_str()->check(CLI::IsMember({"text_amcl", "amcl"}));
  cmd->add_option("--camera-hz", o.camera_rate_hz, "camera rate, Hz (0: the world's)")->capture_default_str()
      ->check(tools::Number(0.0));
  cmd->add_option("--speed-mps", o.go.follower.cruise_speed_mps, "cruise speed of the path follower, m/s")
      ->capture_default_str()->check(tools::PositiveNumber());
  cmd->add_option("--look-ahead-m", o.go.follower.look_ahead_m, "pure-pursuit look-ahead, m")->capture_default_str()
      ->check(tools::PositiveNumber());
  cmd->add_option("--success-m", o.success_distance_m, "success: the true final position within this of the goal, m")
      ->capture_default_str()->check(tools::PositiveNumber());
  o.progress_every_s = 60.0;
  cmd->add_option("--progress-s", o.progress_every_s, "a progress line on stderr every this many simulated seconds "
                  "(rewritten in place twice a second on a terminal; 0: none)")->capture_default_str()
      ->check(tools::Number(0.0));
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

Json PoseJson(const Pose2D& p) { return {{"x_m", p.x_m}, {"y_m", p.y_m}, {"theta_rad", p.theta_rad}}; }

Json OptionsJson(const GotoEvalOptions& o) {
  Json j;
  j["trials"] = o.trials;
  j["first_trial"] = o.first_trial;
  j["seed"] = o.seed;
  j["method"] = o.use_text ? "text_amcl" : "amcl";
  j["camera_rate_hz"] = o.camera_rate_hz;
  j["success_distance_m"] = o.success_distance_m;
  j["initial_std_m"] = o.initial_std_m;
  j["initial_std_rad"] = o.initial_std_rad;
  j["cruise_speed_mps"] = o.go.follower.cruise_speed_mps;
  j["look_ahead_m"] = o.go.follower.look_ahead_m;
  j["clearance_m"] = o.go.planner.clearance_m;
  j["preferred_clearance_m"] = o.go.planner.preferred_clearance_m;
  j["wall_cost_weight"] = o.go.planner.wall_cost_weight;
  return j;
}

Json SummaryJson(const GotoEvalResult& r) {
  const GotoSummary s = Summarize(r);
  Json j;
  j["trials"] = s.trials;
  j["successes"] = s.successes;
  j["arrived"] = s.arrived;
  j["bumped"] = s.bumped;
  j["median_distance_m"] = s.median_distance_m;
  j["max_distance_m"] = s.max_distance_m;
  j["median_abs_yaw_rad"] = s.median_abs_yaw_rad;
  j["median_travel_m"] = s.median_travel_m;
  j["median_sim_s"] = s.median_sim_s;
  j["median_plan_s"] = s.median_plan_s;
  j["max_plan_s"] = s.max_plan_s;
  j["min_plan_clearance_m"] = s.min_plan_clearance_m;
  j["median_estimate_error_m"] = s.median_estimate_error_m;
  j["seconds"] = r.seconds;
  if (r.floors.size() > 1) {
    j["rides"] = s.rides;
    j["found_floor"] = s.found_floor;
    j["median_searched_m"] = s.median_searched_m;
    j["max_searched_m"] = s.max_searched_m;
  }
  return j;
}

Json TrialJson(const GotoTrial& t, bool building) {
  Json j;
  j["index"] = t.index;
  j["seed"] = t.seed;
  j["start"] = PoseJson(t.start_pose);
  j["room"] = t.room;
  if (building) {
    j["start_floor"] = t.start_floor;
    j["room_floor"] = t.room_floor;
    j["lift"] = t.lift;
    j["instruction"] = t.instruction;
    j["rode"] = t.rode;
    j["lift_stop_distance_m"] = t.lift_stop_distance_m;
    j["searched_m"] = t.searched_m;
    j["found_floor"] = t.found_floor;
  }
  j["goal"] = PoseJson(t.goal);
  j["success"] = t.success;
  j["arrived"] = t.arrived;
  j["outcome"] = t.outcome;
  j["plan_length_m"] = t.plan_length_m;
  j["plan_seconds"] = t.plan_seconds;
  j["plan_min_clearance_m"] = t.plan_min_clearance_m;
  j["plan_mean_clearance_m"] = t.plan_mean_clearance_m;
  j["replans"] = t.replans;
  j["final_pose"] = PoseJson(t.final_pose);
  j["final_estimate"] = PoseJson(t.final_estimate);
  j["distance_m"] = t.distance_m;
  j["along_m"] = t.along_m;
  j["across_m"] = t.across_m;
  j["yaw_error_rad"] = t.yaw_error_rad;
  j["estimate_error_m"] = t.estimate_error_m;
  j["travel_m"] = t.travel_m;
  j["sim_seconds"] = t.sim_seconds;
  j["wall_seconds"] = t.wall_seconds;
  j["bumped"] = t.bumped;
  j["plate_updates"] = t.plate_updates;
  return j;
}

Json GotoJson(const GotoEvalResult& r, const GotoEvalOptions& o, const std::string& world_path,
              const std::string& map_path, const std::string& command_line) {
  Json j;
  j["experiment"] = "goto";
  j["command_line"] = command_line;
  j["world"] = world_path;
  j["map"] = map_path;
  j["world_name"] = r.world_name;
  j["options"] = OptionsJson(o);
  j["summary"] = SummaryJson(r);
  j["trials"] = Json::array();
  for (const GotoTrial& t : r.trials) j["trials"].push_back(TrialJson(t, r.floors.size() > 1));
  return j;
}

int RunGoto(const GotoArgs& a, const std::string& command_line) {
  GotoEvalOptions options = a.options;
  options.use_text = a.method == "text_amcl";
  std::string map_path;
  const LocalizeBuilding building = LoadExperimentBuilding("goto", a.world, a.building, a.map, &map_path);
  tools::RefuseOverwritingInputs({{"--world", a.world}, {"--building", a.building}, {"--map", map_path}},
                                 {{"--json", a.json}});  // issue 18: an output never replaces an input
  const GotoEvalResult result = RunGotoEval(building, options);
  PrintTable(result, options);
  if (!a.json.empty()) {
    const std::string world = a.building.empty() ? a.world : a.building;
    WriteFileAtomically(a.json, ResultJsonText(GotoJson(result, options, world, map_path, command_line)));
  }
  return 0;
}

}  // namespace

EvalCommand AddGotoCommand(CLI::App* eval, const std::string& command_line) {
  auto args = std::make_shared<GotoArgs>();
  CLI::App* go = eval->add_subcommand("goto", "Go to a random room from a random corridor pose on a floor (grid path "
                                      "planner + pure pursuit on the Text AMCL estimate).");
  AddGotoOptions(go, args.get());
  return {go, [args, command_line] { return RunGoto(*args, command_line); }};
}

}  // namespace doorplate_localization

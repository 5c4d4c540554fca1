// `doorplate_eval localize`: global localization and kidnapped-robot trials (paper Table III) on one world,
// or on a building of several floors (--building).
#include <cstdio>
#include <memory>

#include "doorplate_localization/maps/map_io.h"
#include "building_input.h"
#include "cli_app.h"
#include "eval_args.h"
#include "eval_commands.h"
#include "localize_eval.h"
#include "localize_eval_json.h"
#include "output_guard.h"

namespace doorplate_localization {
namespace {

struct LocalizeArgs {
  std::string world, building, map, method = "text_amcl", json, drive = "auto";
  std::string recognizer = "tesseract", laser_model = "likelihood_field";
  LocalizeEvalOptions options;  // the numbers and switches, bound directly
};

void AddLocalizeOptions(CLI::App* cmd, LocalizeArgs* a) {
  LocalizeEvalOptions& o = a->options;
  cmd->add_option("--world", a->world, "world file (worlds/*.yaml, docs/world-format.md); or --building");
  cmd->add_option("--building", a->building, "building file of worlds (worlds/*.building.yaml, docs/building-format.md): "
                  "trials start on a random floor the filter is not told, a kidnap is a ride to a random floor");
  cmd->add_option("--map", a->map, "text-map YAML the filter uses (its occupancy_map names the grid) [<world dir>/../maps/"
                  "<world name>.text_map.yaml]; with --building the maps building file [<building dir>/../maps/"
                  "<building name>.building.yaml]");
  cmd->add_option("--method", a->method, "amcl (laser only) or text_amcl (laser + doorplate readings)")
      ->capture_default_str()->check(CLI::IsMember({"amcl", "text_amcl"}));
  cmd->add_option("--trials", o.trials, "number of trials (random start poses)")->capture_default_str()
      ->transform(tools::WholeNumber(1));
  cmd->add_option("--seed", o.seed, "experiment seed; trial i runs with a seed derived from it")->capture_default_str()
      ->transform(tools::Seed());
  cmd->add_option("--json", a->json, "write the results as JSON to this file")->check(tools::InExistingFolder());
  cmd->add_option("--kidnap", o.kidnap, "after a successful convergence teleport the robot and measure the recovery "
                  "(--kidnap alone: on)")->expected(0, 1)->default_str("on")->option_text("[on|off]=off")
      ->transform(tools::OnOff());
  cmd->add_option("--max-travel-m", o.max_travel_m, "a search (and a recovery) fails after the robot drove this far")
      ->capture_default_str()->check(tools::PositiveNumber());
  cmd->add_option("--speed-mps", o.speed_mps, "cruise speed of the robot, m/s")->capture_default_str()
      ->check(tools::PositiveNumber());
  cmd->add_option("--drive", a->drive, "patrol (one corridor: along a wall, turn at the end, back) or contour (a floor: "
                  "follow the right wall round corners, into side corridors, out of dead ends); auto: contour when the "
                  "world lists more than one corridor")->capture_default_str();
  cmd->add_option("--known-rooms", o.known_rooms, "give the text validator the text map's room list (on) or not (off)")
      ->transform(tools::OnOff())->default_str("off");
  cmd->add_option("--camera-hz", o.camera_rate_hz, "camera rate, Hz (0: the world's)")->capture_default_str()
      ->check(tools::Number(0.0));
  cmd->add_option("--recognizer", a->recognizer, "text recogniser: tesseract or ppocr (the learned one; "
                  "scripts/fetch_ocr_models.sh)")->capture_default_str();
  cmd->add_option("--max-particles", o.filter.filter.max_particles, "filter max_particles (global localization draws "
                  "this many)")->capture_default_str()->transform(tools::WholeNumber(1));
  cmd->add_option("--laser-model", a->laser_model, "laser_model_type: likelihood_field, likelihood_field_prob or beam")
      ->capture_default_str();
  o.progress_every_s = 60.0;
  cmd->add_option("--progress-s", o.progress_every_s, "a progress line on stderr every this many simulated seconds "
                  "(rewritten in place twice a second on a terminal; 0: none)")->capture_default_str()
      ->check(tools::Number(0.0));
}

void PrintSummary(const LocalizeEvalResult& r, const LocalizeEvalOptions& o) {
  const LocalizeSummary s = Summarize(r);
  std::printf("world %s, %s, %d trial(s), seed %llu, drive %s%s\n", r.world_name.c_str(), ToString(r.method),
              s.trials, static_cast<unsigned long long>(o.seed), ToString(o.drive), r.kidnap ? ", kidnap" : "");
  const bool building = r.floors.size() > 1;
  for (const LocalizeTrial& t : r.trials) {
    std::printf("  trial %2d: ", t.index);
    if (building) {
      std::printf("floor %s (certain after %.1f m, fix on floor %s), ", t.start_floor.c_str(), t.floor_travel_m,
                  t.fix.floor.c_str());
    }
    std::printf("start (%.2f, %.2f, %.0f deg) %s after %.1f m: error %.2f m %.1f deg, %d/%d plates used",
                t.start_pose.x_m, t.start_pose.y_m, t.start_pose.theta_rad * 180.0 / M_PI,
                t.Success() ? "SUCCESS" : t.converged ? "WRONG CONVERGENCE" : "not converged", t.fix.travel_m,
                t.fix.error_m, t.fix.error_deg, t.plate_updates, t.plate_reports);
    if (t.kidnapped) {
      if (building) std::printf("; kidnap to floor %s", t.kidnap_floor.c_str());
      std::printf("; kidnap to (%.2f, %.2f): %s after %.1f m%s", t.kidnap_pose.x_m, t.kidnap_pose.y_m,
                  t.recovered ? "recovered" : "NOT recovered", t.recovery.travel_m,
                  t.lost_detected ? (", lost detected (" + t.lost_reason + ")").c_str() : "");
    }
    std::printf(" [%.0f s]\n", t.wall_seconds);
  }
  std::printf("  success %d/%d = %.1f %%, wrong convergences %d, not converged %d (estimate right at the end: %d); "
              "median travel %.1f m (longest %.1f m), median error %.3f m %.2f deg\n",
              s.successes, s.trials, 100.0 * s.success_rate, s.wrong_convergences, s.not_converged,
              s.not_converged_estimate_right, s.median_travel_m, s.longest_travel_m, s.median_final_error_m,
              s.median_final_error_deg);
  if (building) {
    std::printf("  building of %zu floors: converged on the wrong floor %d, median travel until the floor was certain "
                "%.1f m\n", r.floors.size(), s.wrong_floor, s.median_floor_travel_m);
  }
  if (r.kidnap) {
    std::printf("  kidnap: recovered %d/%d = %.1f %%, median recovery travel %.1f m, lost detected %d\n", s.recoveries,
                s.kidnaps, 100.0 * s.recovery_rate, s.median_recovery_travel_m, s.kidnap_lost_detected);
  }
  std::printf("  %.0f s\n", r.seconds);
}

int RunLocalize(const LocalizeArgs& a, const std::string& command_line) {
  LocalizeEvalOptions options = a.options;
  options.method = a.method == "amcl" ? LocalizeMethod::kAmcl : LocalizeMethod::kTextAmcl;
  try {
    options.extractor.recognizer_type = ParseTextRecognizerType(a.recognizer, "localize: --recognizer");
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  UseReadingScheduleFor(options.extractor.recognizer_type, &options.extractor.tracker);
  try {
    options.filter.laser_model_type = ParseLaserModelType(a.laser_model);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("localize: --laser-model: ") + e.what());
  }

  std::string map_path;
  const LocalizeBuilding building = LoadExperimentBuilding("localize", a.world, a.building, a.map, &map_path);
  try {
    options.drive = a.drive == "auto" ? (building.worlds.front().corridors.size() > 1 ? LocalizeDrive::kContour
                                                                                      : LocalizeDrive::kPatrol)
                                      : ParseLocalizeDrive(a.drive);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("localize: --drive: ") + e.what() + " (or auto)");
  }

  tools::RefuseOverwritingInputs({{"--world", a.world}, {"--building", a.building}, {"--map", map_path}},
                                 {{"--json", a.json}});  // issue 18: an output never replaces an input
  const LocalizeEvalResult result = RunLocalizeEval(building, options);
  PrintSummary(result, options);
  if (!a.json.empty()) {
    const LocalizeEvalRunInfo info{a.building.empty() ? a.world : a.building, map_path, command_line, options};
    WriteFileAtomically(a.json, ResultJsonText(LocalizeEvalJson(result, info)));
  }
  return 0;
}

}  // namespace

EvalCommand AddLocalizeCommand(CLI::App* eval, const std::string& command_line) {
  auto args = std::make_shared<LocalizeArgs>();
  CLI::App* localize = eval->add_subcommand(
      "localize", "Global localization and kidnapped-robot trials on a simulated corridor (paper Table III) or floor.");
  AddLocalizeOptions(localize, args.get());
  return {localize, [args, command_line] { return RunLocalize(*args, command_line); }};
}

}  // namespace doorplate_localization

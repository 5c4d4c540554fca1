// `doorplate_eval localize`: global localization and kidnapped-robot trials (paper Table III) on one world,
// or on a building of several floors (--building).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "doorplate_localization/maps/map_io.h"
#include "building_input.h"
#include "eval_args.h"
#include "eval_commands.h"
#include "localize_eval.h"
#include "localize_eval_json.h"

namespace doorplate_localization {
namespace {

std::vector<OptionSpec> LocalizeOptions() {
  return {
      {"world", "", "world file (worlds/*.yaml, docs/world-format.md); or --building"},
      {"building", "", "building file of worlds (worlds/*.building.yaml, docs/building-format.md): trials start on a "
                       "random floor the filter is not told, a kidnap is a ride to a random floor"},
      {"map", "", "text-map YAML the filter uses (its occupancy_map names the grid) [<world dir>/../maps/<world name>.text_map.yaml]; "
                  "with --building the maps building file [<building dir>/../maps/<building name>.building.yaml]"},
      {"method", "text_amcl", "amcl (laser only) or text_amcl (laser + doorplate readings)"},
      {"trials", "30", "number of trials (random start poses)"},
      {"seed", "1", "experiment seed; trial i runs with a seed derived from it"},
      {"json", "", "write the results as JSON to this file"},
      {"kidnap", "off", "after a successful convergence teleport the robot and measure the recovery (--kidnap alone: on)"},
      {"max-travel-m", "120", "a search (and a recovery) fails after the robot drove this far"},
      {"speed-mps", "0.4", "cruise speed of the robot, m/s"},
      {"drive", "auto", "patrol (one corridor: along a wall, turn at the end, back) or contour (a floor: follow the "
                        "right wall round corners, into side corridors, out of dead ends); auto: contour when the "
                        "world lists more than one corridor"},
      {"known-rooms", "off", "give the text validator the text map's room list (on) or not (off)"},
      {"camera-hz", "0", "camera rate, Hz (0: the world's)"},
      {"recognizer", "tesseract", "text recogniser: tesseract or ppocr (the learned one; scripts/fetch_ocr_models.sh)"},
      {"max-particles", "5000", "filter max_particles (global localization draws this many)"},
      {"laser-model", "likelihood_field", "laser_model_type: likelihood_field, likelihood_field_prob or beam"},
  };
}

// `--kidnap` may stand alone (a flag) or take on/off; EvalArgs wants a value after every option.
std::vector<std::string> ExpandKidnapFlag(const std::vector<std::string>& args) {
  std::vector<std::string> out;
  for (size_t i = 0; i < args.size(); ++i) {
    out.push_back(args[i]);
    if (args[i] != "--kidnap") continue;
    const bool has_value = i + 1 < args.size() && args[i + 1].compare(0, 2, "--") != 0;
    if (!has_value) out.push_back("on");
  }
  return out;
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

}  // namespace

int RunLocalizeCommand(const std::vector<std::string>& args, const std::string& command_line) {
  EvalArgs parsed("localize", LocalizeOptions());
  parsed.Parse(ExpandKidnapFlag(args));
  if (parsed.help_requested()) {
    std::cout << "Global localization and kidnapped-robot trials on a simulated corridor (paper Table III) or floor.\n"
              << parsed.Usage();
    return 0;
  }
  LocalizeEvalOptions options;
  const std::string method = parsed.String("method");
  if (method == "amcl") {
    options.method = LocalizeMethod::kAmcl;
  } else if (method != "text_amcl") {
    throw UsageError("localize: --method: '" + method + "' must be amcl or text_amcl");
  }
  options.trials = parsed.Integer("trials", 1);
  options.seed = parsed.Unsigned("seed");
  options.kidnap = parsed.OnOff("kidnap");
  options.max_travel_m = parsed.Number("max-travel-m");
  if (options.max_travel_m <= 0.0) throw UsageError("localize: --max-travel-m must be > 0");
  options.speed_mps = parsed.Number("speed-mps");
  if (options.speed_mps <= 0.0) throw UsageError("localize: --speed-mps must be > 0");
  options.known_rooms = parsed.OnOff("known-rooms");
  options.camera_rate_hz = parsed.Number("camera-hz");
  try {
    options.extractor.recognizer_type = ParseTextRecognizerType(parsed.String("recognizer"), "localize: --recognizer");
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  UseReadingScheduleFor(options.extractor.recognizer_type, &options.extractor.tracker);
  if (options.camera_rate_hz < 0.0) throw UsageError("localize: --camera-hz must be >= 0");
  options.filter.filter.max_particles = parsed.Integer("max-particles", 1);
  try {
    options.filter.laser_model_type = ParseLaserModelType(parsed.String("laser-model"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("localize: --laser-model: ") + e.what());
  }
  const std::string json_path = parsed.String("json");
  if (!json_path.empty()) {
    const std::filesystem::path parent = std::filesystem::path(json_path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent)) {
      throw UsageError("localize: --json: folder " + parent.string() + " does not exist");
    }
  }

  const std::string world_path = parsed.String("world");
  const std::string building_path = parsed.String("building");
  std::string map_path;
  const LocalizeBuilding building =
      LoadExperimentBuilding("localize", world_path, building_path, parsed.String("map"), &map_path);
  const std::string drive = parsed.String("drive");
  try {
    options.drive = drive == "auto" ? (building.worlds.front().corridors.size() > 1 ? LocalizeDrive::kContour
                                                                                    : LocalizeDrive::kPatrol)
                                    : ParseLocalizeDrive(drive);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("localize: --drive: ") + e.what() + " (or auto)");
  }

  const LocalizeEvalResult result = RunLocalizeEval(building, options);
  PrintSummary(result, options);
  if (!json_path.empty()) {
    std::ostringstream out;
    JsonWriter json(&out);
    WriteLocalizeEvalJson(result, {building_path.empty() ? world_path : building_path, map_path, command_line, options},
                          &json);
    out << "\n";
    WriteFileAtomically(json_path, out.str());
  }
  return 0;
}

}  // namespace doorplate_localization

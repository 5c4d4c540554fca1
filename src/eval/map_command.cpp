// `doorplate_eval map`: SLAM of one corridor sweep, laser only (rbpf) or with doorplate text (rbpf_text),
// measured against the world (paper Table II).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/world_loader.h"
#include "doorplate_localization/slam/rbpf_slam_options.h"
#include "eval_args.h"
#include "eval_commands.h"
#include "map_eval.h"
#include "map_eval_json.h"
#include "map_output.h"

namespace doorplate_localization {
namespace {

std::vector<OptionSpec> MapOptions() {
  return {
      {"world", "", "world file (worlds/*.yaml, docs/world-format.md)", true},
      {"method", "rbpf_text", "rbpf (laser only) or rbpf_text (with doorplate landmarks)"},
      {"seed", "1", "experiment seed (simulator and filter seeds are derived from it)"},
      {"particles", "30", "number of particles"},
      {"speed-mps", "0.4", "cruise speed of the robot, m/s"},
      {"max-seconds", "1800", "simulated seconds after which an unfinished drive ends the run"},
      {"drive", "auto", "sweep (one corridor: out and back), explore (a whole floor: FloorExplorer's passes) "
                        "or auto (explore when the world lists more than one corridor)"},
      {"set", "", "SLAM options NAME=VALUE[,NAME=VALUE...] (names: rbpf_slam_options.h, text.<field>)"},
      {"progress-s", "60", "a progress line on stderr every this many simulated seconds (0: none)"},
      {"json", "", "write the results as JSON to this file"},
      {"out-dir", "", "write map.pgm/.yaml, text_map.yaml and map.png into this folder"},
  };
}

void ApplySets(const std::string& sets, TextSlamOptions* options) {
  std::stringstream list(sets);
  std::string item;
  while (std::getline(list, item, ',')) {
    if (item.empty()) continue;
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos) throw UsageError("map: --set: '" + item + "' is not NAME=VALUE");
    const std::string name = item.substr(0, eq), value = item.substr(eq + 1);
    std::size_t used = 0;
    double number = 0.0;
    try {
      number = std::stod(value, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != value.size() || value.empty()) throw UsageError("map: --set " + name + ": '" + value + "' is not a number");
    try {
      SetTextSlamOption(name, number, options);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("map: --set: ") + e.what());
    }
  }
}

void PrintSummary(const MapEvalResult& r, MapMethod method, std::uint64_t seed, MapDrive drive) {
  std::printf("world %s, %s, seed %llu: %s %s, %.0f s simulated in %.1f s (SLAM %.1f s CPU, %d/%d scans, %d degenerate)\n",
              r.world_name.c_str(), MapMethodName(method), static_cast<unsigned long long>(seed), MapDriveName(drive),
              r.sweep_done ? "done" : "NOT finished", r.sim_seconds, r.seconds, r.slam_seconds, r.scans_processed,
              r.scans, r.degenerate_scans);
  if (r.corridors.empty()) {  // one straight corridor: its principal axis (with corridors: per corridor below)
    std::printf("  length %.3f m (true %.3f) accuracy %.2f %%; width %.3f m (true %.3f) accuracy %.2f %%\n",
                r.estimate.length_m, r.truth.length_m, 100.0 * r.length_accuracy, r.estimate.width_m, r.truth.width_m,
                100.0 * r.width_accuracy);
  }
  std::printf("  plates: %d/%d mapped (%d in the map, %d/%d reports used), RMSE %.3f m, max %.3f m; final pose "
              "error %.3f m; peak RSS %.0f MB\n",
              r.plates.plates_mapped, r.plates.plates_true, r.plates.plates_in_map, r.plate_reports_used,
              r.plate_reports, r.plates.rmse_m, r.plates.max_error_m, r.final_position_error_m, r.peak_rss_kb / 1024.0);
  std::printf("  trajectory error (processed scans): RMSE %.3f m, max %.3f m\n", r.trajectory_rmse_m,
              r.trajectory_max_error_m);
  if (r.loop_closures > 0 || r.odometry_scale != 1.0) {
    std::printf("  back end: odometry scale %.4f (true / odometry distance), %d loop closures; final maps built in %.2f s CPU\n",
                r.odometry_scale, r.loop_closures, r.map_build_seconds);
  }
}

void PrintDrive(const MapEvalResult& r, MapDrive drive) {
  if (r.plate_fit.ok) {
    std::printf("  plates after the best rigid fit of the map (%d pairs): RMSE %.3f m, max %.3f m\n", r.plate_fit.pairs,
                r.plates_fitted.rmse_m, r.plates_fitted.max_error_m);
  }
  for (const CorridorAccuracy& c : r.corridors) {
    if (!c.ok) {
      std::printf("  corridor %s: not measured (a ray found no wall, or no cross-section)\n", c.id.c_str());
      continue;
    }
    std::printf("  corridor %s: length %.3f m (true %.3f) %.2f %%, width %.3f m (true %.3f) %.2f %%\n", c.id.c_str(),
                c.mapped.length_m, c.truth.length_m, 100.0 * c.length_accuracy, c.mapped.width_m, c.truth.width_m,
                100.0 * c.width_accuracy);
  }
  if (drive != MapDrive::kExplore) return;
  std::printf("  explore: %.1f m driven, %zu pass(es) ended:", r.distance_m, r.pass_ends.size());
  for (std::size_t i = 0; i < r.pass_ends.size(); ++i) {
    std::printf(" %s at scan %d", r.pass_ends[i].c_str(), r.pass_end_scans[i]);
    if (i < r.pass_end_errors_m.size()) std::printf(" (trajectory error there %.3f m)", r.pass_end_errors_m[i]);
    std::printf(i + 1 < r.pass_ends.size() ? ";" : "");
  }
  std::printf("\n");
}

}  // namespace

int RunMapCommand(const std::vector<std::string>& args, const std::string& command_line) {
  EvalArgs parsed("map", MapOptions());
  parsed.Parse(args);
  if (parsed.help_requested()) {
    std::cout << "SLAM of a simulated corridor sweep, laser only or with doorplate text (paper Table II).\n"
              << parsed.Usage();
    return 0;
  }
  MapEvalOptions options;
  try {
    options.method = ParseMapMethod(parsed.String("method"));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("map: --method: ") + e.what());
  }
  // Each method starts from its own defaults: the laser-only filter exactly as on the real logs (no
  // back end); rbpf_text is TextSlamOptions' defaults (degeneracy-aware proposal, plates, back end).
  if (options.method == MapMethod::kRbpf) {
    options.slam.slam = RbpfSlamOptions{};
    options.slam.back_end.enabled = false;
  }
  options.seed = parsed.Unsigned("seed");
  options.slam.slam.num_particles = parsed.Integer("particles", 1);
  options.speed_mps = parsed.Number("speed-mps");
  if (!(options.speed_mps > 0)) throw UsageError("map: --speed-mps must be > 0");
  options.max_time_s = parsed.Number("max-seconds");
  if (!(options.max_time_s > 0)) throw UsageError("map: --max-seconds must be > 0");
  ApplySets(parsed.String("set"), &options.slam);
  options.progress_every_s = parsed.Number("progress-s");
  if (!(options.progress_every_s >= 0)) throw UsageError("map: --progress-s must be >= 0");
  const std::string drive = parsed.String("drive");
  const std::string json_path = parsed.String("json");
  if (!json_path.empty()) {
    const std::filesystem::path parent = std::filesystem::path(json_path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent)) {
      throw UsageError("map: --json: folder " + parent.string() + " does not exist");
    }
  }
  const std::string world_path = parsed.String("world");
  const World world = LoadWorldFile(world_path);
  try {
    options.drive = drive == "auto" ? (world.corridors.size() > 1 ? MapDrive::kExplore : MapDrive::kSweep)
                                    : ParseMapDrive(drive);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("map: --drive: ") + e.what() + " (or auto)");
  }
  const MapEvalResult result = RunMapEval(world, options);
  PrintSummary(result, options.method, options.seed, options.drive);
  PrintDrive(result, options.drive);
  const std::string out_dir = parsed.String("out-dir");
  if (!out_dir.empty()) {
    World built = world;
    BuildSurfaces(built);
    WriteMapOutputs(result, GroundTruthTextMap(built), out_dir);
  }
  if (!json_path.empty()) {
    std::ofstream out(json_path);
    if (!out) throw std::runtime_error("cannot write " + json_path);
    JsonWriter json(&out);
    WriteMapEvalJson(result, {world_path, command_line, options.method, options.seed,
                              options.slam.slam.num_particles, options.drive}, &json);
    out << "\n";
    if (!out) throw std::runtime_error("error writing " + json_path);
  }
  return 0;
}

}  // namespace doorplate_localization

// `doorplate_eval map`: SLAM of one corridor sweep, laser only (rbpf) or with doorplate text (rbpf_text),
// measured against the world (paper Table II).
#include <algorithm>
#include <cstdio>
#include <memory>

#include "cli_app.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/world_loader.h"
#include "doorplate_localization/slam/rbpf_slam_options.h"
#include "eval_args.h"
#include "eval_commands.h"
#include "map_eval.h"
#include "map_eval_json.h"
#include "map_output.h"
#include "output_guard.h"

namespace doorplate_localization {
namespace {

struct MapArgs {
  std::string world, method = "rbpf_text", drive = "auto", json, out_dir;
  std::uint64_t seed = 1;
  int particles = 30;
  double speed_mps = 0.4, max_seconds = 1800, progress_s = 60, map_update_interval_s = 0;
  std::vector<std::string> sets;
};

void AddMapOptions(CLI::App* map, MapArgs* a) {
  map->add_option("--world", a->world, "world file (worlds/*.yaml, docs/world-format.md)")->required();
  map->add_option("--method", a->method, "rbpf (laser only) or rbpf_text (with doorplate landmarks)")
      ->capture_default_str();
  map->add_option("--seed", a->seed, "experiment seed (simulator and filter seeds are derived from it)")
      ->capture_default_str()->transform(tools::Seed());
  map->add_option("--particles", a->particles, "number of particles")->capture_default_str()
      ->transform(tools::WholeNumber(1));
  map->add_option("--speed-mps", a->speed_mps, "cruise speed of the robot, m/s")->capture_default_str()
      ->check(tools::PositiveNumber());
  map->add_option("--max-seconds", a->max_seconds, "simulated seconds after which an unfinished drive ends the run")
      ->capture_default_str()->check(tools::PositiveNumber());
  map->add_option("--drive", a->drive, "sweep (one corridor: out and back), patrol (sweeps until --max-seconds), "
                  "explore (a whole floor: FloorExplorer's passes) or auto (explore when the world lists more than one "
                  "corridor)")->capture_default_str();
  map->add_option("--map-update-interval-s", a->map_update_interval_s, "also solve the back end and rebuild the maps "
                  "every this many simulated seconds, as the nodelet's ~map_update_interval (each solve's time in the "
                  "JSON); 0: once, at the end")->capture_default_str()->check(tools::Number(0.0));
  map->add_option("--set", a->sets, "SLAM options NAME=VALUE[,NAME=VALUE...] (names: rbpf_slam_options.h, "
                  "text.<field>; repeatable)")->delimiter(',')->allow_extra_args(false);
  map->add_option("--progress-s", a->progress_s, "a progress line on stderr every this many simulated seconds "
                  "(rewritten in place twice a second on a terminal; 0: none)")
      ->capture_default_str()->check(tools::Number(0.0));
  map->add_option("--json", a->json, "write the results as JSON to this file")->check(tools::InExistingFolder());
  map->add_option("--out-dir", a->out_dir, "write map.pgm/.yaml, text_map.yaml and map.png into this folder");
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
  std::printf("  trajectory error (processed scans): RMSE %.3f m, max %.3f m; out leg %.2f m (true %.2f) "
              "accuracy %.2f %%\n",
              r.trajectory_rmse_m, r.trajectory_max_error_m, r.out_leg.estimated_m, r.out_leg.true_m,
              100.0 * r.out_leg.accuracy);
  if (r.loop_closures > 0 || r.odometry_scale != 1.0) {
    std::printf("  back end: odometry scale %.4f (true / odometry distance), %d loop closures (%d dropped as "
                "inconsistent); final maps built in %.2f s CPU\n",
                r.odometry_scale, r.loop_closures, r.loop_closures_dropped, r.map_build_seconds);
    if (r.odometry_heading_drift_rad_per_m != 0.0) {  // estimated (back_end.graph.estimate_odometry_heading_drift)
      std::printf("  back end: odometry heading drift %.5f rad/m\n", r.odometry_heading_drift_rad_per_m);
    }
    if (r.nodes_on_mapped_ground > 0) {
      std::printf("  back end: %d nodes on mapped ground kept no scan (max_nodes_per_place)\n",
                  r.nodes_on_mapped_ground);
    }
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
  if (drive == MapDrive::kPatrol) std::printf("  patrol: %d sweep(s) done, %.1f m driven\n", r.sweeps_done, r.distance_m);
  if (r.solves.size() > 1) {  // periodic solves (--map-update-interval-s)
    const auto slowest = std::max_element(r.solves.begin(), r.solves.end(),
                                          [](const MapEvalSolve& a, const MapEvalSolve& b) { return a.wall_s < b.wall_s; });
    std::printf("  back end: %zu solves; slowest %.2f s wall at %d nodes (sim %.0f s); last %.2f s at %d nodes\n",
                r.solves.size(), slowest->wall_s, slowest->nodes, slowest->sim_time_s, r.solves.back().wall_s,
                r.solves.back().nodes);
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

int RunMap(const MapArgs& a, const std::string& command_line) {
  MapEvalOptions options;
  try {
    options.method = ParseMapMethod(a.method);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("map: --method: ") + e.what());
  }
  // Each method starts from its own defaults: the laser-only filter exactly as on the real logs (no
  // back end); rbpf_text is TextSlamOptions' defaults (degeneracy-aware proposal, plates, back end).
  if (options.method == MapMethod::kRbpf) {
    options.slam.slam = RbpfSlamOptions{};
    options.slam.back_end.enabled = false;
  }
  options.seed = a.seed;
  options.slam.slam.num_particles = a.particles;
  options.speed_mps = a.speed_mps;
  options.max_time_s = a.max_seconds;
  options.map_update_interval_s = a.map_update_interval_s;
  for (const std::string& set : a.sets) {
    if (set.empty()) continue;
    tools::ApplySetOption(set, [&](const std::string& name, double v) { SetTextSlamOption(name, v, &options.slam); });
  }
  options.progress_every_s = a.progress_s;
  const World world = LoadWorldFile(a.world);
  try {
    options.drive = a.drive == "auto" ? (world.corridors.size() > 1 ? MapDrive::kExplore : MapDrive::kSweep)
                                      : ParseMapDrive(a.drive);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("map: --drive: ") + e.what() + " (or auto)");
  }
  const auto in_out_dir = [&](const char* name) { return a.out_dir.empty() ? std::string() : a.out_dir + "/" + name; };
  tools::RefuseOverwritingInputs({{"--world", a.world}},  // issue 18: an output never replaces an input
                                 {{"--json", a.json}, {"--out-dir", in_out_dir("map.pgm")}, {"--out-dir", in_out_dir("map.yaml")},
                                  {"--out-dir", in_out_dir("text_map.yaml")}, {"--out-dir", in_out_dir("map.png")}});
  const MapEvalResult result = RunMapEval(world, options);
  PrintSummary(result, options.method, options.seed, options.drive);
  PrintDrive(result, options.drive);
  if (!a.out_dir.empty()) {
    World built = world;
    BuildSurfaces(built);
    WriteMapOutputs(result, GroundTruthTextMap(built), a.out_dir);
  }
  if (!a.json.empty()) {
    const MapEvalRunInfo info{a.world, command_line, options.method, options.seed, options.slam.slam.num_particles,
                              options.drive};
    WriteFileAtomically(a.json, ResultJsonText(MapEvalJson(result, info)));
  }
  return 0;
}

}  // namespace

EvalCommand AddMapCommand(CLI::App* eval, const std::string& command_line) {
  auto args = std::make_shared<MapArgs>();
  CLI::App* map =
      eval->add_subcommand("map", "SLAM of a simulated corridor sweep, laser only or with doorplate text (paper Table II).");
  AddMapOptions(map, args.get());
  return {map, [args, command_line] { return RunMap(*args, command_line); }};
}

}  // namespace doorplate_localization

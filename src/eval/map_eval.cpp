#include "map_eval.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <memory>
#include <stdexcept>

#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/simulator.h"
#include "doorplate_localization/slam/mapping_session.h"
#include "eval_args.h"
#include "progress_line.h"

namespace doorplate_localization {
namespace {

double ThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

long PeakRssKb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;  // Linux: kilobytes
}

// Records that a pass just ended (its reason and the processed scan it ended at).
void NotePassEnd(const FloorExplorer& explorer, MapEvalResult* result) {
  if (result->pass_ends.size() >= static_cast<std::size_t>(explorer.passes_ended())) return;  // noted
  result->pass_ends.push_back(PassEndName(explorer.last_pass_end()));
  result->pass_end_scans.push_back(std::max(0, result->scans_processed - 1));
}

// Records the solve the session just made (MappingSessionCounters::last_solve_wall_s: the solve and the
// maps' rebuild).
void NoteSolve(const MappingSession& session, double sim_time_s, MapEvalResult* result) {
  MapEvalSolve solve;
  solve.sim_time_s = sim_time_s;
  solve.wall_s = session.counters().last_solve_wall_s;
  if (const std::optional<SlamBackEndResult>& back_end = session.BackEndResult()) {
    solve.nodes = static_cast<int>(back_end->poses.size());
    solve.nodes_on_mapped_ground = back_end->nodes_on_mapped_ground;
    solve.loop_closures = back_end->loop_closures;
    solve.loop_alignments_computed = back_end->loop_alignments_computed;
    solve.loop_alignments_reused = back_end->loop_alignments_reused;
  }
  result->solves.push_back(solve);
}

}  // namespace

const char* MapMethodName(MapMethod method) { return method == MapMethod::kRbpf ? "rbpf" : "rbpf_text"; }

MapMethod ParseMapMethod(const std::string& name) {
  if (name == "rbpf") return MapMethod::kRbpf;
  if (name == "rbpf_text") return MapMethod::kRbpfText;
  throw std::invalid_argument("map method '" + name + "' must be rbpf or rbpf_text");
}

const char* MapDriveName(MapDrive drive) {
  switch (drive) {
    case MapDrive::kSweep: return "sweep";
    case MapDrive::kPatrol: return "patrol";
    case MapDrive::kExplore: return "explore";
  }
  return "?";
}

MapDrive ParseMapDrive(const std::string& name) {
  if (name == "sweep") return MapDrive::kSweep;
  if (name == "patrol") return MapDrive::kPatrol;
  if (name == "explore") return MapDrive::kExplore;
  throw std::invalid_argument("drive '" + name + "' must be sweep, patrol or explore");
}

MapEvalResult RunMapEval(const World& world, const MapEvalOptions& options) {
  if (!(options.speed_mps > 0) || !(options.max_time_s > 0)) {
    throw std::invalid_argument("MapEvalOptions: speed_mps and max_time_s must be > 0");
  }
  if (!(options.map_update_interval_s >= 0)) {
    throw std::invalid_argument("MapEvalOptions: map_update_interval_s must be >= 0");
  }
  const auto start = std::chrono::steady_clock::now();
  MapEvalResult result;
  result.world_name = world.name;
  SimulatorOptions sim_options;
  sim_options.seed = PassSeed(options.seed, 0);
  Simulator sim(world, sim_options);
  const World& sim_world = sim.world();
  // Every scan to the filter; the back end solved at the end, and with map_update_interval_s > 0 also every
  // that many simulated seconds, as the nodelet's ~map_update_interval (without its wall-clock share, so
  // deterministic).
  MappingSessionOptions session_options;
  session_options.slam = options.slam;
  session_options.map_update_interval_s = options.map_update_interval_s;
  session_options.slam.slam.seed = PassSeed(options.seed, 1);
  MappingSession session(session_options);
  CorridorSweepOptions sweep_options = options.sweep;
  sweep_options.follower.cruise_speed_mps = options.speed_mps;
  CorridorSweep sweep(sweep_options);
  FloorExplorerOptions explore_options = options.explore;
  explore_options.steering.cruise_speed_mps = options.speed_mps;
  FloorExplorer explorer(explore_options);
  const bool explore = options.drive == MapDrive::kExplore;

  const bool text = options.method == MapMethod::kRbpfText;
  std::unique_ptr<TextExtractor> extractor;
  double camera_yaw_rad = 0.0;
  if (text || explore) {
    TextExtractorOptions extractor_options = options.extractor;
    extractor_options.tracker.fx_px = sim.camera().intrinsics().fx_px;
    extractor_options.tracker.cx_px = sim.camera().intrinsics().cx_px;
    extractor = std::make_unique<TextExtractor>(extractor_options);
    double x, y, z, pitch;
    sim.camera().MountPose(&x, &y, &z, &camera_yaw_rad, &pitch);
  }
  const long long steps_per_scan =
      std::max(1LL, std::llround(1.0 / (sim_world.sensors.laser.rate_hz * sim_options.physics_step_s)));
  const double frame_period_s = 1.0 / sim_world.sensors.camera.rate_hz;
  int next_frame = 0;
  bool first = true;
  tools::ProgressLine progress({options.progress_every_s});
  for (long long step = 0; sim.time_s() < options.max_time_s; ++step) {
    if (progress.Due(sim.time_s())) {
      const std::string phase = !explore ? SweepPhaseName(sweep.phase())
                                : explorer.phase() == ExplorePhase::kFollow ? "pass " + std::to_string(explorer.pass())
                                                                             : ExplorePhaseName(explorer.phase());
      progress.Show("map: %.0f s simulated, %.1f m driven, %d plate reports, %d scans processed, %s",
                    sim.time_s(), sim.distance_travelled_m(), result.plate_reports, result.scans_processed,
                    phase.c_str());
    }
    if (step % steps_per_scan == 0) {
      const LaserScan scan = sim.Scan();
      if (first) {
        result.world_from_map = sim.true_pose().Compose(sim.odom_pose().Inverse());
        first = false;
      }
      const double t0 = ThreadCpuSeconds();
      const MappingUpdate update = session.AddScan(sim.time_s(), sim.odom_pose(), scan);
      for (const MappingPlateOutcome& o : update.plates) result.plate_reports_used += o.result.used();  // held ones
      if (update.solved) NoteSolve(session, sim.time_s(), &result);
      if (update.scan_processed) {
        ++result.scans_processed;
        result.true_trajectory.push_back(result.world_from_map.Inverse().Compose(sim.true_pose()));
      }
      result.slam_seconds += ThreadCpuSeconds() - t0;
      ++result.scans;
      VelocityCommand cmd;
      if (explore) {
        cmd = explorer.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, sim.odom_pose(), sim.time_s());
        NotePassEnd(explorer, &result);
        if (explorer.phase() == ExplorePhase::kDone) break;
      } else {
        cmd = sweep.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, sim.odom_pose(), sim.time_s());
        if (sweep.phase() == SweepPhase::kDone) {
          ++result.sweeps_done;
          if (options.drive != MapDrive::kPatrol) break;
          sweep.Reset();  // patrol: out and back again until max_time_s, as the wall follower's ~mode patrol
        }
      }
      sim.SetCommand(cmd.linear_mps, cmd.angular_rps);
    }
    if (extractor && sim.time_s() + 1e-9 >= next_frame * frame_period_s) {
      ++next_frame;
      for (const PlateReport& report : extractor->Process(sim.CameraImage(), sim.time_s())) {
        if (explore) {
          explorer.OnPlateRead(report.text, report.stamp_s);
          NotePassEnd(explorer, &result);
        }
        if (!text) {
          ++result.plate_reports;  // read (the explorer used it), not given to the laser-only SLAM
          continue;
        }
        const PlateReading sighting =
            PlateReadingFromCamera(report.text, report.confidence, CameraAxis{camera_yaw_rad, 1.0}, report.bearing_rad);
        // Stamped now, with the odometry now (the report's frame may be older: Table II's convention).
        const double t0 = ThreadCpuSeconds();
        const MappingUpdate update = session.AddPlates(sim.time_s(), sim.odom_pose(), {sighting});
        result.slam_seconds += ThreadCpuSeconds() - t0;
        ++result.plate_reports;
        for (const MappingPlateOutcome& o : update.plates) result.plate_reports_used += o.result.used();
      }
    }
    sim.Step();
  }
  progress.Finish();
  result.sweep_done = explore                                ? explorer.phase() == ExplorePhase::kDone
                      : options.drive == MapDrive::kPatrol ? result.sweeps_done > 0
                                                           : sweep.phase() == SweepPhase::kDone;
  result.distance_m = sim.distance_travelled_m();
  result.sim_seconds = sim.time_s();
  for (const MappingPlateOutcome& o : session.Flush().plates) result.plate_reports_used += o.result.used();  // held
  result.degenerate_scans = session.slam().slam().stats().degenerate_scans;
  result.plate_ranges_from_wall = static_cast<int>(session.counters().plate_ranges_from_wall);

  // The final map: with the back end on, its solve and the re-rendering happen here, once per run.
  const double map_t0 = ThreadCpuSeconds();
  session.Solve();
  result.map_build_seconds = ThreadCpuSeconds() - map_t0;
  NoteSolve(session, sim.time_s(), &result);
  result.grid = *session.Map();
  result.text_map = session.GetTextMap();
  result.trajectory = session.Trajectory();
  double sum2 = 0.0;
  const std::size_t n = std::min(result.trajectory.size(), result.true_trajectory.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double e = Norm(result.trajectory[i].Position() - result.true_trajectory[i].Position());
    sum2 += e * e;
    result.trajectory_max_error_m = std::max(result.trajectory_max_error_m, e);
  }
  result.trajectory_rmse_m = n > 0 ? std::sqrt(sum2 / n) : 0.0;
  result.out_leg = MeasureOutLeg(result.trajectory, result.true_trajectory);
  for (const int scan : result.pass_end_scans) {
    if (scan >= 0 && static_cast<std::size_t>(scan) < n) {
      result.pass_end_errors_m.push_back(
          Norm(result.trajectory[scan].Position() - result.true_trajectory[scan].Position()));
    }
  }
  if (const std::optional<SlamBackEndResult>& back_end = session.BackEndResult()) {
    result.odometry_scale = back_end->odometry_scale;
    result.odometry_heading_drift_rad_per_m = back_end->odometry_heading_drift_rad_per_m;
    result.loop_closures = back_end->loop_closures;
    result.loop_closures_dropped = back_end->loop_closures_dropped;
    result.nodes_on_mapped_ground = back_end->nodes_on_mapped_ground;
  }
  // The estimate at the last processed scan (back end, or best particle) vs the truth now: the odometry
  // since then added.
  const Pose2D estimate_now =
      result.trajectory.back().Compose(session.LastProcessedOdometry().Between(sim.odom_pose()));
  result.final_position_error_m =
      Norm(result.world_from_map.Compose(estimate_now).Position() - sim.true_pose().Position());
  std::vector<Segment> walls;
  for (const Wall& w : sim_world.walls) walls.push_back(w.segment);
  result.truth = MeasureSegments(walls);
  result.estimate = MeasureCorridor(result.grid);
  result.length_accuracy = ExtentAccuracy(result.estimate.length_m, result.truth.length_m);
  result.width_accuracy = ExtentAccuracy(result.estimate.width_m, result.truth.width_m);
  const TextMap true_plates = GroundTruthTextMap(sim_world);
  result.plates = ScorePlates(result.text_map, true_plates, result.world_from_map);
  result.plate_fit = AlignPlates(result.text_map, true_plates);
  if (result.plate_fit.ok) result.plates_fitted = ScorePlates(result.text_map, true_plates, result.plate_fit.world_from_map);
  result.corridors = CompareCorridorsWithWorld(result.grid, result.world_from_map, sim_world);
  result.peak_rss_kb = PeakRssKb();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace doorplate_localization

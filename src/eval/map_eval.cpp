#include "map_eval.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <memory>
#include <stdexcept>

#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/simulator.h"
#include "eval_args.h"

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

RangeScan ToRangeScan(const SimulatedScan& scan, const LaserOptions& laser) {
  RangeScan out;
  out.angle_min_rad = scan.angle_min_rad;
  out.angle_increment_rad = scan.angle_increment_rad;
  out.min_range_m = scan.min_range_m;
  out.ranges_m = scan.ranges_m;
  out.laser_pose = {laser.mount_x_m, laser.mount_y_m, laser.mount_yaw_rad};
  return out;
}

}  // namespace

const char* MapMethodName(MapMethod method) { return method == MapMethod::kRbpf ? "rbpf" : "rbpf_text"; }

MapMethod ParseMapMethod(const std::string& name) {
  if (name == "rbpf") return MapMethod::kRbpf;
  if (name == "rbpf_text") return MapMethod::kRbpfText;
  throw std::invalid_argument("map method '" + name + "' must be rbpf or rbpf_text");
}

MapEvalResult RunMapEval(const World& world, const MapEvalOptions& options) {
  if (!(options.speed_mps > 0) || !(options.max_time_s > 0)) {
    throw std::invalid_argument("MapEvalOptions: speed_mps and max_time_s must be > 0");
  }
  const auto start = std::chrono::steady_clock::now();
  MapEvalResult result;
  result.world_name = world.name;
  SimulatorOptions sim_options;
  sim_options.seed = PassSeed(options.seed, 0);
  Simulator sim(world, sim_options);
  const World& sim_world = sim.world();
  TextSlamOptions slam_options = options.slam;
  slam_options.slam.seed = PassSeed(options.seed, 1);
  TextSlam slam(slam_options);
  CorridorSweepOptions sweep_options = options.sweep;
  sweep_options.follower.cruise_speed_mps = options.speed_mps;
  CorridorSweep sweep(sweep_options);

  const bool text = options.method == MapMethod::kRbpfText;
  std::unique_ptr<TextExtractor> extractor;
  double camera_yaw_rad = 0.0;
  if (text) {
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
  for (long long step = 0; sim.time_s() < options.max_time_s; ++step) {
    if (step % steps_per_scan == 0) {
      const SimulatedScan scan = sim.Scan();
      if (first) {
        result.world_from_map = sim.true_pose().Compose(sim.odom_pose().Inverse());
        first = false;
      }
      const double t0 = ThreadCpuSeconds();
      if (slam.AddScan(ToRangeScan(scan, sim_world.sensors.laser), sim.odom_pose(), result.scans)) {
        ++result.scans_processed;
        result.true_trajectory.push_back(result.world_from_map.Inverse().Compose(sim.true_pose()));
      }
      result.slam_seconds += ThreadCpuSeconds() - t0;
      ++result.scans;
      const VelocityCommand cmd = sweep.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, sim.odom_pose());
      if (sweep.phase() == SweepPhase::kDone) break;
      sim.SetCommand(cmd.linear_mps, cmd.angular_rps);
    }
    if (text && sim.time_s() + 1e-9 >= next_frame * frame_period_s) {
      ++next_frame;
      for (const PlateReport& report : extractor->Process(sim.CameraImage(), sim.time_s())) {
        PlateSighting sighting;
        sighting.text = report.text;
        sighting.confidence = report.confidence;
        sighting.bearing_rad = NormalizeAngle(camera_yaw_rad + report.bearing_rad);
        const double t0 = ThreadCpuSeconds();
        const TextSlamPlateResult used = slam.AddPlate(sighting, sim.odom_pose());
        result.slam_seconds += ThreadCpuSeconds() - t0;
        ++result.plate_reports;
        if (used.used()) ++result.plate_reports_used;
      }
    }
    sim.Step();
  }
  result.sweep_done = sweep.phase() == SweepPhase::kDone;
  result.sim_seconds = sim.time_s();
  result.degenerate_scans = slam.slam().stats().degenerate_scans;

  // The final map: with the back end on, its solve and the re-rendering happen here, once per run.
  const double map_t0 = ThreadCpuSeconds();
  result.grid = slam.BuildOccupancyGrid();
  result.text_map = slam.BuildTextMap();
  result.map_build_seconds = ThreadCpuSeconds() - map_t0;
  result.trajectory = slam.Trajectory();
  double sum2 = 0.0;
  const std::size_t n = std::min(result.trajectory.size(), result.true_trajectory.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double e = Norm(result.trajectory[i].Position() - result.true_trajectory[i].Position());
    sum2 += e * e;
    result.trajectory_max_error_m = std::max(result.trajectory_max_error_m, e);
  }
  result.trajectory_rmse_m = n > 0 ? std::sqrt(sum2 / n) : 0.0;
  if (const std::optional<SlamBackEndResult> back_end = slam.BackEndResult()) {
    result.odometry_scale = back_end->odometry_scale;
    result.loop_closures = back_end->loop_closures;
  }
  // The estimate at the last processed scan (back end, or best particle) vs the truth now: the odometry
  // since then added.
  const Pose2D estimate_now =
      result.trajectory.back().Compose(slam.slam().LastProcessedOdometry().Between(sim.odom_pose()));
  result.final_position_error_m =
      Norm(result.world_from_map.Compose(estimate_now).Position() - sim.true_pose().Position());
  std::vector<Segment> walls;
  for (const Wall& w : sim_world.walls) walls.push_back(w.segment);
  result.truth = MeasureSegments(walls);
  result.estimate = MeasureCorridor(result.grid);
  result.length_accuracy = ExtentAccuracy(result.estimate.length_m, result.truth.length_m);
  result.width_accuracy = ExtentAccuracy(result.estimate.width_m, result.truth.width_m);
  result.plates = ScorePlates(result.text_map, GroundTruthTextMap(sim_world), result.world_from_map);
  result.peak_rss_kb = PeakRssKb();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace doorplate_localization

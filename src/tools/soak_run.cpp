#include "soak_run.h"

#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>

#include "doorplate_localization/behaviour/corridor_sweep.h"
#include "doorplate_localization/mcl/localization_grid.h"
#include "doorplate_localization/mcl/text_amcl_session.h"
#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/simulator.h"
#include "doorplate_localization/text/text_extractor.h"
#include "localize_sensors.h"

namespace doorplate_localization::tools {
namespace {

using Clock = std::chrono::steady_clock;
constexpr size_t kKeptErrorMessages = 10;

void Validate(const SoakOptions& o) {
  const auto check = [](bool ok, const char* field) {
    if (!ok) throw std::invalid_argument(std::string("SoakOptions.") + field + ": out of range");
  };
  check(o.duration_s > 0.0, "duration_s");
  check(o.window_s > 0.0 && o.window_s <= o.duration_s, "window_s");
  check(o.camera_rate_hz >= 0.0, "camera_rate_hz");
  check(o.speed_mps > 0.0, "speed_mps");
  check(o.max_particles >= 100, "max_particles");
  check(o.localizer || o.faults.schedule.empty(), "faults.schedule (needs the localizer)");
}

class Soak {
 public:
  Soak(const World& world, const SoakOptions& options)
      : options_(options), sim_(world, SimOptions(options)), faults_(options.faults), kidnap_rng_(options.seed ^ 0x6b1dULL) {
    CorridorSweepOptions sweep;
    sweep.follower.cruise_speed_mps = options.speed_mps;
    sweep_ = std::make_unique<CorridorSweep>(sweep);
    TextExtractorOptions extractor;
    extractor.tracker.fx_px = sim_.camera().intrinsics().fx_px;
    extractor.tracker.cx_px = sim_.camera().intrinsics().cx_px;
    extractor_ = std::make_unique<TextExtractor>(extractor);
    double x = 0, y = 0, z = 0, pitch = 0;
    sim_.camera().MountPose(&x, &y, &z, &camera_yaw_rad_, &pitch);
    if (options.localizer) {
      const World& w = sim_.world();
      grid_ = RasterizeWorld(w, 0.05, w.sensors.laser.mount_height_m);
      text_map_ = std::make_shared<const TextMap>(GroundTruthTextMap(w));
      session_options_.setup.filter.random_seed = options.seed;
      session_options_.setup.filter.max_particles = options.max_particles;
      session_options_.initial_pose = sim_.true_pose();
      session_options_.initial_covariance = Eigen::Vector3d(0.1 * 0.1, 0.1 * 0.1, 0.05 * 0.05).asDiagonal();
      session_ = std::make_unique<TextAmclSession>(session_options_, grid_, text_map_);
      if (faults_.enabled()) free_space_ = std::make_unique<LocalizationGrid>(grid_);
    }
  }

  SoakResult Run() {
    SoakResult result;
    result.start_rss_mb = ResidentMegabytes();
    const double dt = SimOptions(options_).physics_step_s;
    const long long steps_per_scan = std::max(1LL, std::llround(1.0 / (sim_.world().sensors.laser.rate_hz * dt)));
    const double camera_hz = options_.camera_rate_hz > 0.0 ? options_.camera_rate_hz : sim_.world().sensors.camera.rate_hz;
    long long next_frame = 0;
    double window_end_s = options_.window_s;
    Clock::time_point window_start = Clock::now();
    double window_start_cpu_s = ProcessCpuSeconds();
    for (long long step = 0; sim_.time_s() < options_.duration_s - 1e-9 && !(faults_.enabled() && faults_.done());
         ++step) {
      if (step % steps_per_scan == 0) Guard([&] { ScanStep(); });
      if (sim_.time_s() + 1e-9 >= static_cast<double>(next_frame) / camera_hz) {
        ++next_frame;
        Guard([&] { CameraStep(); });
      }
      sim_.Step();
      if (sim_.time_s() + 1e-9 >= window_end_s) {
        window_.end_sim_s = sim_.time_s();
        window_.wall_s = std::chrono::duration<double>(Clock::now() - window_start).count();
        window_.cpu_s = ProcessCpuSeconds() - window_start_cpu_s;
        window_.rss_mb = ResidentMegabytes();
        if (error_samples_ > 0) window_.mean_error_m /= error_samples_;
        result.errors += window_.errors;
        result.windows.push_back(window_);
        window_ = SoakWindow();
        error_samples_ = 0;
        window_end_s += options_.window_s;
        window_start = Clock::now();
        window_start_cpu_s = ProcessCpuSeconds();
      }
    }
    if (window_.scans > 0) {  // the run ended inside a window
      window_.end_sim_s = sim_.time_s();
      window_.wall_s = std::chrono::duration<double>(Clock::now() - window_start).count();
      window_.cpu_s = ProcessCpuSeconds() - window_start_cpu_s;
      window_.rss_mb = ResidentMegabytes();
      if (error_samples_ > 0) window_.mean_error_m /= error_samples_;
      result.errors += window_.errors;
      result.windows.push_back(window_);
    }
    result.distance_m = sim_.distance_travelled_m();
    result.faults = faults_.reports();
    result.first_errors = first_errors_;
    return result;
  }

 private:
  static SimulatorOptions SimOptions(const SoakOptions& o) {
    SimulatorOptions s;
    s.seed = o.seed;
    return s;
  }

  // Runs one component call; an exception is counted and logged, and the run goes on (as a node would).
  template <typename F>
  void Guard(F&& f) {
    try {
      f();
    } catch (const std::exception& e) {
      ++window_.errors;
      std::ostringstream message;
      message << "t=" << sim_.time_s() << " s: " << e.what();
      std::cerr << "soak: error at " << message.str() << "\n";
      if (first_errors_.size() < kKeptErrorMessages) first_errors_.push_back(message.str());
    }
  }

  void ScanStep() {
    if (const auto kind = faults_.Begin(sim_.time_s(), sim_.distance_travelled_m())) {
      if (*kind == FaultKind::kLocalizerRestart) RestartLocalizer();
      if (*kind == FaultKind::kKidnap) Kidnap();
    }
    ++window_.scans;
    if (faults_.enabled() && (route_.empty() || Norm(route_.back() - sim_.true_pose().Position()) >= 0.25)) {
      route_.push_back(sim_.true_pose().Position());
    }
    scan_ = sim_.Scan();
    VelocityCommand cmd = sweep_->Step(scan_.ranges_m, scan_.angle_min_rad, scan_.angle_increment_rad, sim_.odom_pose(),
                                      sim_.time_s());
    if (sweep_->phase() == SweepPhase::kDone) {  // back and forth: a new sweep as soon as one ends
      ++window_.sweeps_completed;
      sweep_->Reset();
      cmd = sweep_->Step(scan_.ranges_m, scan_.angle_min_rad, scan_.angle_increment_rad, sim_.odom_pose(),
                                      sim_.time_s());
    }
    sim_.SetCommand(cmd.linear_mps, cmd.angular_rps);
    if (!session_) return;
    const bool laser_off = faults_.laser_off(sim_.time_s());  // the localizer gets no scan
    if (!laser_off && session_->AddScan(sim_.time_s(), sim_.odom_pose(), scan_).laser_used) ++window_.filter_updates;
    // The estimate carried to now by odometry (map -> odom ∘ odometry), against the truth.
    const Pose2D estimate = session_->PoseAtOdometry(sim_.odom_pose());
    const double error = std::hypot(estimate.x_m - sim_.true_pose().x_m, estimate.y_m - sim_.true_pose().y_m);
    if (!std::isfinite(error)) throw std::runtime_error("localizer estimate is not finite");
    window_.mean_error_m += error;
    window_.max_error_m = std::max(window_.max_error_m, error);
    ++error_samples_;
    const bool converged = session_->Status().state == LocalizationState::kConverged;
    if (converged) ++window_.converged_scans;
    faults_.Observe(sim_.time_s(), sim_.distance_travelled_m(), error,
                    NormalizeAngle(estimate.theta_rad - sim_.true_pose().theta_rad), converged, !laser_off);
  }

  // A restarted nodelet: a new session, global localization, no odometry reference.
  void RestartLocalizer() {
    ++restarts_;
    TextAmclSessionOptions o = session_options_;
    o.setup.filter.random_seed = options_.seed + static_cast<std::uint64_t>(restarts_);
    o.start_with_global_localization = true;
    session_ = std::make_unique<TextAmclSession>(o, grid_, text_map_);
  }

  // Teleports the robot to a random free pose at least kidnap_min_jump_m away and within
  // kidnap_max_off_route_m of the route driven so far, heading along a map axis (the corridors') with
  // kidnap_clearance_m around it and 1.5 m free ahead; a new sweep starts.
  void Kidnap() {
    const FaultOptions& o = faults_.options();
    const Pose2D from = sim_.true_pose();
    for (int attempt = 0; attempt < 100000; ++attempt) {
      Pose2D to = free_space_->SampleFreePose(kidnap_rng_);
      to.theta_rad = 0.5 * M_PI * static_cast<double>(kidnap_rng_() % 4) - M_PI / 2.0;
      const double jump_m = std::hypot(to.x_m - from.x_m, to.y_m - from.y_m);
      if (jump_m < o.kidnap_min_jump_m || !OnRoute(to, o.kidnap_max_off_route_m) || !Clear(to, o.kidnap_clearance_m)) {
        continue;
      }
      sim_.Teleport(to);
      sweep_->Reset();
      faults_.SetKidnap(from, to);
      return;
    }
    throw std::runtime_error("kidnap: no free pose with the clearance and jump asked for");
  }

  bool OnRoute(const Pose2D& pose, double max_off_m) const {
    for (const Vec2& p : route_) {
      if (Norm(p - pose.Position()) <= max_off_m) return true;
    }
    return false;
  }

  bool Clear(const Pose2D& pose, double clearance_m) const {
    for (int i = 0; i < 16; ++i) {
      const double a = 2.0 * M_PI * i / 16.0;
      if (!free_space_->IsFree(pose.TransformPoint({clearance_m * std::cos(a), clearance_m * std::sin(a)}))) return false;
    }
    for (double ahead_m = 0.1; ahead_m <= 1.5 + clearance_m; ahead_m += 0.1) {
      if (!free_space_->IsFree(pose.TransformPoint({ahead_m, 0.0}))) return false;
    }
    return true;
  }

  void CameraStep() {
    if (faults_.camera_off(sim_.time_s())) return;  // no image, so no reading
    ++window_.frames;
    const std::vector<PlateReport> reports = extractor_->Process(sim_.CameraImage(), sim_.time_s());
    window_.plate_reports += static_cast<long long>(reports.size());
    if (!session_ || reports.empty()) return;
    // The session weighs them at this moment's odometry, with the range from the scan it got nearest in
    // time (none during a laser outage longer than its scan age limit).
    std::vector<PlateReading> readings;
    for (const PlateReport& report : reports) readings.push_back(ToPlateReading(report, camera_yaw_rad_));
    session_->AddOdometry(sim_.time_s(), sim_.odom_pose());
    session_->AddPlates(sim_.time_s(), readings);
  }

  const SoakOptions options_;
  Simulator sim_;
  std::unique_ptr<CorridorSweep> sweep_;
  std::unique_ptr<TextExtractor> extractor_;
  std::unique_ptr<TextAmclSession> session_;
  TextAmclSessionOptions session_options_;
  OccupancyGrid grid_;
  std::shared_ptr<const TextMap> text_map_;
  FaultSchedule faults_;
  std::unique_ptr<LocalizationGrid> free_space_;  // where a kidnap may put the robot
  std::mt19937_64 kidnap_rng_;
  int restarts_ = 0;
  std::vector<Vec2> route_;  // true positions driven, every 0.25 m (where a kidnap may put the robot)
  double camera_yaw_rad_ = 0.0;
  LaserScan scan_;  // the latest simulated scan (the sweep drives on it)
  SoakWindow window_;
  long long error_samples_ = 0;
  std::vector<std::string> first_errors_;
};

}  // namespace

SoakResult RunSoak(const World& world, const SoakOptions& options) {
  Validate(options);
  Soak soak(world, options);
  return soak.Run();
}

double ProcessCpuSeconds() {
  timespec t{};
  if (::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t) != 0) return 0.0;
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double ResidentMegabytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) {
      std::istringstream in(line.substr(6));
      double kb = 0.0;
      in >> kb;
      return kb / 1024.0;
    }
  }
  return 0.0;
}

}  // namespace doorplate_localization::tools

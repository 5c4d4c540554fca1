#include "localize_eval.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "doorplate_localization/mcl/building_session.h"
#include "doorplate_localization/sim/simulator.h"
#include "eval_args.h"
#include "localize_sensors.h"
#include "progress_line.h"
#include "stats.h"

namespace doorplate_localization {
namespace {

using Clock = std::chrono::steady_clock;

void Validate(const LocalizeEvalOptions& o, bool has_text_map) {
  auto check = [](bool ok, const char* field) {
    if (!ok) throw std::invalid_argument(std::string("LocalizeEvalOptions.") + field + ": out of range");
  };
  check(o.trials >= 1, "trials");
  check(o.max_travel_m > 0.0, "max_travel_m");
  check(o.speed_mps > 0.0, "speed_mps");
  check(o.success_distance_m > 0.0, "success_distance_m");
  check(o.success_angle_rad > 0.0, "success_angle_rad");
  check(o.camera_rate_hz >= 0.0, "camera_rate_hz");
  if (o.method == LocalizeMethod::kTextAmcl && !has_text_map) {
    throw std::invalid_argument("LocalizeEvalOptions.method: text_amcl needs a text map");
  }
}

// One trial's simulation: the robot, its search behaviour, the filter and (text_amcl) the reader.
class TrialRun {
 public:
  // `progress` gets a line when due; `run_sim_s`: simulated seconds of the run's earlier trials.
  TrialRun(const LocalizeBuilding& building, const std::vector<StartPoseSampler>& poses,
           const LocalizeEvalOptions& options, int index, tools::ProgressLine* progress, double run_sim_s)
      : building_(building), options_(options), poses_(poses), progress_(progress), run_sim_s_(run_sim_s),
        seed_(PassSeed(options.seed, index)), rng_(seed_),
        floor_(DrawFloor()), sim_(building.worlds[static_cast<size_t>(floor_)], SimOptions(seed_)),
        sweep_(SweepOptions(options)), contour_(ContourOptions(options)) {
    trial_.index = index;
    trial_.seed = seed_;
    trial_.start_pose = poses_[static_cast<size_t>(floor_)].Sample(rng_);
    trial_.start_floor = FloorId(floor_);
    sim_.Teleport(trial_.start_pose);
    BuildingSessionOptions session;
    session.session.setup = options.filter;
    session.session.setup.filter.random_seed = seed_;
    session.session.setup.use_text = options.method == LocalizeMethod::kTextAmcl;
    session.session.start_with_global_localization = true;
    session_ = std::make_unique<BuildingSession>(session, SessionMaps(building.maps, session.session.setup.use_text));
    if (session.session.setup.use_text) {
      TextExtractorOptions extractor = options.extractor;
      extractor.tracker.fx_px = sim_.camera().intrinsics().fx_px;
      extractor.tracker.cx_px = sim_.camera().intrinsics().cx_px;
      // The building's identifier format (the first floor's; a building has one) and its rooms.
      extractor.validator.pattern = building.maps->floors.front().text_map->room_pattern;
      if (options.known_rooms) {
        for (const FloorMaps& floor : building.maps->floors) {
          const std::vector<std::string> texts = floor.text_map->Texts();
          extractor.validator.known_rooms.insert(extractor.validator.known_rooms.end(), texts.begin(), texts.end());
        }
      }
      extractor_ = std::make_unique<TextExtractor>(extractor);
      double x = 0, y = 0, z = 0, pitch = 0;
      sim_.camera().MountPose(&x, &y, &z, &camera_yaw_rad_, &pitch);
    }
  }

  LocalizeTrial Run() {
    const Clock::time_point start = Clock::now();
    const SimulatorOptions sim_options = SimOptions(seed_);
    const long long steps_per_scan =
        std::max(1LL, std::llround(1.0 / (sim_.world().sensors.laser.rate_hz * sim_options.physics_step_s)));
    const double frame_period_s = 1.0 / sim_.world().sensors.camera.rate_hz;
    const double search_time_limit_s = 3.0 * options_.max_travel_m / options_.speed_mps + 120.0;
    long long next_frame = 0;
    bool done = false;
    for (long long step = 0; !done; ++step) {
      if (step % steps_per_scan == 0) done = ScanStep();
      if (!done && extractor_ && sim_.time_s() + 1e-9 >= static_cast<double>(next_frame) * frame_period_s) {
        ++next_frame;
        done = CameraStep();
      }
      if (done) break;
      sim_.Step();
      if (progress_->Due(run_sim_s_ + sim_.time_s())) ShowProgress();
      const bool too_far = sim_.distance_travelled_m() - search_start_travel_m_ > options_.max_travel_m;
      const bool too_long = sim_.time_s() - search_start_time_s_ > search_time_limit_s;
      if (too_far || too_long) {
        // The search failed: record where the filter believes the robot is anyway.
        (trial_.kidnapped ? trial_.recovery : trial_.fix) = Fix();
        done = true;
      }
    }
    trial_.laser_updates = session_->Status().laser_updates;
    trial_.sim_seconds = sim_.time_s();
    trial_.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return trial_;
  }

 private:
  // A floor uniformly at random; nothing drawn in a one-floor building (its trials stay draw for draw).
  int DrawFloor() {
    const int floors = static_cast<int>(building_.worlds.size());
    if (floors == 1) return 0;
    return std::uniform_int_distribution<int>(0, floors - 1)(rng_);
  }
  const std::string& FloorId(int floor) const { return building_.maps->floors[static_cast<size_t>(floor)].id; }

  static SimulatorOptions SimOptions(std::uint64_t seed) {
    SimulatorOptions o;
    o.seed = seed;
    return o;
  }
  static CorridorSweepOptions SweepOptions(const LocalizeEvalOptions& options) {
    CorridorSweepOptions o = options.sweep;
    o.follower.cruise_speed_mps = options.speed_mps;
    return o;
  }
  static ContourSteeringOptions ContourOptions(const LocalizeEvalOptions& options) {
    ContourSteeringOptions o = options.contour;
    o.cruise_speed_mps = options.speed_mps;
    return o;
  }

  // Control and the session's scan input at the laser's rate. Returns true when the trial is over.
  bool ScanStep() {
    last_scan_ = sim_.Scan();
    const VelocityCommand cmd = Drive();
    sim_.SetCommand(cmd.linear_mps, cmd.angular_rps);
    session_->AddScan(sim_.time_s(), sim_.odom_pose(), last_scan_);
    return CheckState();
  }

  // The search strategy: contour following (it never ends), or corridor sweeps, a new one as soon as one
  // ends.
  VelocityCommand Drive() {
    if (options_.drive == LocalizeDrive::kContour) {
      return contour_.Step(last_scan_.ranges_m, last_scan_.angle_min_rad, last_scan_.angle_increment_rad).command;
    }
    VelocityCommand cmd = sweep_.Step(last_scan_.ranges_m, last_scan_.angle_min_rad, last_scan_.angle_increment_rad,
                                      sim_.odom_pose(), sim_.time_s());
    if (sweep_.phase() == SweepPhase::kDone) {
      sweep_.Reset();
      cmd = sweep_.Step(last_scan_.ranges_m, last_scan_.angle_min_rad, last_scan_.angle_increment_rad,
                        sim_.odom_pose(), sim_.time_s());
    }
    return cmd;
  }

  // One camera image through the reader; its reports go to the session with the odometry of this moment
  // (the session measures their range and weighs them there).
  bool CameraStep() {
    const CameraFeed feed = FeedCameraFrame(sim_, *extractor_, camera_yaw_rad_, *session_);
    if (feed.reports == 0) return false;
    trial_.plate_reports += feed.reports;
    trial_.plate_updates += feed.plate_updates;
    return CheckState();
  }

  void ShowProgress() {
    const TextAmclStatus status = session_->Status();
    progress_->Show("localize: trial %d/%d%s, %.0f s simulated, %.1f m driven, particle spread %.2f m (%d particles), "
                    "%d/%d plates used, %s", trial_.index + 1, options_.trials, trial_.kidnapped ? " (kidnapped)" : "",
                    run_sim_s_ + sim_.time_s(), sim_.distance_travelled_m() - search_start_travel_m_,
                    ParticleSpreadM(session_->session().particles()), status.particle_count, trial_.plate_updates,
                    trial_.plate_reports, ToString(status.state));
  }

  LocalizeFix Fix() const {
    LocalizeFix fix;
    fix.travel_m = sim_.distance_travelled_m() - search_start_travel_m_;
    fix.sim_time_s = sim_.time_s() - search_start_time_s_;
    fix.truth = sim_.true_pose();
    fix.estimate = session_->PoseAtOdometry(sim_.odom_pose());
    fix.floor = session_->floor_id();
    fix.true_floor = FloorId(floor_);
    fix.error_m = std::hypot(fix.estimate.x_m - fix.truth.x_m, fix.estimate.y_m - fix.truth.y_m);
    const double angle = std::fabs(NormalizeAngle(fix.estimate.theta_rad - fix.truth.theta_rad));
    fix.error_deg = angle * 180.0 / M_PI;
    fix.within_tolerance = fix.floor == fix.true_floor && fix.error_m <= options_.success_distance_m &&
                           angle <= options_.success_angle_rad;
    return fix;
  }

  // Convergence (and, after a kidnap, loss and recovery) checks. Returns true when the trial is over.
  bool CheckState() {
    if (building_.worlds.size() > 1 && session_->floor_certain() && session_->floor() == floor_) {
      double& floor_travel = trial_.kidnapped ? trial_.kidnap_floor_travel_m : trial_.floor_travel_m;
      if (floor_travel < 0.0) floor_travel = sim_.distance_travelled_m() - search_start_travel_m_;
    }
    const LocalizationState state = session_->Status().state;
    if (!trial_.kidnapped) {
      if (state != LocalizationState::kConverged) return false;
      trial_.converged = true;
      trial_.fix = Fix();
      if (!options_.kidnap || !trial_.fix.within_tolerance) return true;
      Kidnap();
      return false;
    }
    if (state == LocalizationState::kLost && !trial_.lost_detected) {
      trial_.lost_detected = true;
      trial_.lost_detected_travel_m = sim_.distance_travelled_m() - search_start_travel_m_;
      trial_.lost_reason = ToString(session_->Status().lost_reason);
    }
    if (state != LocalizationState::kConverged) return false;
    const LocalizeFix fix = Fix();
    if (!fix.within_tolerance) return false;
    trial_.recovered = true;
    trial_.recovery = fix;
    return true;
  }

  void Kidnap() {
    trial_.kidnapped = true;
    const int floor = DrawFloor();
    if (floor == floor_) {
      trial_.kidnap_pose = poses_[static_cast<size_t>(floor)].SampleAwayFrom(sim_.true_pose(), rng_);
      sim_.Teleport(trial_.kidnap_pose);
    } else {  // a lift ride
      floor_ = floor;
      trial_.kidnap_pose = poses_[static_cast<size_t>(floor)].Sample(rng_);
      sim_.ChangeWorld(building_.worlds[static_cast<size_t>(floor)], trial_.kidnap_pose);
    }
    trial_.kidnap_floor = FloorId(floor_);
    sweep_.Reset();
    if (extractor_) extractor_->Reset();
    search_start_travel_m_ = sim_.distance_travelled_m();
    search_start_time_s_ = sim_.time_s();
  }

  const LocalizeBuilding& building_;
  const LocalizeEvalOptions& options_;
  const std::vector<StartPoseSampler>& poses_;
  tools::ProgressLine* const progress_;
  const double run_sim_s_;
  const std::uint64_t seed_;
  std::mt19937_64 rng_;
  int floor_;  // the floor the robot is on (index into building_.worlds)
  Simulator sim_;
  CorridorSweep sweep_;
  const ContourSteering contour_;
  std::unique_ptr<BuildingSession> session_;
  std::unique_ptr<TextExtractor> extractor_;
  double camera_yaw_rad_ = 0.0;
  LaserScan last_scan_;  // the drive steers on it
  double search_start_travel_m_ = 0.0;
  double search_start_time_s_ = 0.0;
  LocalizeTrial trial_;
};

}  // namespace

const char* ToString(LocalizeMethod method) { return method == LocalizeMethod::kAmcl ? "amcl" : "text_amcl"; }

const char* ToString(LocalizeDrive drive) { return drive == LocalizeDrive::kPatrol ? "patrol" : "contour"; }

LocalizeDrive ParseLocalizeDrive(const std::string& name) {
  if (name == "patrol") return LocalizeDrive::kPatrol;
  if (name == "contour") return LocalizeDrive::kContour;
  throw std::invalid_argument("'" + name + "' is not a drive (patrol or contour)");
}

LocalizeSummary Summarize(const LocalizeEvalResult& result) {
  LocalizeSummary s;
  std::vector<double> travel, error_m, error_deg, recovery_travel, floor_travel;
  for (const LocalizeTrial& t : result.trials) {
    ++s.trials;
    if (t.Success()) ++s.successes;
    if (t.WrongConvergence()) ++s.wrong_convergences;
    if (t.converged && t.fix.floor != t.fix.true_floor) ++s.wrong_floor;
    if (t.floor_travel_m >= 0.0) floor_travel.push_back(t.floor_travel_m);
    if (!t.converged) ++s.not_converged;
    if (!t.converged && t.fix.within_tolerance) ++s.not_converged_estimate_right;
    if (t.converged) {
      travel.push_back(t.fix.travel_m);
      error_m.push_back(t.fix.error_m);
      error_deg.push_back(t.fix.error_deg);
    }
    if (t.kidnapped) ++s.kidnaps;
    if (t.lost_detected) ++s.kidnap_lost_detected;
    if (t.recovered) {
      ++s.recoveries;
      recovery_travel.push_back(t.recovery.travel_m);
    }
  }
  s.success_rate = s.trials > 0 ? static_cast<double>(s.successes) / s.trials : 0.0;
  s.recovery_rate = s.kidnaps > 0 ? static_cast<double>(s.recoveries) / s.kidnaps : 0.0;
  s.median_travel_m = Median(travel);
  s.longest_travel_m = travel.empty() ? 0.0 : *std::max_element(travel.begin(), travel.end());
  s.median_final_error_m = Median(error_m);
  s.median_final_error_deg = Median(error_deg);
  s.median_recovery_travel_m = Median(recovery_travel);
  s.median_floor_travel_m = Median(floor_travel);
  return s;
}

LocalizeEvalResult RunLocalizeEval(const World& world, const OccupancyGrid& grid,
                                   std::shared_ptr<const TextMap> text_map, const OccupancyGrid& ground_truth_grid,
                                   const LocalizeEvalOptions& options) {
  return RunLocalizeEval(OneFloorBuilding(world, grid, std::move(text_map), ground_truth_grid), options);
}

double ParticleSpreadM(const std::vector<Particle>& particles) {
  if (particles.size() < 2) return 0.0;
  Vec2 mean{0.0, 0.0};
  for (const Particle& p : particles) mean = mean + p.pose.Position();
  mean = (1.0 / static_cast<double>(particles.size())) * mean;
  double sum_sq = 0.0;
  for (const Particle& p : particles) {
    const Vec2 d = p.pose.Position() - mean;
    sum_sq += Dot(d, d);
  }
  return std::sqrt(sum_sq / static_cast<double>(particles.size()));
}

std::shared_ptr<const BuildingMaps> SessionMaps(std::shared_ptr<const BuildingMaps> maps, bool use_text) {
  if (use_text) return maps;
  auto laser_only = std::make_shared<BuildingMaps>(*maps);
  for (FloorMaps& floor : laser_only->floors) floor.text_map = nullptr;
  return laser_only;
}

LocalizeBuilding OneFloorBuilding(World world, OccupancyGrid grid, std::shared_ptr<const TextMap> text_map,
                                  OccupancyGrid ground_truth_grid) {
  auto maps = std::make_shared<BuildingMaps>();
  maps->name = world.name;
  maps->floors.push_back({world.name, std::move(grid), std::move(text_map)});
  LocalizeBuilding building;
  building.name = world.name;
  building.maps = maps;
  building.ground_truth_grids.push_back(std::move(ground_truth_grid));
  building.worlds.push_back(std::move(world));
  return building;
}

LocalizeEvalResult RunLocalizeEval(const LocalizeBuilding& building, const LocalizeEvalOptions& options) {
  const size_t floors = building.worlds.size();
  if (floors == 0 || !building.maps || building.maps->floors.size() != floors ||
      building.ground_truth_grids.size() != floors) {
    throw std::invalid_argument("LocalizeBuilding: needs one world, one floor of maps and one ground-truth grid per "
                                "floor (got " + std::to_string(floors) + " worlds)");
  }
  bool has_text_maps = true;
  for (const FloorMaps& floor : building.maps->floors) has_text_maps = has_text_maps && floor.text_map != nullptr;
  Validate(options, has_text_maps);
  const Clock::time_point start = Clock::now();
  LocalizeBuilding run = building;
  std::vector<StartPoseSampler> poses;
  poses.reserve(floors);
  for (size_t f = 0; f < floors; ++f) {
    World& world = run.worlds[f];
    if (options.camera_rate_hz > 0.0) world.sensors.camera.rate_hz = options.camera_rate_hz;
    BuildSurfaces(world);
    poses.push_back(MakeStartPoseSampler(world, run.ground_truth_grids[f], options.poses));
  }
  LocalizeEvalResult result;
  result.world_name = building.name;
  result.method = options.method;
  result.kidnap = options.kidnap;
  result.floor_start_poses = poses.front().on_floor();
  for (const FloorMaps& floor : building.maps->floors) result.floors.push_back(floor.id);
  tools::ProgressLine progress({options.progress_every_s});
  double run_sim_s = 0.0;
  for (int i = 0; i < options.trials; ++i) {
    TrialRun trial(run, poses, options, i, &progress, run_sim_s);
    result.trials.push_back(trial.Run());
    run_sim_s += result.trials.back().sim_seconds;
  }
  progress.Finish();
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace doorplate_localization

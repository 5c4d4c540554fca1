#include "goto_eval.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>

#include "doorplate_localization/behaviour/room_goal_planner.h"
#include "doorplate_localization/mcl/text_amcl_session.h"
#include "doorplate_localization/sim/simulator.h"
#include "eval_args.h"
#include "localize_sensors.h"
#include "stats.h"

namespace doorplate_localization {
namespace {

using Clock = std::chrono::steady_clock;

void Validate(const GotoEvalOptions& o, const World& world) {
  auto check = [](bool ok, const char* field) {
    if (!ok) throw std::invalid_argument(std::string("GotoEvalOptions.") + field + ": out of range");
  };
  check(o.trials >= 1, "trials");
  check(o.first_trial >= 0, "first_trial");
  check(o.camera_rate_hz >= 0.0, "camera_rate_hz");
  check(o.initial_std_m > 0.0 && o.initial_std_rad > 0.0, "initial_std_m/initial_std_rad");
  check(o.success_distance_m > 0.0, "success_distance_m");
  check(o.time_limit_factor > 0.0, "time_limit_factor");
  if (world.corridors.empty()) {
    throw std::invalid_argument("world " + world.name + ": lists no corridors (the go-to trials start in them)");
  }
}

// One trial: the robot, the behaviour, the localizer and (text) the reader.
class GotoRun {
 public:
  GotoRun(const World& world, const OccupancyGrid& grid, std::shared_ptr<const TextMap> text_map,
          const StartPoseSampler& poses, const RoomGoalPlanner& rooms, const FloorGoToRoom& prototype,
          const GotoEvalOptions& options, int index)
      : options_(options), seed_(PassSeed(options.seed, index)), rng_(seed_), sim_(world, SimOptions(seed_)),
        go_(prototype) {
    trial_.index = index;
    trial_.seed = seed_;
    trial_.start_pose = poses.Sample(rng_);
    sim_.Teleport(trial_.start_pose);
    const int landmark = std::uniform_int_distribution<int>(0, static_cast<int>(text_map->landmarks.size()) - 1)(rng_);
    const TextLandmark& plate = text_map->landmarks[landmark];
    const std::string request = text_map->Find(plate.text).size() > 1 ? plate.text + "@" + plate.wall : plate.text;
    const RoomGoalResult planned = rooms.Plan(request, trial_.start_pose);
    has_goal_ = planned.goal.has_value();
    if (has_goal_) goal_ = *planned.goal;
    trial_.room = has_goal_ ? planned.goal->room : request;
    trial_.goal = goal_.pose;
    refusal_ = planned.refusal;

    TextAmclSessionOptions session;
    session.setup = options.filter;
    session.setup.filter.random_seed = seed_;
    session.setup.use_text = options.use_text;
    session.start_with_global_localization = false;
    session.initial_pose = trial_.start_pose;  // tracking: the true start pose
    const double var_xy = options.initial_std_m * options.initial_std_m;
    session.initial_covariance = Eigen::Vector3d(var_xy, var_xy, options.initial_std_rad * options.initial_std_rad)
                                     .asDiagonal();
    session_ = std::make_unique<TextAmclSession>(session, grid, options.use_text ? text_map : nullptr);
    if (options.use_text) {
      TextExtractorOptions extractor = options.extractor;
      extractor.tracker.fx_px = sim_.camera().intrinsics().fx_px;
      extractor.tracker.cx_px = sim_.camera().intrinsics().cx_px;
      extractor.validator.pattern = text_map->room_pattern;
      extractor_ = std::make_unique<TextExtractor>(extractor);
      double x = 0, y = 0, z = 0, pitch = 0;
      sim_.camera().MountPose(&x, &y, &z, &camera_yaw_rad_, &pitch);
    }
  }

  GotoTrial Run() {
    const Clock::time_point start = Clock::now();
    if (has_goal_) {
      go_.Start(goal_, session_->PoseAtOdometry(sim_.odom_pose()));  // the estimate at the start
    } else {
      go_.Refuse(refusal_);
    }
    trial_.plan_length_m = go_.path().length_m;
    trial_.plan_seconds = go_.path().plan_seconds;
    trial_.plan_min_clearance_m = go_.path().min_clearance_m;
    trial_.plan_mean_clearance_m = go_.path().mean_clearance_m;
    const double time_limit_s =
        options_.time_limit_factor * trial_.plan_length_m / options_.go.follower.cruise_speed_mps + 60.0;
    const long long steps_per_scan =
        std::max(1LL, std::llround(1.0 / (sim_.world().sensors.laser.rate_hz * SimOptions(seed_).physics_step_s)));
    const double frame_period_s = 1.0 / sim_.world().sensors.camera.rate_hz;
    long long next_frame = 0;
    bool timed_out = false;
    for (long long step = 0; go_.active(); ++step) {
      if (step % steps_per_scan == 0) ScanStep();
      if (!go_.active()) break;
      if (extractor_ && sim_.time_s() + 1e-9 >= static_cast<double>(next_frame) * frame_period_s) {
        ++next_frame;
        CameraStep();
      }
      sim_.Step();
      trial_.bumped = trial_.bumped || sim_.bumped();
      if (sim_.time_s() > time_limit_s) {
        timed_out = true;
        break;
      }
    }
    Finish(timed_out, time_limit_s);
    trial_.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return trial_;
  }

 private:
  static SimulatorOptions SimOptions(std::uint64_t seed) {
    SimulatorOptions o;
    o.seed = seed;
    return o;
  }

  // The session's scan input, then one control step on its estimate.
  void ScanStep() {
    const LocalizationScan scan = ToLocalizationScan(sim_.Scan(), sim_.world().sensors.laser);
    session_->AddScan(sim_.time_s(), sim_.odom_pose(), scan);
    const Pose2D estimate = session_->PoseAtOdometry(sim_.odom_pose());
    const double angle_min = scan.angle_min_rad + scan.laser_pose.theta_rad;
    const VelocityCommand cmd = go_.Step(scan.ranges_m, angle_min, scan.angle_increment_rad, estimate, sim_.time_s());
    sim_.SetCommand(cmd.linear_mps, cmd.angular_rps);
  }

  void CameraStep() {
    trial_.plate_updates += FeedCameraFrame(sim_, *extractor_, camera_yaw_rad_, *session_).plate_updates;
  }

  void Finish(bool timed_out, double time_limit_s) {
    trial_.outcome = go_.Status();
    if (timed_out) {
      char why[64];
      std::snprintf(why, sizeof(why), "timeout after %.0f s; ", time_limit_s);
      trial_.outcome = why + trial_.outcome;
    }
    trial_.arrived = go_.state() == FloorGoToRoomState::kArrived;
    trial_.replans = go_.replans();
    trial_.final_pose = sim_.true_pose();
    trial_.final_estimate = session_->PoseAtOdometry(sim_.odom_pose());
    trial_.estimate_error_m = Norm(trial_.final_estimate.Position() - trial_.final_pose.Position());
    const Vec2 d = trial_.final_pose.Position() - trial_.goal.Position();
    const Vec2 facing{std::cos(trial_.goal.theta_rad), std::sin(trial_.goal.theta_rad)};
    trial_.distance_m = Norm(d);
    trial_.across_m = Dot(d, facing);
    trial_.along_m = Dot(d, Vec2{-facing.y, facing.x});
    trial_.yaw_error_rad = NormalizeAngle(trial_.final_pose.theta_rad - trial_.goal.theta_rad);
    trial_.travel_m = sim_.distance_travelled_m();
    trial_.sim_seconds = sim_.time_s();
    trial_.success = trial_.arrived && trial_.distance_m <= options_.success_distance_m;
  }

  const GotoEvalOptions& options_;
  const std::uint64_t seed_;
  std::mt19937_64 rng_;
  Simulator sim_;
  FloorGoToRoom go_;
  std::unique_ptr<TextAmclSession> session_;
  std::unique_ptr<TextExtractor> extractor_;
  double camera_yaw_rad_ = 0.0;
  bool has_goal_ = false;
  std::string refusal_;
  RoomGoal goal_;
  GotoTrial trial_;
};

}  // namespace

GotoSummary Summarize(const GotoEvalResult& result) {
  GotoSummary s;
  std::vector<double> distance, yaw, travel, sim_s, plan_s, estimate;
  s.min_plan_clearance_m = result.trials.empty() ? 0.0 : 1e9;
  for (const GotoTrial& t : result.trials) {
    ++s.trials;
    s.successes += t.success ? 1 : 0;
    s.arrived += t.arrived ? 1 : 0;
    s.bumped += t.bumped ? 1 : 0;
    distance.push_back(t.distance_m);
    s.max_distance_m = std::max(s.max_distance_m, t.distance_m);
    yaw.push_back(std::fabs(t.yaw_error_rad));
    travel.push_back(t.travel_m);
    sim_s.push_back(t.sim_seconds);
    plan_s.push_back(t.plan_seconds);
    s.max_plan_s = std::max(s.max_plan_s, t.plan_seconds);
    if (t.plan_length_m > 0) s.min_plan_clearance_m = std::min(s.min_plan_clearance_m, t.plan_min_clearance_m);
    estimate.push_back(t.estimate_error_m);
  }
  s.median_distance_m = Median(distance);
  s.median_abs_yaw_rad = Median(yaw);
  s.median_travel_m = Median(travel);
  s.median_sim_s = Median(sim_s);
  s.median_plan_s = Median(plan_s);
  s.median_estimate_error_m = Median(estimate);
  return s;
}

GotoEvalResult RunGotoEval(const World& world, const OccupancyGrid& grid, std::shared_ptr<const TextMap> text_map,
                           const GotoEvalOptions& options) {
  Validate(options, world);
  if (!text_map || text_map->landmarks.empty()) throw std::invalid_argument("RunGotoEval: text_map: no plates");
  const Clock::time_point start = Clock::now();
  World run_world = world;
  if (options.camera_rate_hz > 0.0) run_world.sensors.camera.rate_hz = options.camera_rate_hz;
  BuildSurfaces(run_world);
  const StartPoseSampler poses = MakeStartPoseSampler(run_world, grid, options.poses);
  RoomGoalPlannerOptions room_options;
  room_options.wall_distance_m = 0.6;
  const RoomGoalPlanner rooms(room_options, *text_map, "the text map");
  const FloorGoToRoom prototype(options.go, grid);  // the clearance image once, copied per trial
  GotoEvalResult result;
  result.world_name = world.name;
  for (int i = options.first_trial; i < options.first_trial + options.trials; ++i) {
    GotoRun run(run_world, grid, text_map, poses, rooms, prototype, options, i);
    result.trials.push_back(run.Run());
  }
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace doorplate_localization

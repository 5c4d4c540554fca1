#include "goto_eval.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>

#include "doorplate_localization/behaviour/building_route.h"
#include "doorplate_localization/behaviour/room_goal_planner.h"
#include "doorplate_localization/mcl/building_session.h"
#include "doorplate_localization/sim/simulator.h"
#include "eval_args.h"
#include "localize_sensors.h"
#include "progress_line.h"
#include "stats.h"

namespace doorplate_localization {
namespace {

using Clock = std::chrono::steady_clock;

void Validate(const GotoEvalOptions& o, const LocalizeBuilding& building) {
  auto check = [](bool ok, const char* field) {
    if (!ok) throw std::invalid_argument(std::string("GotoEvalOptions.") + field + ": out of range");
  };
  check(o.trials >= 1, "trials");
  check(o.first_trial >= 0, "first_trial");
  check(o.camera_rate_hz >= 0.0, "camera_rate_hz");
  check(o.initial_std_m > 0.0 && o.initial_std_rad > 0.0, "initial_std_m/initial_std_rad");
  check(o.success_distance_m > 0.0, "success_distance_m");
  check(o.time_limit_factor > 0.0, "time_limit_factor");
  check(o.max_search_travel_m > 0.0, "max_search_travel_m");
  if (building.worlds.empty() || !building.maps || building.maps->floors.size() != building.worlds.size()) {
    throw std::invalid_argument("RunGotoEval: needs one world and one floor of maps per floor");
  }
  for (size_t f = 0; f < building.worlds.size(); ++f) {
    const World& world = building.worlds[f];
    if (world.corridors.empty()) {
      throw std::invalid_argument("world " + world.name + ": lists no corridors (the go-to trials start in them)");
    }
    const auto& text_map = building.maps->floors[f].text_map;
    if (!text_map || text_map->landmarks.empty()) {
      throw std::invalid_argument("RunGotoEval: floor '" + building.maps->floors[f].id + "': the text map has no plates");
    }
  }
}

// What one trial shares with the others: the worlds, samplers, route planner and behaviour prototypes.
struct GotoSetup {
  LocalizeBuilding building;                // camera rate applied, surfaces built
  std::vector<StartPoseSampler> poses;      // per floor
  std::unique_ptr<BuildingRoutePlanner> routes;
  std::vector<FloorGoToRoom> prototypes;    // per floor: the clearance image once, copied per trial
};

enum class GotoPhase { kToLift, kSearch, kToRoom, kDone };

// One trial: the robot, the behaviour, the localizer and (text) the reader.
class GotoRun {
 public:
  // `progress` gets a line when due; `run_sim_s`: simulated seconds of the run's earlier trials.
  GotoRun(const GotoSetup& setup, const GotoEvalOptions& options, int index, tools::ProgressLine* progress,
          double run_sim_s)
      : setup_(setup), options_(options), progress_(progress), run_sim_s_(run_sim_s),
        seed_(PassSeed(options.seed, index)), rng_(seed_),
        floor_(DrawStartFloor()), sim_(setup.building.worlds[static_cast<size_t>(floor_)], SimOptions(seed_)),
        search_(SearchOptions(options)) {
    const BuildingMaps& maps = *setup_.building.maps;
    trial_.index = index;
    trial_.seed = seed_;
    trial_.start_pose = setup_.poses[static_cast<size_t>(floor_)].Sample(rng_);
    trial_.start_floor = maps.floors[static_cast<size_t>(floor_)].id;
    sim_.Teleport(trial_.start_pose);
    const int room_floor = DrawRoomFloor();
    const TextMap& text_map = *maps.floors[static_cast<size_t>(room_floor)].text_map;
    const int landmark = std::uniform_int_distribution<int>(0, static_cast<int>(text_map.landmarks.size()) - 1)(rng_);
    const TextLandmark& plate = text_map.landmarks[landmark];
    const std::string request = text_map.Find(plate.text).size() > 1 ? plate.text + "@" + plate.wall : plate.text;
    const BuildingRouteResult planned = setup_.routes->Plan(request, floor_, trial_.start_pose);
    if (planned.route) {
      route_ = *planned.route;
      trial_.room_floor = maps.floors[static_cast<size_t>(route_->room_floor)].id;
      trial_.instruction = route_->instruction;
      trial_.lift = route_->lift;
    }
    trial_.room = route_ ? route_->goal.room : request;
    trial_.goal = route_ ? route_->goal.pose : Pose2D{};
    refusal_ = planned.refusal;

    BuildingSessionOptions session;
    session.session.setup = options.filter;
    session.session.setup.filter.random_seed = seed_;
    session.session.setup.use_text = options.use_text;
    session.session.start_with_global_localization = false;
    session.session.initial_pose = trial_.start_pose;  // tracking: the true start pose on the known floor
    const double var_xy = options.initial_std_m * options.initial_std_m;
    session.session.initial_covariance =
        Eigen::Vector3d(var_xy, var_xy, options.initial_std_rad * options.initial_std_rad).asDiagonal();
    session.start_floor = trial_.start_floor;
    session_ = std::make_unique<BuildingSession>(session, SessionMaps(setup_.building.maps, options.use_text));
    if (options.use_text) {
      TextExtractorOptions extractor = options.extractor;
      extractor.tracker.fx_px = sim_.camera().intrinsics().fx_px;
      extractor.tracker.cx_px = sim_.camera().intrinsics().cx_px;
      extractor.validator.pattern = maps.floors.front().text_map->room_pattern;
      extractor_ = std::make_unique<TextExtractor>(extractor);
      double x = 0, y = 0, z = 0, pitch = 0;
      sim_.camera().MountPose(&x, &y, &z, &camera_yaw_rad_, &pitch);
    }
  }

  GotoTrial Run() {
    const Clock::time_point start = Clock::now();
    const Pose2D estimate = session_->PoseAtOdometry(sim_.odom_pose());
    go_.emplace(setup_.prototypes[static_cast<size_t>(floor_)]);
    if (!route_) {
      go_->Refuse(refusal_);
    } else if (route_->via_lift) {
      phase_ = GotoPhase::kToLift;
      RoomGoal stop;
      stop.room = "lift " + route_->lift;
      stop.pose = route_->lift_stop_here;
      go_->Start(stop, estimate);
    } else {
      phase_ = GotoPhase::kToRoom;
      go_->Start(route_->goal, estimate);
    }
    trial_.plan_length_m = route_ && route_->via_lift ? route_->length_m : go_->path().length_m;
    trial_.plan_seconds = go_->path().plan_seconds;
    trial_.plan_min_clearance_m = go_->path().min_clearance_m;
    trial_.plan_mean_clearance_m = go_->path().mean_clearance_m;
    const double search_allowance_s =
        route_ && route_->via_lift ? options_.time_limit_factor * options_.max_search_travel_m /
                                         options_.go.follower.cruise_speed_mps : 0.0;
    const double time_limit_s =
        options_.time_limit_factor * trial_.plan_length_m / options_.go.follower.cruise_speed_mps + 60.0 +
        search_allowance_s;
    const long long steps_per_scan =
        std::max(1LL, std::llround(1.0 / (sim_.world().sensors.laser.rate_hz * SimOptions(seed_).physics_step_s)));
    const double frame_period_s = 1.0 / sim_.world().sensors.camera.rate_hz;
    long long next_frame = 0;
    bool timed_out = false;
    if (!go_->active()) phase_ = GotoPhase::kDone;
    for (long long step = 0; phase_ != GotoPhase::kDone; ++step) {
      if (step % steps_per_scan == 0) ScanStep();
      if (phase_ == GotoPhase::kDone) break;
      if (extractor_ && sim_.time_s() + 1e-9 >= static_cast<double>(next_frame) * frame_period_s) {
        ++next_frame;
        CameraStep();
      }
      sim_.Step();
      trial_.bumped = trial_.bumped || sim_.bumped();
      if (progress_->Due(run_sim_s_ + sim_.time_s())) ShowProgress();
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
  static ContourSteeringOptions SearchOptions(const GotoEvalOptions& options) {
    ContourSteeringOptions o = options.search;
    o.cruise_speed_mps = options.go.follower.cruise_speed_mps;
    return o;
  }
  int Floors() const { return static_cast<int>(setup_.building.worlds.size()); }
  // Nothing is drawn for floors in a one-floor building (its trials stay draw for draw).
  int DrawStartFloor() { return Floors() == 1 ? 0 : std::uniform_int_distribution<int>(0, Floors() - 1)(rng_); }
  int DrawRoomFloor() {
    if (Floors() == 1) return 0;
    const int other = std::uniform_int_distribution<int>(0, Floors() - 2)(rng_);
    return other < floor_ ? other : other + 1;
  }

  // The session's scan input, then one control step of the phase.
  void ScanStep() {
    const LaserScan scan = sim_.Scan();
    session_->AddScan(sim_.time_s(), sim_.odom_pose(), scan);
    const Pose2D estimate = session_->PoseAtOdometry(sim_.odom_pose());
    const double angle_min = scan.angle_min_rad + scan.laser_pose.theta_rad;
    VelocityCommand cmd;
    if (phase_ == GotoPhase::kSearch) {
      cmd = search_.Step(scan.ranges_m, angle_min, scan.angle_increment_rad).command;
      CheckSearch(estimate);
    } else {
      cmd = go_->Step(scan.ranges_m, angle_min, scan.angle_increment_rad, estimate, sim_.time_s());
      if (!go_->active()) {
        if (phase_ == GotoPhase::kToLift && go_->state() == FloorGoToRoomState::kArrived) {
          Ride();
          cmd = {};
        } else {
          phase_ = GotoPhase::kDone;
        }
      }
    }
    sim_.SetCommand(cmd.linear_mps, cmd.angular_rps);
  }

  // At the lift stop: ride to the room's floor, leave the lift facing away from its door, and let the
  // plates tell the localizer where the robot is.
  void Ride() {
    trial_.rode = true;
    trial_.lift_stop_distance_m = Norm(sim_.true_pose().Position() - route_->lift_stop_here.Position());
    floor_ = route_->room_floor;
    Pose2D out = route_->lift_stop_there;
    out.theta_rad = NormalizeAngle(out.theta_rad + M_PI);
    sim_.ChangeWorld(setup_.building.worlds[static_cast<size_t>(floor_)], out);
    session_->GlobalLocalization();
    if (extractor_) extractor_->Reset();
    ride_travel_m_ = sim_.distance_travelled_m();
    phase_ = GotoPhase::kSearch;
  }

  // After a ride: search until the session is converged on a certain floor, then plan to the room.
  void CheckSearch(const Pose2D& estimate) {
    trial_.searched_m = sim_.distance_travelled_m() - ride_travel_m_;
    if (session_->Status().state == LocalizationState::kConverged) {
      trial_.found_floor = session_->floor() == route_->room_floor;
      if (!trial_.found_floor) {
        phase_ = GotoPhase::kDone;
        failure_ = "localized on floor " + session_->floor_id() + ", not the room's floor " + trial_.room_floor;
        return;
      }
      go_.emplace(setup_.prototypes[static_cast<size_t>(route_->room_floor)]);
      phase_ = go_->Start(route_->goal, estimate) ? GotoPhase::kToRoom : GotoPhase::kDone;
    } else if (trial_.searched_m > options_.max_search_travel_m) {
      phase_ = GotoPhase::kDone;
      failure_ = "not localized after the ride within " + std::to_string(options_.max_search_travel_m) + " m";
    }
  }

  void ShowProgress() {
    const int trial = trial_.index - options_.first_trial + 1;
    const double sim_s = run_sim_s_ + sim_.time_s();
    if (phase_ == GotoPhase::kSearch) {
      progress_->Show("goto: trial %d/%d, %.0f s simulated, %.1f m driven, after the lift ride %.1f m searched, "
                      "particle spread %.2f m, %d plates used", trial, options_.trials, sim_s,
                      sim_.distance_travelled_m(), trial_.searched_m,
                      ParticleSpreadM(session_->session().particles()), trial_.plate_updates);
      return;
    }
    const std::string target = phase_ == GotoPhase::kToLift ? "lift " + route_->lift : "room " + trial_.room;
    progress_->Show("goto: trial %d/%d, to %s, %.0f s simulated, %.1f m driven, distance left %.1f m, %s", trial,
                    options_.trials, target.c_str(), sim_s, sim_.distance_travelled_m(), go_->follower().remaining_m(),
                    PathFollowStateName(go_->follower().state()));
  }

  void CameraStep() {
    trial_.plate_updates += FeedCameraFrame(sim_, *extractor_, camera_yaw_rad_, *session_).plate_updates;
  }

  void Finish(bool timed_out, double time_limit_s) {
    trial_.outcome = failure_.empty() ? go_->Status() : "failed: " + failure_;
    if (timed_out) {
      char why[64];
      std::snprintf(why, sizeof(why), "timeout after %.0f s; ", time_limit_s);
      trial_.outcome = why + trial_.outcome;
    }
    const bool on_room_floor = route_ && floor_ == route_->room_floor;
    trial_.arrived = failure_.empty() && on_room_floor && go_->state() == FloorGoToRoomState::kArrived;
    trial_.replans = go_->replans();
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

  const GotoSetup& setup_;
  const GotoEvalOptions& options_;
  tools::ProgressLine* const progress_;
  const double run_sim_s_;
  const std::uint64_t seed_;
  std::mt19937_64 rng_;
  int floor_;  // the floor the robot is on
  Simulator sim_;
  const ContourSteering search_;
  std::optional<FloorGoToRoom> go_;
  GotoPhase phase_ = GotoPhase::kDone;
  std::optional<BuildingRoute> route_;
  std::unique_ptr<BuildingSession> session_;
  std::unique_ptr<TextExtractor> extractor_;
  double camera_yaw_rad_ = 0.0;
  double ride_travel_m_ = 0.0;
  std::string refusal_;
  std::string failure_;  // a failure of the building phases (else the behaviour's status says it)
  GotoTrial trial_;
};

}  // namespace

GotoSummary Summarize(const GotoEvalResult& result) {
  GotoSummary s;
  std::vector<double> distance, yaw, travel, sim_s, plan_s, estimate, searched;
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
    if (t.rode) {
      ++s.rides;
      s.found_floor += t.found_floor ? 1 : 0;
      searched.push_back(t.searched_m);
      s.max_searched_m = std::max(s.max_searched_m, t.searched_m);
    }
  }
  s.median_searched_m = Median(searched);
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
  return RunGotoEval(OneFloorBuilding(world, grid, std::move(text_map), grid), options);
}

GotoEvalResult RunGotoEval(const LocalizeBuilding& building, const GotoEvalOptions& options) {
  Validate(options, building);
  const Clock::time_point start = Clock::now();
  GotoSetup setup;
  setup.building = building;
  for (size_t f = 0; f < building.worlds.size(); ++f) {
    World& world = setup.building.worlds[f];
    if (options.camera_rate_hz > 0.0) world.sensors.camera.rate_hz = options.camera_rate_hz;
    BuildSurfaces(world);
    const OccupancyGrid& grid = building.maps->floors[f].grid;
    setup.poses.push_back(MakeStartPoseSampler(world, setup.building.ground_truth_grids[f], options.poses));
    setup.prototypes.emplace_back(options.go, grid);
  }
  BuildingRouteOptions route_options;
  route_options.planner = options.go.planner;
  route_options.room.wall_distance_m = 0.6;
  setup.routes = std::make_unique<BuildingRoutePlanner>(route_options, building.maps);
  GotoEvalResult result;
  result.world_name = building.name;
  for (const FloorMaps& floor : building.maps->floors) result.floors.push_back(floor.id);
  tools::ProgressLine progress({options.progress_every_s});
  double run_sim_s = 0.0;
  for (int i = options.first_trial; i < options.first_trial + options.trials; ++i) {
    GotoRun run(setup, options, i, &progress, run_sim_s);
    result.trials.push_back(run.Run());
    run_sim_s += result.trials.back().sim_seconds;
  }
  progress.Finish();
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace doorplate_localization

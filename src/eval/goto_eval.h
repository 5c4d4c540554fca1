// Go to any room on a floor (issue 17): trials of FloorGoToRoom (behaviour/floor_go_to_room.h) in the
// simulator, driven by the Text AMCL estimate. Each trial puts the robot at a random corridor pose
// (StartPoseSampler over the world's `corridors`: a corridor drawn in proportion to its length, a point
// uniform along its centreline and across its width minus wall_margin_m each side, heading along it
// ± heading_noise_rad), picks a random room of the text map (uniform over its plates; RoomGoalPlanner's
// goal in front of the plate), starts a TextAmclSession in tracking mode at the TRUE start pose (initial
// covariance initial_std_m, initial_std_rad), plans from the session's estimate and drives. The session
// gets what localize_eval gives it: the simulator's scans with their odometry at the laser's rate, and (with
// use_text) each camera frame through the real TextExtractor, its plate reports as PlateReadings with the
// odometry of their moment. The behaviour gets the session's estimate carried to the scan's odometry
// (TextAmclSession::PoseAtOdometry) and the scan; its commands drive the simulator (physics 100 Hz).
// A trial ends when the behaviour ends (arrived, refused, failed) or after time_limit_factor × (planned
// length / cruise speed) + 60 s. Success: arrived with the TRUE final pose within success_distance_m of the
// goal pose. Deterministic for a given seed (trial i uses PassSeed(seed, i)) except the timings.
// Buildings of several floors (issue 17 item 5; RunGotoEval on a LocalizeBuilding): the robot starts on a
// floor drawn uniformly (the session knows it: tracking), the room is drawn on another floor (uniform over
// the other floors, then over its plates), and BuildingRoutePlanner says which lift to take. The robot drives
// to the lift's stop on its floor (FloorGoToRoom), rides (the simulator's ChangeWorld: out of the lift at the
// stop on the room's floor, facing away from the door), asks the localizer for global localization (it does
// not tell it the floor: the plates pick it, BuildingSession), searches (ContourSteering, at most
// max_search_travel_m) until the session is converged on a certain floor, then plans to the room from its
// estimate. Success: arrived on the room's floor within success_distance_m of the goal. One floor: the
// trials of before, draw for draw (nothing is drawn for floors).
// Frames: the world = ground-truth map frame (each floor's); metres, radians, seconds.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "doorplate_localization/behaviour/contour_steering.h"
#include "doorplate_localization/behaviour/floor_go_to_room.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/mcl/text_amcl_setup.h"
#include "doorplate_localization/sim/world.h"
#include "doorplate_localization/text/text_extractor.h"
#include "localize_eval.h"
#include "localize_start_poses.h"

namespace doorplate_localization {

struct GotoEvalOptions {
  int trials = 30;
  int first_trial = 0;                  // trials first_trial .. first_trial + trials − 1 (split runs)
  std::uint64_t seed = 1;
  bool use_text = true;                 // text_amcl (camera plates) or laser-only amcl tracking
  double camera_rate_hz = 0.0;          // 0: the world's
  double initial_std_m = 0.1;           // session's initial covariance around the true start pose
  double initial_std_rad = 0.05;
  double success_distance_m = 0.3;
  double time_limit_factor = 3.0;
  double max_search_travel_m = 120.0;   // buildings: the search after a ride fails beyond this
  ContourSteeringOptions search;        // buildings: the drive after a ride (cruise speed: the follower's)
  FloorGoToRoomOptions go;              // planner and follower
  TextAmclSetupOptions filter;          // use_text and the random seed are set per trial
  TextExtractorOptions extractor;       // tracker intrinsics and room pattern are set from the run
  StartPoseSamplerOptions poses;
  // > 0: a progress line on stderr (trial, simulated seconds, distance driven, distance left along the plan,
  // or the search after a ride) every this many simulated seconds of the run, rewritten in place on a
  // terminal (progress_line.h).
  double progress_every_s = 0.0;
};

struct GotoTrial {
  int index = 0;
  std::uint64_t seed = 0;
  Pose2D start_pose;
  std::string start_floor;              // buildings only (below, down to searched_m)
  std::string room_floor;
  std::string instruction;              // BuildingRoute::instruction ("... take lift A from floor 2 to floor 3 ...")
  std::string lift;                     // the lift taken ("" = none)
  bool rode = false;                    // reached the lift stop and rode
  double lift_stop_distance_m = 0.0;    // true position to the lift stop when the robot arrived there
  double searched_m = 0.0;              // travel after the ride until localized on a certain floor
  bool found_floor = false;             // ... and on the room's floor
  std::string room;
  Pose2D goal;
  std::string outcome;                  // FloorGoToRoom status at the end, or "timeout: ..."
  bool arrived = false;
  bool success = false;
  double plan_length_m = 0.0;           // the first plan
  double plan_seconds = 0.0;
  double plan_min_clearance_m = 0.0;
  double plan_mean_clearance_m = 0.0;
  int replans = 0;
  Pose2D final_pose;                    // truth
  Pose2D final_estimate;                // the session's
  double distance_m = 0.0;              // true final position to the goal position
  double along_m = 0.0;                 // ... along the goal's wall (signed, left of the door positive)
  double across_m = 0.0;                // ... towards the wall (signed, + = closer to the wall than the goal)
  double yaw_error_rad = 0.0;           // true final heading − goal heading
  double estimate_error_m = 0.0;        // session estimate vs truth at the end
  double travel_m = 0.0;
  double sim_seconds = 0.0;
  double wall_seconds = 0.0;
  bool bumped = false;                  // the simulator stopped a step at a wall
  int plate_updates = 0;                // plate readings the filter used
};

struct GotoEvalResult {
  std::string world_name;
  std::vector<std::string> floors;      // the building's floor ids (one for a world)
  std::vector<GotoTrial> trials;
  double seconds = 0.0;
};

struct GotoSummary {
  int trials = 0, successes = 0, arrived = 0, bumped = 0;
  double median_distance_m = 0.0, max_distance_m = 0.0;        // over all trials
  double median_abs_yaw_rad = 0.0, median_travel_m = 0.0, median_sim_s = 0.0;
  double median_plan_s = 0.0, max_plan_s = 0.0, min_plan_clearance_m = 0.0;
  double median_estimate_error_m = 0.0;
  int rides = 0, found_floor = 0;      // buildings: rides taken; searches that ended on the room's floor
  double median_searched_m = 0.0, max_searched_m = 0.0;  // over the rides
};

GotoSummary Summarize(const GotoEvalResult& result);

// Runs the trials on `world` (it must list `corridors`) with the map the robot knows: `grid` and
// `text_map` (both in the world frame). Throws std::invalid_argument / std::runtime_error naming the field.
GotoEvalResult RunGotoEval(const World& world, const OccupancyGrid& grid, std::shared_ptr<const TextMap> text_map,
                           const GotoEvalOptions& options);
// The same in a building (every floor's world must list `corridors`; lifts in building.maps).
GotoEvalResult RunGotoEval(const LocalizeBuilding& building, const GotoEvalOptions& options);

}  // namespace doorplate_localization

// Follows a planned path (GridPathPlanner) with pure pursuit, then turns in place to a goal heading.
//
// Each Step takes base_link's pose in the path's frame (the map frame: the localizer's estimate) and a
// laser scan in base_link (beam i at angle_min_rad + i · angle_increment_rad, x forward, y left;
// non-finite ranges ignored). Progress along the path is the closest path point within progress_window_m
// ahead of the last one (never backwards, so a jump of the estimate does not send the robot back); the
// look-ahead point is look_ahead_m further along the path (the path's end near the end). Steering: pure
// pursuit, curvature 2·sin(bearing)/distance to the look-ahead point, angular speed <= max_angular_speed_rps
// (the linear speed is lowered to keep the curvature); linear speed <= approach_gain_per_s × remaining
// distance near the end (>= min_approach_speed_mps).
//
// States: kTurning (in place towards the look-ahead point while it is more than rotate_in_place_rad off the
// heading — at the start, or after an overshoot — until within resume_driving_rad) → kDriving → kFacing
// (within goal_tolerance_m of the path's end, or the end is already behind the robot within
// overshoot_tolerance_m: in place to the goal heading) → kArrived (within face_tolerance_rad). kBlocked
// while driving when a laser return lies within stop_distance_m ahead of base_link and front_half_width_m
// of its centre line: the robot stops and drives on once the way is clear. Commands are zero outside
// kTurning, kDriving and kFacing, and for a pose with a non-finite value. Units: metres, radians, seconds.
#pragma once

#include <vector>

#include "doorplate_localization/behaviour/isolated_returns.h"
#include "doorplate_localization/behaviour/wall_follower.h"
#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct PathFollowerOptions {
  double look_ahead_m = 0.8;
  double cruise_speed_mps = 0.4;
  double max_angular_speed_rps = 0.8;
  double turn_speed_rps = 0.6;           // in-place turns (towards the path, to the goal heading)
  double rotate_in_place_rad = 1.0;      // look-ahead point further off the heading: turn in place ...
  double resume_driving_rad = 0.3;       // ... until it is within this
  double approach_gain_per_s = 0.8;      // near the end, linear speed <= gain × remaining distance
  double min_approach_speed_mps = 0.05;  //   but at least this
  double goal_tolerance_m = 0.05;        // distance to the path's end at which driving stops
  double overshoot_tolerance_m = 0.15;   // the end behind the robot within this also stops driving
  double face_gain_per_s = 2.0;          // facing: angular speed = gain × yaw error, <= turn_speed_rps
  double face_tolerance_rad = 0.05;
  double stop_distance_m = 0.35;         // an obstacle this close ahead of base_link stops the robot ...
  double front_half_width_m = 0.25;      // ... if within this of the centre line
  IsolatedReturnOptions isolated_returns;  // returns without neighbours are no obstacle (isolated_returns.h)
  double progress_window_m = 2.0;        // the closest path point is searched this far ahead of the last
};

enum class PathFollowState { kIdle, kTurning, kDriving, kFacing, kArrived, kBlocked };

// "idle", "turning", "driving", "facing", "arrived", "blocked".
const char* PathFollowStateName(PathFollowState state);

class PathFollower {
 public:
  // Throws std::invalid_argument naming the field of an invalid option.
  explicit PathFollower(const PathFollowerOptions& options);

  // Starts following `path` (at least one point; map frame) and then turning to `goal_heading_rad`.
  // Throws std::invalid_argument for an empty path or a non-finite value.
  void Start(const std::vector<Vec2>& path, double goal_heading_rad);
  void Stop();  // kIdle

  VelocityCommand Step(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad,
                       const Pose2D& pose);

  PathFollowState state() const { return state_; }
  bool active() const;  // kTurning, kDriving, kFacing or kBlocked
  const std::vector<Vec2>& path() const { return path_; }
  // From the pose of the last Step: distance to the closest path point (cross-track), along the path to its
  // end, straight to its end, and the yaw error to the goal heading.
  double cross_track_m() const { return cross_track_m_; }
  double remaining_m() const { return remaining_m_; }
  double distance_to_end_m() const { return distance_to_end_m_; }
  double yaw_error_rad() const { return yaw_error_rad_; }
  double obstacle_ahead_m() const { return obstacle_ahead_m_; }  // nearest return in the stop band, +inf if none
  const PathFollowerOptions& options() const { return options_; }

 private:
  void UpdateProgress(Vec2 position);
  double NearestAhead(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad) const;

  const PathFollowerOptions options_;
  std::vector<Vec2> path_;
  std::vector<double> along_m_;  // path length from the start to each point
  double goal_heading_rad_ = 0.0;
  size_t progress_ = 0;
  PathFollowState state_ = PathFollowState::kIdle;
  double cross_track_m_ = 0.0, remaining_m_ = 0.0, distance_to_end_m_ = 0.0, yaw_error_rad_ = 0.0;
  double obstacle_ahead_m_ = 0.0;
};

}  // namespace doorplate_localization

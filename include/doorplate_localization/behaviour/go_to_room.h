// Go to a room (paper Sec. 3.4, Fig. 8): drive along the corridor to a goal in front of a doorplate and stop
// facing the door. Lateral control is the WallFollower's (paper Sec. 3.2): the robot follows the goal
// plate's wall at follower.wall_distance_m, so it arrives at the planner's goal (RoomGoalPlanner) in front of
// the plate. Progress along the corridor comes from the pose passed to Step: the localizer's pose in the
// map frame, or, in the eq. 15 fallback (PlanFromReading), the odometry pose in the odom frame; the goal and
// the poses must be in the same frame.
//
// Sequence: kTurning (in place, towards the goal, when it lies more than align_tolerance_rad off the heading,
// e.g. behind; again while driving when the heading gets 2 align_tolerance_rad off, e.g. after an overshoot)
// → kDriving (wall following, slowing down near the goal) → kFacing (in place, to the goal's
// theta) → kArrived. kFailed when the wall follower stops at a wall or obstacle ahead before the goal and it
// is still there after blocked_wait_s (a person walking past clears; a corridor's end does not).
// kRefused when the caller refuses a request (Refuse()): the planner's reason is kept for the status.
//
// Along-corridor coordinate: the goal's position projected on the corridor axis, i.e. the direction
// perpendicular to the goal's theta; only that coordinate decides arrival (the lateral position is the
// follower's, converged to wall_distance_m after a few metres of driving).
#pragma once

#include <string>
#include <vector>

#include "doorplate_localization/behaviour/hold_timer.h"
#include "doorplate_localization/behaviour/room_goal_planner.h"
#include "doorplate_localization/behaviour/wall_follower.h"
#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct GoToRoomOptions {
  // Lateral control and the stop at walls ahead; wall_side is ignored: the side is the goal's wall, chosen
  // per goal from the travel direction.
  WallFollowerOptions follower;
  // Approach (as CorridorSweepOptions): the goal's wall is often the far one. Until the fitted wall is within
  // approach_tolerance_m of follower.wall_distance_m, the wall fit uses only the beams from
  // follower.side_sector_min_deg to approach_sector_max_deg from straight ahead: beams further back reach
  // the end wall behind the robot near a corridor's end and bend the line.
  double approach_sector_max_deg = 90.0;
  double approach_tolerance_m = 0.15;
  double turn_speed_rps = 0.6;           // in-place turns towards the goal
  double align_tolerance_rad = 0.3;      // a turn towards the goal ends within this of the travel direction
  double arrive_tolerance_m = 0.03;      // along-corridor distance to the goal at which the robot stops
  double approach_gain_per_s = 0.8;      // near the goal, linear speed <= gain * remaining distance
  double min_approach_speed_mps = 0.05;  //   but at least this
  double face_gain_per_s = 2.0;          // facing the door: angular speed = gain * yaw error, <= turn_speed_rps
  double face_tolerance_rad = 0.05;      // facing ends (kArrived) within this of the goal's theta
  // Something within follower.end_stop_distance_m ahead while driving: stop, and fail the goal only if it is
  // still there after this long (0: at once). A demo on the realistic corridor failed its goal the moment a
  // person walked past in front of the robot.
  double blocked_wait_s = 10.0;
};

enum class GoToRoomState { kIdle, kTurning, kDriving, kFacing, kArrived, kRefused, kFailed };

// "idle", "turning", "driving", "facing", "arrived", "refused", "failed".
const char* GoToRoomStateName(GoToRoomState state);

class GoToRoom {
 public:
  // Throws std::invalid_argument naming the field of an invalid option (follower fields included).
  explicit GoToRoom(const GoToRoomOptions& options);

  // Starts driving to `goal` (RoomGoal::pose in the frame of the poses given to Step).
  void Start(const RoomGoal& goal);
  // Records a refused request: state kRefused with `reason`, no goal, zero commands.
  void Refuse(const std::string& reason);
  // Drops the goal: kIdle, zero commands.
  void Cancel();

  // One control step with the laser scan (base_link, as WallFollower::Observe), base_link's pose in the
  // goal's frame at the scan's time and that time (seconds, any monotonic clock: it times blocked_wait_s).
  // Returns the command to apply until the next step; zero unless the state after the step is kTurning,
  // kDriving or kFacing, zero while it waits before something ahead, and zero (a stop, state unchanged) for
  // a pose or time with a non-finite value.
  VelocityCommand Step(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad,
                       const Pose2D& pose, double time_s);

  GoToRoomState state() const { return state_; }
  bool active() const;  // kTurning, kDriving or kFacing
  const RoomGoal& goal() const { return goal_; }
  // Signed along-corridor distance from the pose of the last Step to the goal, metres (0 before any step).
  double remaining_m() const { return remaining_m_; }
  // Why the goal failed or was refused; "" otherwise.
  const std::string& reason() const { return reason_; }
  // One line for ~status: "<state>: <detail>", e.g. "turning: room 105, starting" (before the first Step),
  // "driving: room 105, 3.20 m to go",
  // "refused: room 999 is not in the text map ...", "arrived: room 105 (#2 ...), 0.04 m along, yaw error 0.02 rad".
  std::string Status() const;
  const GoToRoomOptions& options() const { return options_; }

 private:
  VelocityCommand Drive(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad,
                        const Vec2& travel, double time_s);

  const GoToRoomOptions options_;
  const WallFollower left_follower_, right_follower_;      // the goal's wall on the left / right
  const WallFollower left_approach_, right_approach_;      // the same with the approach sector
  bool approaching_ = true;  // this leg has not yet reached the wall distance
  GoToRoomState state_ = GoToRoomState::kIdle;
  RoomGoal goal_;
  std::string reason_;
  double remaining_m_ = 0.0;
  double yaw_error_rad_ = 0.0;
  bool stepped_ = false;  // Step ran since Start: remaining_m_ is known
  HoldTimer blocked_;     // stopped before something ahead
};

}  // namespace doorplate_localization

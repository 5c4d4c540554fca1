// Go to a room anywhere on a floor (issue 17): the goal pose in front of the plate (RoomGoalPlanner), a
// path to it over the occupancy grid (GridPathPlanner: round corners, down the corridors' middles) and
// pure pursuit along it, then a turn in place to face the door (PathFollower). GoToRoom (go_to_room.h)
// stays the one-corridor behaviour of the paper (wall following, eq. 15 fallback); this one needs a pose in
// the map frame (the localizer's estimate) and the grid of that map.
//
// Start plans from the robot's pose to the goal; a goal the planner refuses (inside an obstacle, no path)
// is refused with the planner's reason. While following, a robot more than max_path_deviation_m from the
// path (a localization jump, a push) gets a new path from where it is, at most max_replans times per goal;
// a replan that fails ends the goal (kFailed). A blocked way (PathFollower kBlocked) stops the robot until
// it clears, or for at most max_blocked_s (then kFailed). Frames: the grid's and the goal's map frame;
// units: metres, radians, seconds (stamps are those given to Step).
#pragma once

#include <string>
#include <vector>

#include "doorplate_localization/behaviour/grid_path_planner.h"
#include "doorplate_localization/behaviour/hold_timer.h"
#include "doorplate_localization/behaviour/path_follower.h"
#include "doorplate_localization/behaviour/room_goal_planner.h"
#include "doorplate_localization/maps/occupancy_grid.h"

namespace doorplate_localization {

struct FloorGoToRoomOptions {
  GridPathPlannerOptions planner;
  PathFollowerOptions follower;
  double max_path_deviation_m = 1.0;  // farther from the path: plan again from the pose
  int max_replans = 5;
  double max_blocked_s = 30.0;        // blocked longer than this: kFailed
};

enum class FloorGoToRoomState { kIdle, kFollowing, kArrived, kRefused, kFailed };

// "idle", "following", "arrived", "refused", "failed".
const char* FloorGoToRoomStateName(FloorGoToRoomState state);

class FloorGoToRoom {
 public:
  // Builds the planner on `grid` (map frame). Throws std::invalid_argument naming the field of an invalid
  // option (planner and follower fields included).
  FloorGoToRoom(const FloorGoToRoomOptions& options, const OccupancyGrid& grid);

  // Plans from `robot_in_map` to `goal` and starts following; returns false (state kRefused, reason()
  // says why) when the planner refuses.
  bool Start(const RoomGoal& goal, const Pose2D& robot_in_map);
  void Refuse(const std::string& reason);
  void Cancel();

  // One control step: the scan in base_link (as PathFollower::Step), base_link's pose in the map frame and
  // the time of the scan, seconds. Zero commands unless kFollowing.
  VelocityCommand Step(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad,
                       const Pose2D& pose, double stamp_s);

  FloorGoToRoomState state() const { return state_; }
  bool active() const { return state_ == FloorGoToRoomState::kFollowing; }
  const RoomGoal& goal() const { return goal_; }
  const GridPath& path() const { return path_; }      // the latest plan
  const PathFollower& follower() const { return follower_; }
  int replans() const { return replans_; }
  double first_plan_length_m() const { return first_plan_length_m_; }
  const std::string& reason() const { return reason_; }  // kRefused / kFailed: why
  // "following: room 205, driving, 12.30 m to go", "arrived: room 205, 0.03 m from the goal, yaw error
  // 0.02 rad", "refused: goal inside an obstacle: ...", "failed: ...".
  std::string Status() const;
  const GridPathPlanner& planner() const { return planner_; }

 private:
  bool Replan(const Pose2D& pose);

  const FloorGoToRoomOptions options_;
  const GridPathPlanner planner_;
  PathFollower follower_;
  FloorGoToRoomState state_ = FloorGoToRoomState::kIdle;
  RoomGoal goal_;
  GridPath path_;
  std::string reason_;
  int replans_ = 0;
  double first_plan_length_m_ = 0.0;
  HoldTimer blocked_;  // the path follower blocked
};

}  // namespace doorplate_localization

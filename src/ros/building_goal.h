// A room goal of GoToRoomNodelet in a building of several floors (~building_file, issue 17 item 5): the route
// from the localizer's floor (BuildingRoutePlanner) and its legs, as the experiment `doorplate_eval goto`
// drives them (src/eval/goto_eval.cpp). ROS-free; the nodelet converts the messages, drives each leg with
// FloorGoToRoom on leg_floor()'s grid, and turns the search drive (the wall follower's ~enable, ~mode roam)
// on exactly while searching().
//
//   Start ──▶ localizing: search until the localizer is converged (a certain floor), then plan the route
//               ├─ the room on this floor ──▶ to_room (leg) ──▶ done
//               └─ on another ──▶ to_lift (leg: the lift's stop) ──▶ waiting_for_lift ──ride──▶ localizing
//                    (after the ride: until converged on the room's floor) ──▶ to_room (leg) ──▶ done
//
// Frames: each floor's map frame (the localizer's map frame shows the current floor's map); metres, radians.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "doorplate_localization/behaviour/building_route.h"
#include "doorplate_localization/ros/lift_ride.h"

namespace doorplate_localization {

enum class BuildingGoalPhase { kIdle, kLocalizing, kToLift, kWaitingForLift, kToRoom, kDone };

class BuildingGoal {
 public:
  // Throws std::invalid_argument as BuildingRoutePlanner's constructor.
  BuildingGoal(const BuildingRouteOptions& options, std::shared_ptr<const BuildingMaps> maps);

  // A new request (replaces the current one): kLocalizing and "", or kDone and the refusal when no floor has
  // the room ("room 999 is on no floor of building h (floors: 2, 3)").
  std::string Start(const std::string& request);
  void Cancel();  // kIdle

  // The localizer's latest ~floor (its current floor's id) and ~state ("converged", "tracking", ...).
  void SetLocalizerFloor(const std::string& floor) { localizer_floor_ = floor; }
  void SetLocalizerState(const std::string& state) { localizer_state_ = state; }
  // While localizing, with the robot's pose in the map frame (nullopt: none yet): once the localizer has
  // converged, plans the route from its floor and returns true: a leg starts (to the lift's stop, or to the
  // room), which the nodelet drives (leg() on leg_floor()). Converged on another floor than the ride's ends
  // the goal (kDone, failed); a route the planner refuses ends it refused. Otherwise false.
  bool TryStartLeg(const std::optional<Pose2D>& pose);
  // The leg the nodelet drove has ended: arrived (to_lift: kWaitingForLift; to_room: kDone) or not (kDone);
  // `leg_status` is FloorGoToRoom's status, the goal's status when it ends the goal.
  void OnLegEnded(bool arrived, const std::string& leg_status);
  // A lift ride (the ride_lift message's text, ros/lift_ride.h) while waiting for the lift: the route's lift
  // to the room's floor is the route's ride (kLocalizing again: the nodelet asks the localizer for global
  // localization, and the localizer counts as converged only once it says so again); else false: nothing
  // changes, *problem says why (malformed, not waiting for a lift, another lift, another floor).
  bool OnRide(const std::string& ride_text, std::string* problem);

  BuildingGoalPhase phase() const { return phase_; }
  bool searching() const { return phase_ == BuildingGoalPhase::kLocalizing; }
  const std::string& request() const { return request_; }
  const std::optional<BuildingRoute>& route() const { return route_; }
  int leg_floor() const { return leg_floor_; }  // index into the building's floors
  const RoomGoal& leg() const { return leg_; }  // the lift's stop ("lift A") or the room's goal
  // "localizing: room 305: searching for plates until the localizer has converged (localizer: floor 2,
  // tracking)", "to_lift: room 305 is on floor 3: take lift A from floor 2 to floor 3 (wait at ...)",
  // "waiting_for_lift: waiting for lift A to floor 3 (room 305) at its stop on floor 2", "to_room: room 305 is on this
  // floor (3)", then the leg's end: "arrived: room 305, ...", "failed: ...", "refused: ...". "idle".
  std::string Status() const;

 private:
  void StartLeg(int floor, const RoomGoal& goal, BuildingGoalPhase phase);

  const std::unique_ptr<const BuildingRoutePlanner> routes_;
  BuildingGoalPhase phase_ = BuildingGoalPhase::kIdle;
  std::string request_;
  std::optional<BuildingRoute> route_;
  std::string ride_floor_;   // after a ride: the floor the lift went to ("" before)
  std::string ride_lift_;
  std::string localizer_floor_, localizer_state_;
  int leg_floor_ = -1;
  RoomGoal leg_;
  std::string end_status_;   // kDone: how the goal ended
};

}  // namespace doorplate_localization

// Which way to a room in a building of several floors (issue 17 item 5): the room's goal on its floor
// (RoomGoalPlanner on that floor's text map) and, when that is not the robot's floor, which lift to take.
// Of the lifts that stop on both floors, the one with the shortest route: grid path (GridPathPlanner) from
// the robot to the lift's stop on its floor, plus grid path from the lift's stop on the room's floor to the
// room's goal. A room number on several floors is taken on the robot's floor when it is there, else on the
// first floor (building order) with a route. ROS-free.
// Frames: each floor's map frame (robot pose and goal poses on their floor's map); metres, radians.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "doorplate_localization/behaviour/grid_path_planner.h"
#include "doorplate_localization/behaviour/room_goal_planner.h"
#include "doorplate_localization/maps/building_map.h"

namespace doorplate_localization {

struct BuildingRouteOptions {
  GridPathPlannerOptions planner;
  RoomGoalPlannerOptions room;
};

struct BuildingRoute {
  int robot_floor = -1;   // index into BuildingMaps::floors
  int room_floor = -1;
  RoomGoal goal;          // on room_floor's map
  bool via_lift = false;  // room_floor != robot_floor
  std::string lift;       // via_lift: the lift's id
  Pose2D lift_stop_here;  // via_lift: its stop on the robot's floor (wait there, facing the door)
  Pose2D lift_stop_there; // via_lift: its stop on the room's floor (where the ride ends)
  double length_m = 0.0;  // planned path length on both floors
  // What to tell a person: "room 305 is on floor 3: take lift A from floor 2 to floor 3 (wait at
  // (23.00, 28.80) on floor 2)", or "room 205 is on this floor (2)".
  std::string instruction;
};

struct BuildingRouteResult {
  std::optional<BuildingRoute> route;
  std::string refusal;  // set exactly when !route: the room on no floor, no lift between the floors, no path
};

class BuildingRoutePlanner {
 public:
  // Builds a planner per floor. Throws std::invalid_argument naming the field of a bad option, or a floor
  // without a text map ("floor '3': no text map").
  BuildingRoutePlanner(const BuildingRouteOptions& options, std::shared_ptr<const BuildingMaps> maps);

  // The route from `robot_in_map` on floor `robot_floor` to room `request` (RoomGoalPlanner requests:
  // "214", "220@north").
  BuildingRouteResult Plan(const std::string& request, int robot_floor, const Pose2D& robot_in_map) const;

  const BuildingMaps& maps() const { return *maps_; }
  const RoomGoalPlanner& rooms(int floor) const { return rooms_[static_cast<size_t>(floor)]; }

 private:
  // The route to `goal` on `room_floor` via `lift` (its stops on both floors), or a failure reason.
  std::optional<BuildingRoute> ViaLift(const Lift& lift, int robot_floor, const Pose2D& robot, int room_floor,
                                       const RoomGoal& goal, std::string* failure) const;

  const std::shared_ptr<const BuildingMaps> maps_;
  std::vector<GridPathPlanner> planners_;
  std::vector<RoomGoalPlanner> rooms_;
};

}  // namespace doorplate_localization

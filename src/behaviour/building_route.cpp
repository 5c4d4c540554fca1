#include "doorplate_localization/behaviour/building_route.h"

#include <cstdio>
#include <stdexcept>
#include <utility>

namespace doorplate_localization {
namespace {

std::string FloorName(const BuildingMaps& maps, int floor) { return maps.floors[static_cast<size_t>(floor)].id; }

}  // namespace

BuildingRoutePlanner::BuildingRoutePlanner(const BuildingRouteOptions& options, std::shared_ptr<const BuildingMaps> maps)
    : maps_(std::move(maps)) {
  if (!maps_ || maps_->floors.empty()) throw std::invalid_argument("BuildingRoutePlanner: the building has no floor");
  for (const FloorMaps& floor : maps_->floors) {
    if (!floor.text_map) throw std::invalid_argument("BuildingRoutePlanner: floor '" + floor.id + "': no text map");
    planners_.emplace_back(options.planner, floor.grid);
    rooms_.emplace_back(options.room, *floor.text_map, "the text map of floor " + floor.id);
  }
}

std::optional<BuildingRoute> BuildingRoutePlanner::ViaLift(const Lift& lift, int robot_floor, const Pose2D& robot,
                                                           int room_floor, const RoomGoal& goal,
                                                           std::string* failure) const {
  const LiftStop* here = lift.StopOn(FloorName(*maps_, robot_floor));
  const LiftStop* there = lift.StopOn(FloorName(*maps_, room_floor));
  if (here == nullptr || there == nullptr) return std::nullopt;
  const GridPath to_lift = planners_[static_cast<size_t>(robot_floor)].Plan(robot.Position(), here->pose.Position());
  const GridPath from_lift = planners_[static_cast<size_t>(room_floor)].Plan(there->pose.Position(), goal.pose.Position());
  if (!to_lift.found || !from_lift.found) {
    *failure = "lift " + lift.id + ": " + (to_lift.found ? "from its stop on floor " + FloorName(*maps_, room_floor) +
                                                                ": " + from_lift.failure
                                                          : "to its stop: " + to_lift.failure);
    return std::nullopt;
  }
  BuildingRoute route;
  route.robot_floor = robot_floor;
  route.room_floor = room_floor;
  route.goal = goal;
  route.via_lift = true;
  route.lift = lift.id;
  route.lift_stop_here = here->pose;
  route.lift_stop_there = there->pose;
  route.length_m = to_lift.length_m + from_lift.length_m;
  char text[256];
  std::snprintf(text, sizeof(text), "room %s is on floor %s: take lift %s from floor %s to floor %s (wait at (%.2f, %.2f) on floor %s)",
                goal.room.c_str(), FloorName(*maps_, room_floor).c_str(), lift.id.c_str(),
                FloorName(*maps_, robot_floor).c_str(), FloorName(*maps_, room_floor).c_str(), here->pose.x_m,
                here->pose.y_m, FloorName(*maps_, robot_floor).c_str());
  route.instruction = text;
  return route;
}

BuildingRouteResult BuildingRoutePlanner::Plan(const std::string& request, int robot_floor,
                                               const Pose2D& robot_in_map) const {
  BuildingRouteResult result;
  if (robot_floor < 0 || robot_floor >= static_cast<int>(maps_->floors.size())) {
    result.refusal = "no floor index " + std::to_string(robot_floor) + " in building " + maps_->name;
    return result;
  }
  // On the robot's floor first (a refusal there, e.g. an ambiguous number, is final).
  const RoomGoalResult here = rooms_[static_cast<size_t>(robot_floor)].Plan(request, robot_in_map);
  if (!here.goal && !rooms_[static_cast<size_t>(robot_floor)].Candidates(request).landmarks.empty()) {
    result.refusal = here.refusal;
    return result;
  }
  if (here.goal) {
    const GridPath path = planners_[static_cast<size_t>(robot_floor)].Plan(robot_in_map.Position(), here.goal->pose.Position());
    if (!path.found) {
      result.refusal = "room " + here.goal->room + " on floor " + FloorName(*maps_, robot_floor) + ": " + path.failure;
      return result;
    }
    BuildingRoute route;
    route.robot_floor = route.room_floor = robot_floor;
    route.goal = *here.goal;
    route.length_m = path.length_m;
    route.instruction = "room " + here.goal->room + " is on this floor (" + FloorName(*maps_, robot_floor) + ")";
    result.route = route;
    return result;
  }
  std::string failures;
  bool on_some_floor = false;
  for (int floor = 0; floor < static_cast<int>(maps_->floors.size()); ++floor) {
    if (floor == robot_floor) continue;
    // Where the ride ends is where a repeated room number is resolved from: the nearest to the lift.
    const RoomCandidates candidates = rooms_[static_cast<size_t>(floor)].Candidates(request);
    if (candidates.landmarks.empty()) continue;
    on_some_floor = true;
    std::optional<BuildingRoute> best;
    for (const Lift& lift : maps_->lifts) {
      const LiftStop* there = lift.StopOn(FloorName(*maps_, floor));
      if (there == nullptr || lift.StopOn(FloorName(*maps_, robot_floor)) == nullptr) continue;
      const RoomGoalResult goal = rooms_[static_cast<size_t>(floor)].Plan(request, there->pose);
      if (!goal.goal) {
        failures += (failures.empty() ? "" : "; ") + goal.refusal;
        continue;
      }
      std::string failure;
      std::optional<BuildingRoute> route = ViaLift(lift, robot_floor, robot_in_map, floor, *goal.goal, &failure);
      if (!route) {
        if (!failure.empty()) failures += (failures.empty() ? "" : "; ") + failure;
        continue;
      }
      if (!best || route->length_m < best->length_m) best = std::move(route);
    }
    if (best) {
      result.route = best;
      return result;
    }
    if (failures.empty()) {
      failures = "no lift stops on floors " + FloorName(*maps_, robot_floor) + " and " + FloorName(*maps_, floor);
    }
  }
  if (!on_some_floor) {
    result.refusal = here.refusal + " (nor on any other floor of building " + maps_->name + ")";
  } else {
    result.refusal = "room " + request + ": no route from floor " + FloorName(*maps_, robot_floor) + ": " + failures;
  }
  return result;
}

}  // namespace doorplate_localization

#include "building_goal.h"

#include <stdexcept>
#include <utility>

namespace doorplate_localization {

BuildingGoal::BuildingGoal(const BuildingRouteOptions& options, std::shared_ptr<const BuildingMaps> maps)
    : routes_(std::make_unique<const BuildingRoutePlanner>(options, std::move(maps))) {}

std::string BuildingGoal::Start(const std::string& request) {
  Cancel();
  request_ = request;
  const BuildingMaps& maps = routes_->maps();
  std::string floors;
  for (size_t f = 0; f < maps.floors.size(); ++f) {
    if (!routes_->rooms(static_cast<int>(f)).Candidates(request).landmarks.empty()) {
      phase_ = BuildingGoalPhase::kLocalizing;
      return "";
    }
    floors += (floors.empty() ? "" : ", ") + maps.floors[f].id;
  }
  phase_ = BuildingGoalPhase::kDone;
  const std::string refusal =
      "room " + request + " is on no floor of building " + maps.name + " (floors: " + floors + ")";
  end_status_ = "refused: " + refusal;
  return refusal;
}

void BuildingGoal::Cancel() {
  phase_ = BuildingGoalPhase::kIdle;
  route_.reset();
  ride_floor_.clear();
  leg_floor_ = -1;
  end_status_.clear();
}

bool BuildingGoal::TryStartLeg(const std::optional<Pose2D>& pose) {
  const std::string& floor = localizer_floor_;
  if (phase_ != BuildingGoalPhase::kLocalizing || localizer_state_ != "converged" || !pose) return false;
  const int robot_floor = routes_->maps().FloorIndex(floor);
  if (robot_floor < 0 || (!ride_floor_.empty() && floor != ride_floor_)) {
    phase_ = BuildingGoalPhase::kDone;
    end_status_ = "failed: room " + request_ + ": the localizer converged on floor " + floor +
                  (robot_floor < 0 ? ", which building " + routes_->maps().name + " does not have"
                                   : ", not on floor " + ride_floor_ + " where the lift went");
    return false;
  }
  const BuildingRouteResult result = routes_->Plan(request_, robot_floor, *pose);
  if (!result.route) {
    phase_ = BuildingGoalPhase::kDone;
    end_status_ = "refused: " + result.refusal;
    return false;
  }
  route_ = result.route;
  if (route_->via_lift) {
    RoomGoal stop;
    stop.room = "lift " + route_->lift;
    stop.pose = route_->lift_stop_here;
    StartLeg(robot_floor, stop, BuildingGoalPhase::kToLift);
  } else {
    StartLeg(route_->room_floor, route_->goal, BuildingGoalPhase::kToRoom);
  }
  return true;
}

void BuildingGoal::StartLeg(int floor, const RoomGoal& goal, BuildingGoalPhase phase) {
  leg_floor_ = floor;
  leg_ = goal;
  phase_ = phase;
}

void BuildingGoal::OnLegEnded(bool arrived, const std::string& leg_status) {
  if (phase_ != BuildingGoalPhase::kToLift && phase_ != BuildingGoalPhase::kToRoom) return;
  if (phase_ == BuildingGoalPhase::kToLift && arrived) {
    phase_ = BuildingGoalPhase::kWaitingForLift;
    return;
  }
  phase_ = BuildingGoalPhase::kDone;
  end_status_ = leg_status;
}

bool BuildingGoal::OnRide(const std::string& ride_text, std::string* problem) {
  LiftRideRequest ride;
  *problem = ParseLiftRide(ride_text, &ride);
  if (!problem->empty()) return false;
  if (phase_ != BuildingGoalPhase::kWaitingForLift) {
    *problem = "not waiting for a lift";
    return false;
  }
  const std::string& room_floor = routes_->maps().floors[static_cast<size_t>(route_->room_floor)].id;
  if (ride.lift != route_->lift) {  // another lift's stop is elsewhere: that ride did not carry this robot
    *problem = "the robot waits for lift " + route_->lift + ", not " + ride.lift;
    return false;
  }
  if (ride.floor != room_floor) {
    *problem = "room " + route_->goal.room + " is on floor " + room_floor + ", not " + ride.floor;
    return false;
  }
  ride_floor_ = ride.floor;
  ride_lift_ = ride.lift;
  localizer_state_.clear();  // what the localizer said before the ride no longer holds
  phase_ = BuildingGoalPhase::kLocalizing;
  return true;
}

std::string BuildingGoal::Status() const {
  const std::string localizer = " (localizer: floor " + (localizer_floor_.empty() ? "?" : localizer_floor_) + ", " +
                                (localizer_state_.empty() ? "?" : localizer_state_) + ")";
  switch (phase_) {
    case BuildingGoalPhase::kIdle:
      return "idle";
    case BuildingGoalPhase::kLocalizing:
      if (ride_floor_.empty()) {
        return "localizing: room " + request_ + ": searching for plates until the localizer has converged" + localizer;
      }
      return "localizing: room " + request_ + ": rode lift " + ride_lift_ + " to floor " + ride_floor_ +
             "; searching for plates until the localizer has converged on floor " + ride_floor_ + localizer;
    case BuildingGoalPhase::kToLift:
      return "to_lift: " + route_->instruction;
    case BuildingGoalPhase::kWaitingForLift:
      return "waiting_for_lift: waiting for lift " + route_->lift + " to floor " +
             routes_->maps().floors[static_cast<size_t>(route_->room_floor)].id + " (room " + route_->goal.room +
             ") at its stop on floor " + routes_->maps().floors[static_cast<size_t>(route_->robot_floor)].id;
    case BuildingGoalPhase::kToRoom:
      return "to_room: " + route_->instruction;
    case BuildingGoalPhase::kDone:
      return end_status_;
  }
  return "idle";
}

}  // namespace doorplate_localization

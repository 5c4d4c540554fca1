#include "doorplate_localization/ros/lift_ride.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace doorplate_localization {

std::string ParseLiftRide(const std::string& text, LiftRideRequest* ride) {
  std::istringstream words(text);
  LiftRideRequest parsed;
  std::string extra;
  if (!(words >> parsed.lift >> parsed.floor) || (words >> extra)) {
    return "expected '<lift id> <floor id>', e.g. 'A 3', got '" + text + "'";
  }
  *ride = parsed;
  return "";
}

std::string PlanLiftRide(const BuildingFile& building, const LiftRideRequest& ride, const std::string& robot_floor,
                         const Pose2D& robot, double max_distance_m, int* floor, Pose2D* pose) {
  const Lift* lift = nullptr;
  std::string lifts;
  for (const Lift& l : building.lifts) {
    if (l.id == ride.lift) lift = &l;
    lifts += (lifts.empty() ? "" : ", ") + l.id;
  }
  if (lift == nullptr) {
    return "no lift '" + ride.lift + "' in building " + building.name + " (" +
           (lifts.empty() ? std::string("it has none") : "lifts: " + lifts) + ")";
  }
  const int to = building.FloorIndex(ride.floor);
  if (to < 0) {
    std::string floors;
    for (const BuildingFloor& f : building.floors) floors += (floors.empty() ? "" : ", ") + f.id;
    return "no floor '" + ride.floor + "' in building " + building.name + " (floors: " + floors + ")";
  }
  if (ride.floor == robot_floor) return "the robot is on floor " + robot_floor + " already";
  const LiftStop* here = lift->StopOn(robot_floor);
  const LiftStop* there = lift->StopOn(ride.floor);
  if (here == nullptr || there == nullptr) {
    return "lift " + lift->id + " does not stop on floor " + (here == nullptr ? robot_floor : ride.floor);
  }
  const double distance_m = Norm(robot.Position() - here->pose.Position());
  if (distance_m > max_distance_m) {
    char text[200];
    std::snprintf(text, sizeof(text), "the robot is %.2f m from the stop of lift %s on floor %s at (%.2f, %.2f); "
                  "it rides only within %.2f m", distance_m, lift->id.c_str(), robot_floor.c_str(), here->pose.x_m,
                  here->pose.y_m, max_distance_m);
    return text;
  }
  *floor = to;
  *pose = Pose2D{there->pose.x_m, there->pose.y_m, NormalizeAngle(there->pose.theta_rad + M_PI)};
  return "";
}

}  // namespace doorplate_localization

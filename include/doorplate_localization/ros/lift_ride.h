// The ride_lift message (std_msgs/String "<lift id> <floor id>", e.g. "A 3": the robot rides lift A to floor
// 3), shared by the simulator, which carries the robot, and go-to-room, which waits for the ride (library
// doorplate_ros_conversions). Pure functions. Frames: each floor's map/world frame; metres, radians.
#pragma once

#include <string>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/building_map.h"

namespace doorplate_localization {

struct LiftRideRequest {
  std::string lift;   // a Lift::id
  std::string floor;  // the floor it goes to (a BuildingFloor::id)
};

// Returns "" and fills *ride from the message's text, or what is wrong ("expected '<lift id> <floor id>',
// e.g. 'A 3', got 'A'"); *ride is left alone on error. Blanks around and between the two words are ignored.
std::string ParseLiftRide(const std::string& text, LiftRideRequest* ride);

// Where the ride `ride` ends for a robot at `robot` (pose in the frame of floor `robot_floor`): the lift's stop
// on the ride's floor, turned to face away from the lift door (a stop faces the door). Returns "" and fills
// *floor (index into building.floors) and *pose, or why the ride cannot happen: no such lift or floor (naming
// the building's), the lift does not stop on the robot's floor or on the ride's, the robot is already on that
// floor, or it is more than max_distance_m from the lift's stop on its floor.
std::string PlanLiftRide(const BuildingFile& building, const LiftRideRequest& ride, const std::string& robot_floor,
                         const Pose2D& robot, double max_distance_m, int* floor, Pose2D* pose);

}  // namespace doorplate_localization

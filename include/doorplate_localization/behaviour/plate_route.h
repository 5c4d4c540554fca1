// The odometry fallback of go-to-room (paper Sec. 3.4, eq. 15): when the localizer has not converged but the
// robot has just read plate i, the distance it has to drive along the wall to plate j is the sum of the
// adjacent distances between them (eq. 13, Dist(k,k+1) = u(k+1) - u(k), stored in TextMap::adjacent):
//   sum_{k=i}^{j-1} Dist(k,k+1)  (i < j),   sum_{k=j}^{i-1} Dist(k,k+1)  (j < i),
// driven by odometry. The goal is therefore expressed in the odom frame, relative to where the robot was
// when it read plate i.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "doorplate_localization/behaviour/room_goal_planner.h"
#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/text_map.h"

namespace doorplate_localization {

// A chain of adjacent plates from one landmark to another.
struct PlateRoute {
  double distance_m = 0.0;   // eq. 15: the sum of the chain's adjacent distances, metres, >= 0
  std::vector<int> plates;   // landmark indexes from the start to the target, both included
  std::string source;        // "odometry", "map" or "mixed": which adjacent distances were summed ("none": from == to)
};

// The route along adjacent distances from landmark `from` to landmark `to`. For a pair listed with both
// sources the "odometry" distance is used (measured while mapping, what the robot's odometry will see);
// otherwise "map". nullopt, with `*reason` set, when no chain of adjacent distances links the two plates
// (different walls, or a map without `adjacent`). Throws std::out_of_range for an invalid index.
std::optional<PlateRoute> AdjacentRoute(const TextMap& map, int from, int to, std::string* reason);

// The plate the robot has just read, matched to a landmark of the map (the raw reading is
// sensors/plate_reading.h's PlateReading): the moment its reading crossed the camera's image centre.
struct MatchedPlateReading {
  int landmark = -1;          // index into TextMap::landmarks of the plate read
  Pose2D odom_pose;           // base_link in the odom frame at that moment
  bool plate_on_left = true;  // the plate was on the robot's left (a left-looking camera), else on its right
};

// The eq. 15 goal for `request` in the ODOM frame. The robot's travel direction when it read the plate is
// known from the map (the read plate's facing direction and the side it was seen on), so the target lies
// ahead (+) or behind (−) it; the goal is odom_pose advanced by ±route distance along odom_pose's heading,
// facing the plates' wall (theta = heading ± pi/2 towards the read plate's side). Only the goal's position
// along that heading and its theta are meaningful (GoToRoom uses only those); its lateral position is the
// robot's line at the reading. The target must be linked to the read plate by adjacent distances (same
// wall); among several plates of the room number the shortest route is taken (duplicate_rule "nearest") or
// the request is refused ("refuse"). `goal->note` states the route (plates and metres).
RoomGoalResult PlanFromReading(const RoomGoalPlanner& planner, const std::string& request,
                               const MatchedPlateReading& reading);

}  // namespace doorplate_localization

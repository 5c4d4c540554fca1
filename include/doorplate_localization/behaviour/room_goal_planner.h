// Where to stop for a room (paper Sec. 3.4, Fig. 8): "the robot computes the target room position in the
// grid map and moves forward to the place". Given the text map (docs/text-map-format.md) and a requested
// room number, the planner returns the goal pose in the map frame: in front of the room's doorplate, at the
// wall-following distance from the plate's wall, facing the door. Requests it cannot serve are refused with
// a message naming the room, the text map file and the rooms it knows.
//
// Requests: "<room>" (e.g. "105"), or "<room>@<wall>" (e.g. "220@north") to pick one plate of a room number
// that the map holds more than once (the `wall` label of the landmark). Surrounding whitespace is ignored.
// Room numbers are compared in canonical form (common/room_id.h, TextMap::Find): "E14-295", "E14295" and
// "e14 295" reach the same plate; look-alikes ("312A"/"312B", "32-076"/"32-069T") stay apart.
//
// Repeated room numbers: duplicate_rule "nearest" goes to the plate closest (straight line, map frame) to
// the robot's current pose and says which plates there were; "refuse" refuses and lists the plates with the
// "<room>@<wall>" requests that select them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/text_map.h"

namespace doorplate_localization {

struct RoomGoalPlannerOptions {
  double wall_distance_m = 0.6;             // goal distance from the plate's wall (the follower's d_wall)
  std::string duplicate_rule = "nearest";   // "nearest" or "refuse" (above)
};

// A goal for one room. `pose` is base_link's goal pose in the text map's frame (metres, radians):
// plate position + wall_distance_m along the plate's facing direction, theta = the plate's yaw + pi (the
// robot looks at the door; the plate faces the corridor).
struct RoomGoal {
  std::string room;     // the room number as asked for (without "@wall"; the plate's text may be spelled otherwise)
  int landmark = -1;    // index into TextMap::landmarks of the chosen plate
  Pose2D pose;
  std::string note;     // how a repeated room number was resolved, "" otherwise
};

// Either a goal or the reason there is none.
struct RoomGoalResult {
  std::optional<RoomGoal> goal;
  std::string refusal;  // set exactly when !goal, e.g. "room 999 is not in the text map maps/x.yaml; known rooms: 101, 102"
};

// The plates a request names, or why it names none.
struct RoomCandidates {
  std::string room;
  std::vector<int> landmarks;  // indexes into TextMap::landmarks, ascending; empty on refusal
  std::string refusal;
};

class RoomGoalPlanner {
 public:
  // `map_name` (normally the text map's file path) is quoted in refusals. Throws std::invalid_argument
  // naming the field of an invalid option.
  RoomGoalPlanner(const RoomGoalPlannerOptions& options, TextMap map, std::string map_name);

  // Every plate the request can mean (all plates of the room number, or the one on the named wall).
  RoomCandidates Candidates(const std::string& request) const;

  // The goal for `request`. `robot_in_map` (base_link in the map frame) resolves repeated room numbers
  // under the "nearest" rule; without it a repeated number is refused like under "refuse".
  RoomGoalResult Plan(const std::string& request, const std::optional<Pose2D>& robot_in_map) const;

  // The goal pose in front of landmark `index` (see RoomGoal::pose).
  Pose2D GoalPoseOf(int index) const;

  // "#3 '220' on wall north at (26.7, 2.2)": how refusals and notes name a plate.
  std::string DescribePlate(int index) const;

  const TextMap& map() const { return map_; }
  const std::string& map_name() const { return map_name_; }
  const RoomGoalPlannerOptions& options() const { return options_; }

 private:
  std::string DuplicateList(const std::vector<int>& landmarks) const;

  const RoomGoalPlannerOptions options_;
  const TextMap map_;
  const std::string map_name_;
};

}  // namespace doorplate_localization

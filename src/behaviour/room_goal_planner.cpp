#include "doorplate_localization/behaviour/room_goal_planner.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

namespace doorplate_localization {
namespace {

std::string Trim(const std::string& s) {
  const char* space = " \t\r\n";
  const size_t first = s.find_first_not_of(space);
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(space) - first + 1);
}

std::string Join(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

}  // namespace

RoomGoalPlanner::RoomGoalPlanner(const RoomGoalPlannerOptions& options, TextMap map, std::string map_name)
    : options_(options), map_(std::move(map)), map_name_(std::move(map_name)) {
  if (!(std::isfinite(options.wall_distance_m) && options.wall_distance_m > 0)) {
    throw std::invalid_argument("RoomGoalPlannerOptions.wall_distance_m: must be finite and > 0");
  }
  if (options.duplicate_rule != "nearest" && options.duplicate_rule != "refuse") {
    throw std::invalid_argument("RoomGoalPlannerOptions.duplicate_rule: must be 'nearest' or 'refuse', got '" +
                                options.duplicate_rule + "'");
  }
}

std::string RoomGoalPlanner::DescribePlate(int index) const {
  const TextLandmark& plate = map_.landmarks.at(static_cast<size_t>(index));
  char where[96];
  std::snprintf(where, sizeof(where), " at (%.2f, %.2f)", plate.pose.x_m, plate.pose.y_m);
  return "#" + std::to_string(index) + " '" + plate.text + "'" +
         (plate.wall.empty() ? std::string(" on an unlabelled wall") : " on wall " + plate.wall) + where;
}

std::string RoomGoalPlanner::DuplicateList(const std::vector<int>& landmarks) const {
  std::vector<std::string> plates;
  for (const int i : landmarks) plates.push_back(DescribePlate(i));
  return Join(plates);
}

RoomCandidates RoomGoalPlanner::Candidates(const std::string& request) const {
  RoomCandidates out;
  const std::string trimmed = Trim(request);
  const size_t at = trimmed.find('@');
  out.room = Trim(trimmed.substr(0, at));
  const std::string wall = at == std::string::npos ? "" : Trim(trimmed.substr(at + 1));
  if (out.room.empty()) {
    out.refusal = "empty room number in request '" + request + "'; known rooms: " + Join(map_.Texts());
    return out;
  }
  const std::vector<int> all = map_.Find(out.room);
  if (all.empty()) {
    out.refusal = "room " + out.room + " is not in the text map " + map_name_ + "; known rooms: " + Join(map_.Texts());
    return out;
  }
  if (at == std::string::npos) {
    out.landmarks = all;
    return out;
  }
  for (const int i : all) {
    if (map_.landmarks[static_cast<size_t>(i)].wall == wall) out.landmarks.push_back(i);
  }
  if (out.landmarks.empty()) {
    out.refusal = "room " + out.room + " has no plate on wall '" + wall + "' in the text map " + map_name_ +
                  "; its plates: " + DuplicateList(all);
  }
  return out;
}

Pose2D RoomGoalPlanner::GoalPoseOf(int index) const {
  const Pose2D& plate = map_.landmarks.at(static_cast<size_t>(index)).pose;
  return {plate.x_m + options_.wall_distance_m * std::cos(plate.theta_rad),
          plate.y_m + options_.wall_distance_m * std::sin(plate.theta_rad), NormalizeAngle(plate.theta_rad + M_PI)};
}

RoomGoalResult RoomGoalPlanner::Plan(const std::string& request, const std::optional<Pose2D>& robot_in_map) const {
  RoomGoalResult result;
  const RoomCandidates candidates = Candidates(request);
  if (candidates.landmarks.empty()) {
    result.refusal = candidates.refusal;
    return result;
  }
  RoomGoal goal;
  goal.room = candidates.room;
  goal.landmark = candidates.landmarks.front();
  if (candidates.landmarks.size() > 1) {
    const std::string plates = "room " + goal.room + " is on " + std::to_string(candidates.landmarks.size()) +
                               " plates: " + DuplicateList(candidates.landmarks);
    if (options_.duplicate_rule == "refuse" || !robot_in_map) {
      std::vector<std::string> requests;
      for (const int i : candidates.landmarks) {
        const std::string& wall = map_.landmarks[static_cast<size_t>(i)].wall;
        if (!wall.empty()) requests.push_back("'" + goal.room + "@" + wall + "'");
      }
      result.refusal = plates + (robot_in_map ? "" : "; the robot's pose is unknown, so the nearest cannot be chosen") +
                       "; ask for one of them" + (requests.empty() ? "" : ": " + Join(requests));
      return result;
    }
    double best = std::numeric_limits<double>::infinity();
    for (const int i : candidates.landmarks) {
      const double d = Norm(GoalPoseOf(i).Position() - robot_in_map->Position());
      if (d < best) {
        best = d;
        goal.landmark = i;
      }
    }
    goal.note = plates + "; going to the nearest, " + DescribePlate(goal.landmark);
  }
  goal.pose = GoalPoseOf(goal.landmark);
  result.goal = goal;
  return result;
}

}  // namespace doorplate_localization

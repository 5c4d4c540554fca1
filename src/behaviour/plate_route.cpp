#include "doorplate_localization/behaviour/plate_route.h"

#include <cmath>
#include <cstdio>
#include <deque>
#include <map>
#include <stdexcept>
#include <utility>

namespace doorplate_localization {
namespace {

struct Link {
  double distance_m = 0.0;
  bool odometry = false;
};

}  // namespace

std::optional<PlateRoute> AdjacentRoute(const TextMap& map, int from, int to, std::string* reason) {
  const int n = static_cast<int>(map.landmarks.size());
  if (from < 0 || from >= n || to < 0 || to >= n) {
    throw std::out_of_range("AdjacentRoute: landmark index out of range (" + std::to_string(from) + ", " +
                            std::to_string(to) + "; the map has " + std::to_string(n) + ")");
  }
  // One link per unordered pair; an odometry distance replaces a map one.
  std::map<std::pair<int, int>, Link> links;
  std::vector<std::vector<int>> neighbours(static_cast<size_t>(n));
  for (const AdjacentDistance& a : map.adjacent) {
    const std::pair<int, int> key{std::min(a.from, a.to), std::max(a.from, a.to)};
    const bool odometry = a.source == "odometry";
    auto [it, inserted] = links.emplace(key, Link{a.distance_m, odometry});
    if (inserted) {
      neighbours[static_cast<size_t>(a.from)].push_back(a.to);
      neighbours[static_cast<size_t>(a.to)].push_back(a.from);
    } else if (odometry && !it->second.odometry) {
      it->second = Link{a.distance_m, true};
    }
  }
  // Breadth-first: along one wall the chain is a path, so this is the chain between the two plates.
  std::vector<int> previous(static_cast<size_t>(n), -2);
  previous[static_cast<size_t>(from)] = -1;
  std::deque<int> queue{from};
  while (!queue.empty() && previous[static_cast<size_t>(to)] == -2) {
    const int k = queue.front();
    queue.pop_front();
    for (const int m : neighbours[static_cast<size_t>(k)]) {
      if (previous[static_cast<size_t>(m)] != -2) continue;
      previous[static_cast<size_t>(m)] = k;
      queue.push_back(m);
    }
  }
  if (previous[static_cast<size_t>(to)] == -2) {
    if (reason) {
      const std::string& wf = map.landmarks[static_cast<size_t>(from)].wall;
      const std::string& wt = map.landmarks[static_cast<size_t>(to)].wall;
      *reason = "no chain of adjacent distances links plate #" + std::to_string(from) + " (wall '" + wf +
                "') to plate #" + std::to_string(to) + " (wall '" + wt + "')" +
                (wf != wt ? ": they are on different walls" : "");
    }
    return std::nullopt;
  }
  PlateRoute route;
  int odometry_links = 0, links_used = 0;
  for (int k = to; k != -1; k = previous[static_cast<size_t>(k)]) route.plates.insert(route.plates.begin(), k);
  for (size_t i = 1; i < route.plates.size(); ++i) {
    const int a = route.plates[i - 1], b = route.plates[i];
    const Link& link = links.at({std::min(a, b), std::max(a, b)});
    route.distance_m += link.distance_m;
    odometry_links += link.odometry ? 1 : 0;
    ++links_used;
  }
  route.source = links_used == 0                ? "none"
                 : odometry_links == links_used ? "odometry"
                 : odometry_links == 0          ? "map"
                                                : "mixed";
  return route;
}

RoomGoalResult PlanFromReading(const RoomGoalPlanner& planner, const std::string& request,
                               const MatchedPlateReading& reading) {
  RoomGoalResult result;
  const TextMap& map = planner.map();
  const RoomCandidates candidates = planner.Candidates(request);
  if (candidates.landmarks.empty()) {
    result.refusal = candidates.refusal;
    return result;
  }
  std::vector<std::pair<int, PlateRoute>> reachable;
  std::string reasons;
  for (const int target : candidates.landmarks) {
    std::string reason;
    if (const std::optional<PlateRoute> route = AdjacentRoute(map, reading.landmark, target, &reason)) {
      reachable.emplace_back(target, *route);
    } else {
      reasons += (reasons.empty() ? "" : "; ") + reason;
    }
  }
  const std::string from = "the plate just read, " + planner.DescribePlate(reading.landmark);
  if (reachable.empty()) {
    result.refusal = "room " + candidates.room + " cannot be reached by odometry (eq. 15) from " + from + ": " + reasons;
    return result;
  }
  if (reachable.size() > 1 && planner.options().duplicate_rule == "refuse") {
    result.refusal = "room " + candidates.room + " is on " + std::to_string(reachable.size()) +
                     " plates reachable from " + from + "; ask for one of them as '<room>@<wall>'";
    return result;
  }
  size_t best = 0;
  for (size_t i = 1; i < reachable.size(); ++i) {
    if (reachable[i].second.distance_m < reachable[best].second.distance_m) best = i;
  }
  const auto& [target, route] = reachable[best];
  // The heading in the map when the plate was read: along the wall, with the plate on the seen side.
  const TextLandmark& read = map.landmarks[static_cast<size_t>(reading.landmark)];
  const double side = reading.plate_on_left ? 1.0 : -1.0;
  const double map_heading = read.pose.theta_rad + side * M_PI / 2;
  const Vec2 to_target = map.landmarks[static_cast<size_t>(target)].pose.Position() - read.pose.Position();
  const double direction = Dot({std::cos(map_heading), std::sin(map_heading)}, to_target) >= 0.0 ? 1.0 : -1.0;
  const Pose2D& start = reading.odom_pose;
  RoomGoal goal;
  goal.room = candidates.room;
  goal.landmark = target;
  goal.pose = {start.x_m + direction * route.distance_m * std::cos(start.theta_rad),
               start.y_m + direction * route.distance_m * std::sin(start.theta_rad),
               NormalizeAngle(start.theta_rad + side * M_PI / 2)};
  char metres[64];
  std::snprintf(metres, sizeof(metres), "%.2f m %s", route.distance_m, direction > 0 ? "ahead" : "behind");
  std::string chain;
  for (const int k : route.plates) chain += (chain.empty() ? "#" : " -> #") + std::to_string(k);
  goal.note = "eq. 15 from " + from + ": " + metres + " (" + route.source + " adjacent distances " + chain + ")";
  result.goal = goal;
  return result;
}

}  // namespace doorplate_localization

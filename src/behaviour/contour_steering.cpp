#include "doorplate_localization/behaviour/contour_steering.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {
namespace {

constexpr double kDeg = M_PI / 180.0;

void Require(bool ok, const char* field, const char* rule) {
  if (!ok) throw std::invalid_argument(std::string("ContourSteeringOptions.") + field + ": " + rule);
}

// Squared distance from p to the segment a→b.
double SquaredDistanceToSegment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = Dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(Dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  const Vec2 d = p - (a + t * ab);
  return Dot(d, d);
}

}  // namespace

ContourSteering::ContourSteering(const ContourSteeringOptions& o)
    : options_(o), side_sign_(o.wall_side == "left" ? 1.0 : -1.0) {
  Require(o.wall_side == "left" || o.wall_side == "right", "wall_side", "must be 'left' or 'right'");
  Require(o.wall_distance_m > 0, "wall_distance_m", "must be > 0");
  Require(o.min_look_ahead_m > 0, "min_look_ahead_m", "must be > 0");
  CheckIsolatedReturnOptions(o.isolated_returns, "ContourSteeringOptions.isolated_returns.");
  Require(o.look_ahead_m >= o.min_look_ahead_m, "look_ahead_m", "must be >= min_look_ahead_m");
  Require(o.robot_clearance_m > 0 && o.robot_clearance_m <= o.wall_distance_m, "robot_clearance_m",
          "must be in (0, wall_distance_m]");
  Require(o.angle_step_deg > 0 && o.angle_step_deg <= 10, "angle_step_deg", "must be in (0, 10]");
  Require(o.max_range_m >= o.look_ahead_m + o.wall_distance_m, "max_range_m",
          "must be >= look_ahead_m + wall_distance_m (returns that can block a target)");
  Require(o.cruise_speed_mps > 0, "cruise_speed_mps", "must be > 0");
  Require(o.max_angular_speed_rps > 0, "max_angular_speed_rps", "must be > 0");
  Require(o.rotate_in_place_deg > 0 && o.rotate_in_place_deg < 180, "rotate_in_place_deg", "must be in (0, 180)");
  Require(o.min_speed_fraction > 0 && o.min_speed_fraction <= 1, "min_speed_fraction", "must be in (0, 1]");
}

ContourSteeringResult ContourSteering::Step(const std::vector<float>& ranges_m, double angle_min_rad,
                                            double angle_increment_rad) const {
  const ContourSteeringOptions& o = options_;
  // Returns in a frame mirrored for the left wall, so the followed wall is always on the right (y < 0).
  std::vector<Vec2> points;
  points.reserve(ranges_m.size());
  const double reach = o.look_ahead_m + o.wall_distance_m;
  const double behind_reach = o.wall_distance_m + o.robot_clearance_m;
  ContourSteeringResult result;
  double front_m = o.max_range_m;  // nearest return ahead within the robot's lane
  for (std::size_t i = 0; i < ranges_m.size(); ++i) {
    const double r = ranges_m[i];
    if (!std::isfinite(r) || r <= 0.0 || r > o.max_range_m) continue;
    const double a = angle_min_rad + static_cast<double>(i) * angle_increment_rad;
    const Vec2 p{r * std::cos(a), -side_sign_ * r * std::sin(a)};
    // The followed wall: a return on its side within reach beside or ahead, or behind within the distance the
    // robot keeps while it rounds a wall's end. A wall farther behind is one the robot has left (it stood with
    // its back to it, as at a lift's door): steering for it from the perpendicular circles on the spot.
    // (Isolated returns count: glass returns a beam here and there.)
    if (p.y < 0 && r <= (p.x >= 0 ? reach : behind_reach)) result.wall_found = true;
    if (IsIsolatedReturn(ranges_m, i, o.isolated_returns)) continue;  // no obstacle: blocks no target
    points.push_back(p);
    if (p.x > 0 && std::fabs(p.y) <= o.robot_clearance_m) front_m = std::min(front_m, p.x);
  }
  // Towards a wall ahead the targets come closer, so the robot turns near it, not a look-ahead early.
  result.look_ahead_m = std::clamp(front_m - o.wall_distance_m, o.min_look_ahead_m, o.look_ahead_m);
  const double clear2 = o.wall_distance_m * o.wall_distance_m;
  const double path2 = o.robot_clearance_m * o.robot_clearance_m;
  auto free_target = [&](double theta) {
    const Vec2 q{result.look_ahead_m * std::cos(theta), result.look_ahead_m * std::sin(theta)};
    const Vec2 half = 0.5 * q;
    for (const Vec2& p : points) {
      if (SquaredDistanceToSegment(p, half, q) < clear2) return false;
      if (SquaredDistanceToSegment(p, {0.0, 0.0}, half) < path2) return false;
    }
    return true;
  };
  // From the wall's perpendicular round through ahead to the other side and behind it (a dead end). With
  // no wall within reach on the followed side, from straight ahead: the robot goes on until it finds one
  // (turning towards open space would circle in a hall).
  const double step = o.angle_step_deg * kDeg;
  const double first = result.wall_found ? -M_PI / 2 : 0.0;
  for (double theta = first; theta <= 1.5 * M_PI - step / 2; theta += step) {
    if (free_target(theta)) {
      result.target_found = true;
      result.target_bearing_rad = NormalizeAngle(theta);
      break;
    }
  }
  VelocityCommand& cmd = result.command;
  const double turn_sign = -side_sign_;  // mirrored bearing → real angular direction
  if (!result.target_found || result.target_bearing_rad > o.rotate_in_place_deg * kDeg ||
      result.target_bearing_rad < -M_PI / 2 - 1e-9) {
    cmd.angular_rps = turn_sign * o.max_angular_speed_rps;  // away from the wall, on the spot
  } else {
    const double theta = result.target_bearing_rad;
    const double sharpness = std::min(1.0, std::fabs(theta) / (o.rotate_in_place_deg * kDeg));
    cmd.linear_mps = o.cruise_speed_mps * (1.0 - (1.0 - o.min_speed_fraction) * sharpness);
    const double curvature = 2.0 * std::sin(theta) / result.look_ahead_m;
    cmd.angular_rps = std::clamp(turn_sign * cmd.linear_mps * curvature, -o.max_angular_speed_rps,
                                 o.max_angular_speed_rps);
  }
  if (side_sign_ > 0) result.target_bearing_rad = -result.target_bearing_rad;  // back to base_link
  return result;
}

}  // namespace doorplate_localization

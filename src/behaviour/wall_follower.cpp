#include "doorplate_localization/behaviour/wall_follower.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {
namespace {

void Require(bool ok, const char* field, const char* rule) {
  if (!ok) throw std::invalid_argument(std::string("WallFollowerOptions.") + field + ": " + rule);
}

constexpr double kDeg = M_PI / 180.0;

}  // namespace

WallFollower::WallFollower(const WallFollowerOptions& o)
    : options_(o), side_sign_(o.wall_side == "left" ? 1.0 : -1.0) {
  Require(o.wall_side == "left" || o.wall_side == "right", "wall_side", "must be 'left' or 'right'");
  Require(o.wall_distance_m > 0, "wall_distance_m", "must be > 0");
  Require(o.cruise_speed_mps > 0, "cruise_speed_mps", "must be > 0");
  Require(o.end_stop_distance_m > 0, "end_stop_distance_m", "must be > 0");
  Require(o.slow_down_distance_m > o.end_stop_distance_m, "slow_down_distance_m", "must be > end_stop_distance_m");
  Require(o.side_sector_min_deg >= 0 && o.side_sector_min_deg < o.side_sector_max_deg && o.side_sector_max_deg <= 180,
          "side_sector_min_deg", "need 0 <= side_sector_min_deg < side_sector_max_deg <= 180");
  Require(o.side_max_range_m > o.wall_distance_m, "side_max_range_m", "must be > wall_distance_m");
  Require(o.max_angular_speed_rps > 0, "max_angular_speed_rps", "must be > 0");
  Require(o.front_half_width_m > 0, "front_half_width_m", "must be > 0");
  CheckIsolatedReturnOptions(o.isolated_returns, "WallFollowerOptions.isolated_returns.");
  Require(o.width_sector_half_angle_deg > 0 && o.width_sector_half_angle_deg < 90, "width_sector_half_angle_deg",
          "must be in (0, 90)");
}

CorridorObservation WallFollower::Observe(const std::vector<float>& ranges_m, double angle_min_rad,
                                          double angle_increment_rad) const {
  CorridorObservation obs;
  obs.front_distance_m = std::numeric_limits<double>::infinity();
  double left_min = std::numeric_limits<double>::infinity(), right_min = left_min;
  std::vector<Vec2> wall_points;
  for (size_t i = 0; i < ranges_m.size(); ++i) {
    const double r = ranges_m[i];
    if (!std::isfinite(r) || r <= 0.0) continue;
    const double a = NormalizeAngle(angle_min_rad + static_cast<double>(i) * angle_increment_rad);
    const double x = r * std::cos(a), y = r * std::sin(a);
    // An isolated return is no obstacle ahead, but may still be the wall (glass returns a beam here and there).
    if (x > 0 && std::fabs(y) <= options_.front_half_width_m && !IsIsolatedReturn(ranges_m, i, options_.isolated_returns)) {
      obs.front_distance_m = std::min(obs.front_distance_m, x);
    }
    const bool sideways = std::fabs(std::fabs(a) - M_PI / 2) <= options_.width_sector_half_angle_deg * kDeg;
    if (sideways && a > 0) left_min = std::min(left_min, r);
    if (sideways && a < 0) right_min = std::min(right_min, r);
    const double side_angle = side_sign_ * a;  // angle measured towards the followed side
    if (side_angle >= options_.side_sector_min_deg * kDeg && side_angle <= options_.side_sector_max_deg * kDeg &&
        r <= options_.side_max_range_m) {
      wall_points.push_back({x, y});
    }
  }
  if (std::isfinite(left_min) && std::isfinite(right_min)) obs.width_m = left_min + right_min;
  if (wall_points.size() < 5) return obs;
  // Total least squares line through the side points: its direction is the principal axis of their scatter.
  Vec2 mean;
  for (const Vec2& p : wall_points) mean = mean + p;
  mean = (1.0 / static_cast<double>(wall_points.size())) * mean;
  double sxx = 0, syy = 0, sxy = 0;
  for (const Vec2& p : wall_points) {
    const Vec2 d = p - mean;
    sxx += d.x * d.x;
    syy += d.y * d.y;
    sxy += d.x * d.y;
  }
  double direction = 0.5 * std::atan2(2.0 * sxy, sxx - syy);  // in (-pi/2, pi/2]: points forward
  if (direction > M_PI / 2 - 1e-12) direction -= M_PI;
  const Vec2 normal{-std::sin(direction), std::cos(direction)};
  obs.wall_found = true;
  obs.wall_distance_m = std::fabs(Dot(normal, mean));
  obs.wall_angle_rad = direction;
  return obs;
}

VelocityCommand WallFollower::Command(const CorridorObservation& obs, WallFollowState* state) const {
  VelocityCommand cmd;
  if (obs.front_distance_m <= options_.end_stop_distance_m) {
    *state = WallFollowState::kEndReached;
    return cmd;  // stop
  }
  const double slow = std::clamp((obs.front_distance_m - options_.end_stop_distance_m) /
                                     (options_.slow_down_distance_m - options_.end_stop_distance_m),
                                 0.25, 1.0);
  cmd.linear_mps = options_.cruise_speed_mps * slow;
  if (!obs.wall_found) {
    *state = WallFollowState::kNoWall;  // keep the heading: doors and gaps interrupt the wall briefly
    return cmd;
  }
  *state = WallFollowState::kFollowing;
  // Desired heading relative to the wall: turn towards it when too far, away when too close.
  const double error_m = obs.wall_distance_m - options_.wall_distance_m;
  const double correction = std::clamp(options_.distance_gain_rad_per_m * error_m,
                                       -options_.max_heading_correction_rad, options_.max_heading_correction_rad);
  const double desired_heading = side_sign_ * correction;  // relative to the wall direction
  const double heading_error = desired_heading - (-obs.wall_angle_rad);
  cmd.angular_rps = std::clamp(options_.heading_gain_per_s * heading_error, -options_.max_angular_speed_rps,
                               options_.max_angular_speed_rps);
  return cmd;
}

}  // namespace doorplate_localization

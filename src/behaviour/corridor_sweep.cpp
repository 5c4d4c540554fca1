#include "doorplate_localization/behaviour/corridor_sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

void Require(bool ok, const char* field, const char* rule) {
  if (!ok) throw std::invalid_argument(std::string("CorridorSweepOptions.") + field + ": " + rule);
}

const CorridorSweepOptions& Validated(const CorridorSweepOptions& o) {
  Require(o.turn_speed_rps > 0, "turn_speed_rps", "must be > 0");
  Require(o.turn_tolerance_rad > 0 && o.turn_tolerance_rad < M_PI / 2, "turn_tolerance_rad", "must be in (0, pi/2)");
  Require(o.parallel_tolerance_rad > 0, "parallel_tolerance_rad", "must be > 0");
  Require(o.approach_sector_max_deg > o.follower.side_sector_min_deg && o.approach_sector_max_deg <= 180,
          "approach_sector_max_deg", "must be in (follower.side_sector_min_deg, 180]");
  Require(o.approach_max_range_m > o.follower.wall_distance_m, "approach_max_range_m",
          "must be > follower.wall_distance_m");
  Require(o.approach_tolerance_m > 0, "approach_tolerance_m", "must be > 0");
  Require(o.wall_gate_m > 0, "wall_gate_m", "must be > 0");
  Require(o.min_wall_span_m >= 0, "min_wall_span_m", "must be >= 0");
  Require(o.max_wall_turn_rad >= 0 && o.max_wall_turn_rad < M_PI / 2, "max_wall_turn_rad", "must be in [0, pi/2)");
  Require(o.direction_settle_fits >= 1, "direction_settle_fits", "must be >= 1");
  Require(o.direction_settle_spread_rad >= 0, "direction_settle_spread_rad", "must be >= 0");
  Require(o.wall_direction_gain > 0 && o.wall_direction_gain <= 1, "wall_direction_gain", "must be in (0, 1]");
  Require(o.wall_gate_reset_s > 0 && std::isfinite(o.wall_gate_reset_s), "wall_gate_reset_s", "must be finite and > 0");
  Require(o.wall_reacquire_s > o.wall_gate_reset_s && std::isfinite(o.wall_reacquire_s), "wall_reacquire_s",
          "must be finite and > wall_gate_reset_s");
  Require(o.end_confirm_s >= 0 && std::isfinite(o.end_confirm_s), "end_confirm_s", "must be finite and >= 0");
  Require(o.end_min_width_m >= 0 && std::isfinite(o.end_min_width_m), "end_min_width_m", "must be finite and >= 0");
  Require(o.end_max_wall_angle_rad > 0 && o.end_max_wall_angle_rad < M_PI / 2, "end_max_wall_angle_rad",
          "must be in (0, pi/2)");
  Require(o.narrow_end_confirm_s >= o.end_confirm_s && std::isfinite(o.narrow_end_confirm_s), "narrow_end_confirm_s",
          "must be finite and >= end_confirm_s");
  return o;
}

WallFollowerOptions ApproachOptions(const CorridorSweepOptions& o) {
  WallFollowerOptions approach = o.follower;
  approach.side_sector_max_deg = o.approach_sector_max_deg;
  approach.side_max_range_m = o.approach_max_range_m;
  return approach;
}

constexpr double kBlockingGapM = 0.15;  // returns closer than this to the next belong to one thing
constexpr int kBlockingMaxMisses = 3;   // beams skipped in a row (no echo, a spurious return) before it ends

}  // namespace

double BlockingWidth(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad) {
  const int n = static_cast<int>(ranges_m.size());
  const auto point = [&](int i) -> std::optional<Vec2> {
    const double r = ranges_m[static_cast<std::size_t>(i)];
    if (!std::isfinite(r) || r <= 0.0) return std::nullopt;
    const double a = angle_min_rad + static_cast<double>(i) * angle_increment_rad;
    return Vec2{r * std::cos(a), r * std::sin(a)};
  };
  int nearest = -1;
  double nearest_x = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const std::optional<Vec2> p = point(i);
    if (p && p->x > 0 && std::fabs(p->y) < p->x && p->x < nearest_x) {  // within ±45° ahead
      nearest_x = p->x;
      nearest = i;
    }
  }
  if (nearest < 0) return 0.0;
  const bool full_circle = std::fabs(std::fabs(angle_increment_rad) * n - 2.0 * M_PI) < 2.0 * std::fabs(angle_increment_rad);
  double min_y = point(nearest)->y, max_y = min_y;
  for (const int direction : {-1, 1}) {
    Vec2 previous = *point(nearest);
    int misses = 0;  // beams in a row without an echo or off the chain (dropouts, spurious short returns)
    for (int k = 1; k < n && misses <= kBlockingMaxMisses; ++k) {
      int i = nearest + direction * k;
      if (i < 0 || i >= n) {
        if (!full_circle) break;
        i = (i + n) % n;
      }
      const std::optional<Vec2> p = point(i);
      if (p && p->x <= 0) break;
      if (!p || Norm(*p - previous) > kBlockingGapM) {
        ++misses;
        continue;
      }
      misses = 0;
      min_y = std::min(min_y, p->y);
      max_y = std::max(max_y, p->y);
      previous = *p;
    }
  }
  return max_y - min_y;
}

const char* SweepPhaseName(SweepPhase phase) {
  switch (phase) {
    case SweepPhase::kFollowOut:
      return "follow_out";
    case SweepPhase::kTurnAround:
      return "turn_around";
    case SweepPhase::kFollowBack:
      return "follow_back";
    case SweepPhase::kDone:
      return "done";
  }
  return "unknown";
}

CorridorSweep::CorridorSweep(const CorridorSweepOptions& options)
    : options_(Validated(options)), follower_(options.follower), approach_observer_(ApproachOptions(options)) {}

void CorridorSweep::Reset() {
  phase_ = SweepPhase::kFollowOut;
  last_observation_ = CorridorObservation{};
  approaching_ = true;
  has_wall_ = false;
  turned_rad_ = 0.0;
  blocked_.Reset();
  ForgetWallDirection();
  back_direction_odom_rad_.reset();
  gate_dropped_ = false;
}

VelocityCommand CorridorSweep::Step(const std::vector<float>& ranges_m, double angle_min_rad,
                                    double angle_increment_rad, const Pose2D& odom_pose, double time_s) {
  if (!std::isfinite(time_s)) throw std::invalid_argument("CorridorSweep::Step: time_s must be finite");
  if (phase_ == SweepPhase::kDone) return {};
  const CorridorObservation approach = approach_observer_.Observe(ranges_m, angle_min_rad, angle_increment_rad);
  if (phase_ == SweepPhase::kTurnAround) {
    last_observation_ = approach;
    const VelocityCommand turn = Turn(approach, odom_pose);
    if (phase_ == SweepPhase::kTurnAround) return turn;
  }
  if (approaching_ && approach.wall_found &&
      std::fabs(approach.wall_distance_m - options_.follower.wall_distance_m) <= options_.approach_tolerance_m) {
    approaching_ = false;
    last_wall_s_ = time_s;
  }
  last_observation_ = approaching_ ? approach : ObserveGated(ranges_m, angle_min_rad, angle_increment_rad);
  if (!approaching_ && gate_dropped_ && last_observation_.wall_found &&
      last_observation_.wall_distance_m > options_.follower.wall_distance_m + options_.wall_gate_m) {
    last_observation_.wall_found = false;
  }
  if (!approaching_ && last_observation_.wall_found) CheckWallDirection(odom_pose, &last_observation_);
  if (!approaching_ && last_observation_.wall_found) {
    wall_ = last_observation_;
    has_wall_ = true;
    gate_dropped_ = false;
    last_wall_s_ = time_s;
  } else if (!approaching_ && has_wall_ && time_s - last_wall_s_ > options_.wall_gate_reset_s) {
    has_wall_ = false;  // the next fit ungated
    gate_dropped_ = true;
  } else if (!approaching_ && time_s - last_wall_s_ > options_.wall_reacquire_s) {
    // No wall taken for this long: the leg's direction may be wrong. Start over as after the approach.
    ForgetWallDirection();
    gate_dropped_ = false;
    last_wall_s_ = time_s;
  }
  CorridorObservation steer = last_observation_;
  if (!approaching_ && !steer.wall_found && wall_direction_odom_rad_) {
    // No wall this step (a door, the glass, a rejected fit): hold the leg's wall direction, not whatever
    // heading the robot has, so that a gap does not let it drift into the opposite wall.
    steer.wall_found = true;
    steer.wall_distance_m = options_.follower.wall_distance_m;
    steer.wall_angle_rad = NormalizeAngle(*wall_direction_odom_rad_ - odom_pose.theta_rad);
  }
  WallFollowState state;
  const VelocityCommand command = follower_.Command(steer, &state);
  if (state != WallFollowState::kEndReached) {
    blocked_.Reset();
    return command;
  }
  // The leg's direction relative to the robot: the followed wall's fit, or on the way back without one the
  // way out reversed.
  std::optional<double> leg_angle_rad;
  if (steer.wall_found) {
    leg_angle_rad = steer.wall_angle_rad;
  } else if (phase_ == SweepPhase::kFollowBack && back_direction_odom_rad_) {
    leg_angle_rad = NormalizeAngle(*back_direction_odom_rad_ - odom_pose.theta_rad);
  }
  if (leg_angle_rad && std::fabs(*leg_angle_rad) > options_.end_max_wall_angle_rad) {
    // Turned across the corridor: a side wall, not the corridor's end. Turn back along the leg.
    blocked_.Reset();
    return {0.0, std::copysign(options_.turn_speed_rps, *leg_angle_rad)};
  }
  const double held_s = blocked_.Held(time_s);
  const double wait_s = BlockingWidth(ranges_m, angle_min_rad, angle_increment_rad) >= options_.end_min_width_m
                            ? options_.end_confirm_s
                            : options_.narrow_end_confirm_s;
  if (held_s < wait_s) return command;  // a stop: wait for it to clear
  blocked_.Reset();
  if (phase_ == SweepPhase::kFollowBack) {
    phase_ = SweepPhase::kDone;
    return {};
  }
  phase_ = SweepPhase::kTurnAround;
  back_direction_odom_rad_ =
      NormalizeAngle((wall_direction_odom_rad_ ? *wall_direction_odom_rad_ : odom_pose.theta_rad) + M_PI);
  approaching_ = true;  // the way back starts at the far wall's distance
  has_wall_ = false;
  ForgetWallDirection();
  gate_dropped_ = false;
  turned_rad_ = 0.0;
  last_yaw_rad_ = odom_pose.theta_rad;
  last_observation_ = approach;
  return Turn(approach, odom_pose);
}

void CorridorSweep::ForgetWallDirection() {
  wall_direction_odom_rad_.reset();
  settling_directions_odom_rad_.clear();
}

CorridorObservation CorridorSweep::ObserveGated(const std::vector<float>& ranges_m, double angle_min_rad,
                                                double angle_increment_rad) const {
  const CorridorObservation raw = follower_.Observe(ranges_m, angle_min_rad, angle_increment_rad);
  if (!has_wall_) return raw;
  // The previous line in base_link: direction wall_.wall_angle_rad, on the followed side at its distance.
  const double side_sign = options_.follower.wall_side == "left" ? 1.0 : -1.0;
  const Vec2 along{std::cos(wall_.wall_angle_rad), std::sin(wall_.wall_angle_rad)};
  const Vec2 normal{-along.y, along.x};
  const double offset = side_sign * wall_.wall_distance_m;
  const WallFollowerOptions& f = options_.follower;
  double span_min = std::numeric_limits<double>::infinity(), span_max = -span_min;
  std::vector<float> gated = ranges_m;
  for (size_t i = 0; i < gated.size(); ++i) {
    const double r = gated[i];
    if (!std::isfinite(r) || r <= 0.0) continue;
    const double a = NormalizeAngle(angle_min_rad + static_cast<double>(i) * angle_increment_rad);
    const Vec2 p{r * std::cos(a), r * std::sin(a)};
    if (side_sign * p.y <= 0.0) continue;
    if (std::fabs(Dot(normal, p) - offset) > options_.wall_gate_m) {
      gated[i] = std::numeric_limits<float>::infinity();
      continue;
    }
    const double side_angle_deg = side_sign * a * 180.0 / M_PI;
    if (side_angle_deg >= f.side_sector_min_deg && side_angle_deg <= f.side_sector_max_deg && r <= f.side_max_range_m) {
      span_min = std::min(span_min, Dot(along, p));
      span_max = std::max(span_max, Dot(along, p));
    }
  }
  CorridorObservation observation = follower_.Observe(gated, angle_min_rad, angle_increment_rad);
  if (!(span_max - span_min >= options_.min_wall_span_m)) observation.wall_found = false;
  observation.front_distance_m = raw.front_distance_m;  // the end wall and obstacles ahead are never gated
  observation.width_m = raw.width_m;
  return observation;
}

void CorridorSweep::CheckWallDirection(const Pose2D& odom_pose, CorridorObservation* observation) {
  if (!(options_.max_wall_turn_rad > 0)) return;
  const double direction = NormalizeAngle(odom_pose.theta_rad + observation->wall_angle_rad);
  if (!wall_direction_odom_rad_) {
    // Taken only from fits the robot runs parallel to: a fit made while it still turns towards the wall
    // (after the approach, after a kidnap) can be off by more than the check's tolerance.
    std::vector<double>& fits = settling_directions_odom_rad_;
    if (std::fabs(observation->wall_angle_rad) > options_.parallel_tolerance_rad) {
      fits.clear();
      return;
    }
    fits.push_back(direction);
    if (fits.size() > static_cast<size_t>(options_.direction_settle_fits)) fits.erase(fits.begin());
    if (fits.size() < static_cast<size_t>(options_.direction_settle_fits)) return;
    double low = 0.0, high = 0.0, sum = 0.0;  // about the first fit, so the angles do not wrap
    for (const double fit : fits) {
      const double offset = NormalizeAngle(fit - fits.front());
      low = std::min(low, offset);
      high = std::max(high, offset);
      sum += offset;
    }
    if (high - low <= options_.direction_settle_spread_rad) {
      wall_direction_odom_rad_ = NormalizeAngle(fits.front() + sum / static_cast<double>(fits.size()));
      fits.clear();
    }
    return;
  }
  const double turn = NormalizeAngle(direction - *wall_direction_odom_rad_);
  if (std::fabs(turn) > options_.max_wall_turn_rad) {
    observation->wall_found = false;  // not the wall: Step holds the leg's direction
    return;
  }
  wall_direction_odom_rad_ = NormalizeAngle(*wall_direction_odom_rad_ + options_.wall_direction_gain * turn);
}

VelocityCommand CorridorSweep::Turn(const CorridorObservation& observation, const Pose2D& odom_pose) {
  turned_rad_ += std::fabs(NormalizeAngle(odom_pose.theta_rad - last_yaw_rad_));
  last_yaw_rad_ = odom_pose.theta_rad;
  const bool parallel = observation.wall_found && std::fabs(observation.wall_angle_rad) <= options_.parallel_tolerance_rad;
  if ((turned_rad_ >= M_PI - options_.turn_tolerance_rad && parallel) ||
      turned_rad_ >= M_PI + options_.turn_tolerance_rad) {
    phase_ = SweepPhase::kFollowBack;
    return {};
  }
  // Turn away from the followed wall: counter-clockwise when it is on the right.
  const double direction = options_.follower.wall_side == "right" ? 1.0 : -1.0;
  return {0.0, direction * options_.turn_speed_rps};
}

}  // namespace doorplate_localization

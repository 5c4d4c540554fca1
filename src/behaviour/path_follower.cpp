#include "doorplate_localization/behaviour/path_follower.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>


namespace doorplate_localization {
namespace {

void Require(bool ok, const char* field, const char* rule) {
  if (!ok) throw std::invalid_argument(std::string("PathFollowerOptions.") + field + ": " + rule);
}

bool Positive(double v) { return v > 0 && std::isfinite(v); }

const PathFollowerOptions& Validated(const PathFollowerOptions& o) {
  Require(Positive(o.look_ahead_m), "look_ahead_m", "must be finite and > 0");
  Require(Positive(o.cruise_speed_mps), "cruise_speed_mps", "must be finite and > 0");
  Require(Positive(o.max_angular_speed_rps), "max_angular_speed_rps", "must be finite and > 0");
  Require(Positive(o.turn_speed_rps), "turn_speed_rps", "must be finite and > 0");
  Require(o.rotate_in_place_rad > 0 && o.rotate_in_place_rad < M_PI, "rotate_in_place_rad", "must be in (0, pi)");
  Require(o.resume_driving_rad > 0 && o.resume_driving_rad < o.rotate_in_place_rad, "resume_driving_rad",
          "must be in (0, rotate_in_place_rad)");
  Require(Positive(o.approach_gain_per_s), "approach_gain_per_s", "must be finite and > 0");
  Require(o.min_approach_speed_mps > 0 && o.min_approach_speed_mps <= o.cruise_speed_mps, "min_approach_speed_mps",
          "must be in (0, cruise_speed_mps]");
  Require(Positive(o.goal_tolerance_m), "goal_tolerance_m", "must be finite and > 0");
  Require(o.overshoot_tolerance_m >= o.goal_tolerance_m && std::isfinite(o.overshoot_tolerance_m),
          "overshoot_tolerance_m", "must be finite and >= goal_tolerance_m");
  Require(Positive(o.face_gain_per_s), "face_gain_per_s", "must be finite and > 0");
  Require(o.face_tolerance_rad > 0 && o.face_tolerance_rad < M_PI / 2, "face_tolerance_rad", "must be in (0, pi/2)");
  Require(o.stop_distance_m >= 0 && std::isfinite(o.stop_distance_m), "stop_distance_m", "must be finite and >= 0");
  Require(Positive(o.front_half_width_m), "front_half_width_m", "must be finite and > 0");
  CheckIsolatedReturnOptions(o.isolated_returns, "PathFollowerOptions.isolated_returns.");
  Require(Positive(o.progress_window_m), "progress_window_m", "must be finite and > 0");
  return o;
}

}  // namespace

const char* PathFollowStateName(PathFollowState state) {
  switch (state) {
    case PathFollowState::kIdle:
      return "idle";
    case PathFollowState::kTurning:
      return "turning";
    case PathFollowState::kDriving:
      return "driving";
    case PathFollowState::kFacing:
      return "facing";
    case PathFollowState::kArrived:
      return "arrived";
    case PathFollowState::kBlocked:
      return "blocked";
  }
  return "unknown";
}

PathFollower::PathFollower(const PathFollowerOptions& options) : options_(Validated(options)) {}

bool PathFollower::active() const {
  return state_ == PathFollowState::kTurning || state_ == PathFollowState::kDriving ||
         state_ == PathFollowState::kFacing || state_ == PathFollowState::kBlocked;
}

void PathFollower::Start(const std::vector<Vec2>& path, double goal_heading_rad) {
  const char* problem = path.empty() ? "path: empty" : nullptr;
  for (const Vec2& p : path) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) problem = "path: not finite";
  }
  if (!std::isfinite(goal_heading_rad)) problem = "goal_heading_rad: not finite";
  if (problem) throw std::invalid_argument(std::string("PathFollower::Start: ") + problem);
  path_ = path;
  along_m_.assign(path_.size(), 0.0);
  for (size_t i = 1; i < path_.size(); ++i) along_m_[i] = along_m_[i - 1] + Norm(path_[i] - path_[i - 1]);
  goal_heading_rad_ = goal_heading_rad;
  progress_ = 0;
  cross_track_m_ = 0.0;
  remaining_m_ = along_m_.back();
  distance_to_end_m_ = remaining_m_;
  yaw_error_rad_ = 0.0;
  obstacle_ahead_m_ = std::numeric_limits<double>::infinity();
  state_ = PathFollowState::kTurning;  // the first Step decides whether a turn is needed
}

void PathFollower::Stop() { state_ = PathFollowState::kIdle; }

void PathFollower::UpdateProgress(Vec2 position) {
  double best = std::numeric_limits<double>::infinity();
  size_t best_index = progress_;
  const double window_end = along_m_[progress_] + options_.progress_window_m;
  for (size_t i = progress_; i < path_.size() && along_m_[i] <= window_end; ++i) {
    const double d = Norm(path_[i] - position);
    if (d < best) {
      best = d;
      best_index = i;
    }
  }
  progress_ = best_index;
  cross_track_m_ = best;
  remaining_m_ = along_m_.back() - along_m_[progress_];
  distance_to_end_m_ = Norm(path_.back() - position);
}

double PathFollower::NearestAhead(const std::vector<float>& ranges_m, double angle_min_rad,
                                  double angle_increment_rad) const {
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < ranges_m.size(); ++i) {
    const double r = ranges_m[i];
    if (!std::isfinite(r) || r <= 0.0 || IsIsolatedReturn(ranges_m, i, options_.isolated_returns)) continue;
    const double a = angle_min_rad + static_cast<double>(i) * angle_increment_rad;
    const double x = r * std::cos(a), y = r * std::sin(a);
    if (x > 0.0 && std::fabs(y) <= options_.front_half_width_m) nearest = std::min(nearest, x);
  }
  return nearest;
}

VelocityCommand PathFollower::Step(const std::vector<float>& ranges_m, double angle_min_rad,
                                   double angle_increment_rad, const Pose2D& pose) {
  if (!active()) return {};
  if (!std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.theta_rad)) return {};
  const Vec2 position = pose.Position();
  UpdateProgress(position);
  yaw_error_rad_ = NormalizeAngle(goal_heading_rad_ - pose.theta_rad);
  const Pose2D inverse = pose.Inverse();
  const Vec2 end_local = inverse.TransformPoint(path_.back());
  if (state_ != PathFollowState::kFacing && remaining_m_ <= options_.look_ahead_m &&
      (distance_to_end_m_ <= options_.goal_tolerance_m ||
       (end_local.x <= 0.0 && distance_to_end_m_ <= options_.overshoot_tolerance_m))) {
    state_ = PathFollowState::kFacing;
  }
  if (state_ == PathFollowState::kFacing) {
    if (std::fabs(yaw_error_rad_) <= options_.face_tolerance_rad) {
      state_ = PathFollowState::kArrived;
      return {};
    }
    return {0.0, std::clamp(options_.face_gain_per_s * yaw_error_rad_, -options_.turn_speed_rps,
                            options_.turn_speed_rps)};
  }

  // The look-ahead point: look_ahead_m along the path from the progress point, else the end.
  size_t target = progress_;
  while (target + 1 < path_.size() && along_m_[target] - along_m_[progress_] < options_.look_ahead_m) ++target;
  const Vec2 local = inverse.TransformPoint(path_[target]);
  const double bearing = std::atan2(local.y, local.x);
  if (state_ == PathFollowState::kDriving && std::fabs(bearing) > options_.rotate_in_place_rad) {
    state_ = PathFollowState::kTurning;
  }
  if (state_ == PathFollowState::kTurning) {
    if (std::fabs(bearing) > options_.resume_driving_rad) {
      return {0.0, bearing > 0 ? options_.turn_speed_rps : -options_.turn_speed_rps};
    }
    state_ = PathFollowState::kDriving;
  }

  obstacle_ahead_m_ = NearestAhead(ranges_m, angle_min_rad, angle_increment_rad);
  if (obstacle_ahead_m_ <= options_.stop_distance_m) {
    state_ = PathFollowState::kBlocked;
    return {};
  }
  state_ = PathFollowState::kDriving;  // (again, after kBlocked)
  const double to_go = remaining_m_ <= options_.look_ahead_m ? distance_to_end_m_ : remaining_m_;
  double linear = std::min(options_.cruise_speed_mps,
                           std::max(options_.min_approach_speed_mps, options_.approach_gain_per_s * to_go));
  linear *= std::max(0.3, std::cos(bearing));  // slower in sharp bends
  const double distance = std::max(Norm(local), 1e-3);
  const double curvature = 2.0 * std::sin(bearing) / distance;
  double angular = linear * curvature;
  if (std::fabs(angular) > options_.max_angular_speed_rps) {
    angular = std::copysign(options_.max_angular_speed_rps, angular);
    linear = std::fabs(angular / curvature);
  }
  return {linear, angular};
}

}  // namespace doorplate_localization

#include "doorplate_localization/behaviour/go_to_room.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace doorplate_localization {
namespace {

void Require(bool ok, const char* field, const char* rule) {
  if (!ok) throw std::invalid_argument(std::string("GoToRoomOptions.") + field + ": " + rule);
}

const GoToRoomOptions& Validated(const GoToRoomOptions& o) {
  Require(o.approach_sector_max_deg > o.follower.side_sector_min_deg && o.approach_sector_max_deg <= 180,
          "approach_sector_max_deg", "must be in (follower.side_sector_min_deg, 180]");
  Require(o.approach_tolerance_m > 0 && std::isfinite(o.approach_tolerance_m), "approach_tolerance_m",
          "must be finite and > 0");
  Require(o.turn_speed_rps > 0 && std::isfinite(o.turn_speed_rps), "turn_speed_rps", "must be finite and > 0");
  Require(o.align_tolerance_rad > 0 && o.align_tolerance_rad < M_PI / 2, "align_tolerance_rad",
          "must be in (0, pi/2)");
  Require(o.arrive_tolerance_m > 0 && std::isfinite(o.arrive_tolerance_m), "arrive_tolerance_m",
          "must be finite and > 0");
  Require(o.approach_gain_per_s > 0 && std::isfinite(o.approach_gain_per_s), "approach_gain_per_s",
          "must be finite and > 0");
  Require(o.min_approach_speed_mps > 0 && o.min_approach_speed_mps <= o.follower.cruise_speed_mps,
          "min_approach_speed_mps", "must be in (0, follower.cruise_speed_mps]");
  Require(o.face_gain_per_s > 0 && std::isfinite(o.face_gain_per_s), "face_gain_per_s", "must be finite and > 0");
  Require(o.face_tolerance_rad > 0 && o.face_tolerance_rad < M_PI / 2, "face_tolerance_rad", "must be in (0, pi/2)");
  Require(o.blocked_wait_s >= 0 && std::isfinite(o.blocked_wait_s), "blocked_wait_s", "must be finite and >= 0");
  return o;
}

WallFollowerOptions Side(WallFollowerOptions follower, const char* side) {
  follower.wall_side = side;
  return follower;
}

WallFollowerOptions Approach(const GoToRoomOptions& o, const char* side) {
  WallFollowerOptions approach = Side(o.follower, side);
  approach.side_sector_max_deg = o.approach_sector_max_deg;
  return approach;
}

}  // namespace

const char* GoToRoomStateName(GoToRoomState state) {
  switch (state) {
    case GoToRoomState::kIdle:
      return "idle";
    case GoToRoomState::kTurning:
      return "turning";
    case GoToRoomState::kDriving:
      return "driving";
    case GoToRoomState::kFacing:
      return "facing";
    case GoToRoomState::kArrived:
      return "arrived";
    case GoToRoomState::kRefused:
      return "refused";
    case GoToRoomState::kFailed:
      return "failed";
  }
  return "unknown";
}

GoToRoom::GoToRoom(const GoToRoomOptions& options)
    : options_(Validated(options)),
      left_follower_(Side(options.follower, "left")),
      right_follower_(Side(options.follower, "right")),
      left_approach_(Approach(options, "left")),
      right_approach_(Approach(options, "right")) {}

bool GoToRoom::active() const {
  return state_ == GoToRoomState::kTurning || state_ == GoToRoomState::kDriving || state_ == GoToRoomState::kFacing;
}

void GoToRoom::Start(const RoomGoal& goal) {
  goal_ = goal;
  reason_.clear();
  remaining_m_ = 0.0;
  yaw_error_rad_ = 0.0;
  stepped_ = false;
  blocked_.Reset();
  state_ = GoToRoomState::kTurning;  // the first Step decides whether a turn is needed
}

void GoToRoom::Refuse(const std::string& reason) {
  goal_ = RoomGoal{};
  reason_ = reason;
  state_ = GoToRoomState::kRefused;
}

void GoToRoom::Cancel() {
  goal_ = RoomGoal{};
  reason_.clear();
  state_ = GoToRoomState::kIdle;
}

VelocityCommand GoToRoom::Step(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad,
                               const Pose2D& pose, double time_s) {
  if (!active()) return {};
  if (!std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.theta_rad) || !std::isfinite(time_s)) {
    return {};  // stop
  }
  // The corridor axis at the goal: perpendicular to the direction the robot will face (the door).
  const Vec2 axis{-std::sin(goal_.pose.theta_rad), std::cos(goal_.pose.theta_rad)};
  remaining_m_ = Dot(goal_.pose.Position() - pose.Position(), axis);
  stepped_ = true;
  yaw_error_rad_ = NormalizeAngle(goal_.pose.theta_rad - pose.theta_rad);
  if (state_ != GoToRoomState::kFacing && std::fabs(remaining_m_) <= options_.arrive_tolerance_m) {
    state_ = GoToRoomState::kFacing;
  }
  if (state_ == GoToRoomState::kFacing) {
    if (std::fabs(yaw_error_rad_) <= options_.face_tolerance_rad) {
      state_ = GoToRoomState::kArrived;
      return {};
    }
    return {0.0, std::clamp(options_.face_gain_per_s * yaw_error_rad_, -options_.turn_speed_rps,
                            options_.turn_speed_rps)};
  }
  const Vec2 travel = (remaining_m_ >= 0.0 ? 1.0 : -1.0) * axis;
  const double heading_error = NormalizeAngle(std::atan2(travel.y, travel.x) - pose.theta_rad);
  // Turn in place when starting off the travel direction, when the goal got behind (an overshoot), or when
  // the follower has steered twice the alignment tolerance away (a wall fit bent by an end wall or a gap).
  if (state_ == GoToRoomState::kDriving && std::fabs(heading_error) > 2 * options_.align_tolerance_rad) {
    state_ = GoToRoomState::kTurning;
  }
  if (state_ == GoToRoomState::kTurning) {
    if (std::fabs(heading_error) > options_.align_tolerance_rad) {
      return {0.0, heading_error > 0 ? options_.turn_speed_rps : -options_.turn_speed_rps};
    }
    state_ = GoToRoomState::kDriving;
    approaching_ = true;
  }
  return Drive(ranges_m, angle_min_rad, angle_increment_rad, travel, time_s);
}

VelocityCommand GoToRoom::Drive(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad,
                                const Vec2& travel, double time_s) {
  // The goal's wall lies in the direction of the goal's theta: on the left of the travel direction if
  // turning from `travel` to it is counter-clockwise.
  const Vec2 facing{std::cos(goal_.pose.theta_rad), std::sin(goal_.pose.theta_rad)};
  const bool left = Cross(travel, facing) > 0;
  const WallFollower& follower = left ? left_follower_ : right_follower_;
  CorridorObservation observation;
  if (approaching_) {
    observation = (left ? left_approach_ : right_approach_).Observe(ranges_m, angle_min_rad, angle_increment_rad);
    const double error_m = observation.wall_distance_m - options_.follower.wall_distance_m;
    approaching_ = !(observation.wall_found && std::fabs(error_m) <= options_.approach_tolerance_m);
  } else {
    observation = follower.Observe(ranges_m, angle_min_rad, angle_increment_rad);
  }
  WallFollowState follow_state;
  VelocityCommand command = follower.Command(observation, &follow_state);
  if (follow_state == WallFollowState::kEndReached) {
    const double held_s = blocked_.Held(time_s);
    if (held_s < options_.blocked_wait_s) return {};  // a stop: wait for it to clear
    char why[192];
    std::snprintf(why, sizeof(why), "stopped by a wall or obstacle %.2f m ahead for %.1f s with %.2f m still to go",
                  observation.front_distance_m, held_s, std::fabs(remaining_m_));
    reason_ = why;
    state_ = GoToRoomState::kFailed;
    return {};
  }
  blocked_.Reset();
  const double remaining = std::fabs(remaining_m_);
  command.linear_mps =
      std::min(command.linear_mps, std::max(options_.min_approach_speed_mps, options_.approach_gain_per_s * remaining));
  return command;
}

std::string GoToRoom::Status() const {
  const std::string state = GoToRoomStateName(state_);
  if (state_ == GoToRoomState::kIdle) return state;
  if (state_ == GoToRoomState::kRefused) return state + ": " + reason_;
  char numbers[128];
  std::string detail = state + ": room " + goal_.room;
  switch (state_) {
    case GoToRoomState::kTurning:
    case GoToRoomState::kDriving:
      if (!stepped_) return detail + ", starting";
      std::snprintf(numbers, sizeof(numbers), ", %.2f m to go", std::fabs(remaining_m_));
      return detail + numbers;
    case GoToRoomState::kFacing:
      std::snprintf(numbers, sizeof(numbers), ", turning %.2f rad to face the door", yaw_error_rad_);
      return detail + numbers;
    case GoToRoomState::kArrived:
      std::snprintf(numbers, sizeof(numbers), ", %.3f m along, yaw error %.3f rad", remaining_m_, yaw_error_rad_);
      return detail + numbers;
    default:
      return detail + ": " + reason_;
  }
}

}  // namespace doorplate_localization

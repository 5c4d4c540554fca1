#include "doorplate_localization/behaviour/floor_go_to_room.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace doorplate_localization {
namespace {

const FloorGoToRoomOptions& Validated(const FloorGoToRoomOptions& o) {
  auto require = [](bool ok, const char* field, const char* rule) {
    if (!ok) throw std::invalid_argument(std::string("FloorGoToRoomOptions.") + field + ": " + rule);
  };
  require(o.max_path_deviation_m > 0 && std::isfinite(o.max_path_deviation_m), "max_path_deviation_m",
          "must be finite and > 0");
  require(o.max_replans >= 0, "max_replans", "must be >= 0");
  require(o.max_blocked_s > 0 && std::isfinite(o.max_blocked_s), "max_blocked_s", "must be finite and > 0");
  return o;
}

}  // namespace

const char* FloorGoToRoomStateName(FloorGoToRoomState state) {
  switch (state) {
    case FloorGoToRoomState::kIdle:
      return "idle";
    case FloorGoToRoomState::kFollowing:
      return "following";
    case FloorGoToRoomState::kArrived:
      return "arrived";
    case FloorGoToRoomState::kRefused:
      return "refused";
    case FloorGoToRoomState::kFailed:
      return "failed";
  }
  return "unknown";
}

FloorGoToRoom::FloorGoToRoom(const FloorGoToRoomOptions& options, const OccupancyGrid& grid)
    : options_(Validated(options)), planner_(options.planner, grid), follower_(options.follower) {}

bool FloorGoToRoom::Start(const RoomGoal& goal, const Pose2D& robot_in_map) {
  goal_ = goal;
  reason_.clear();
  replans_ = 0;
  blocked_.Reset();
  path_ = planner_.Plan(robot_in_map.Position(), goal.pose.Position());
  if (!path_.found) {
    Refuse(path_.failure);
    return false;
  }
  first_plan_length_m_ = path_.length_m;
  follower_.Start(path_.waypoints, goal.pose.theta_rad);
  state_ = FloorGoToRoomState::kFollowing;
  return true;
}

void FloorGoToRoom::Refuse(const std::string& reason) {
  follower_.Stop();
  reason_ = reason;
  state_ = FloorGoToRoomState::kRefused;
}

void FloorGoToRoom::Cancel() {
  follower_.Stop();
  reason_.clear();
  state_ = FloorGoToRoomState::kIdle;
}

bool FloorGoToRoom::Replan(const Pose2D& pose) {
  if (replans_ >= options_.max_replans) {
    char why[128];
    std::snprintf(why, sizeof(why), "%.2f m off the path after %d replans", follower_.cross_track_m(), replans_);
    reason_ = why;
    return false;
  }
  ++replans_;
  const GridPath path = planner_.Plan(pose.Position(), goal_.pose.Position());
  if (!path.found) {
    reason_ = "replanning: " + path.failure;
    return false;
  }
  path_ = path;
  follower_.Start(path_.waypoints, goal_.pose.theta_rad);
  return true;
}

VelocityCommand FloorGoToRoom::Step(const std::vector<float>& ranges_m, double angle_min_rad,
                                    double angle_increment_rad, const Pose2D& pose, double stamp_s) {
  if (state_ != FloorGoToRoomState::kFollowing) return {};
  VelocityCommand command = follower_.Step(ranges_m, angle_min_rad, angle_increment_rad, pose);
  const PathFollowState follow = follower_.state();
  if (follow == PathFollowState::kArrived) {
    state_ = FloorGoToRoomState::kArrived;
    return {};
  }
  if (follow == PathFollowState::kBlocked) {
    const double held_s = blocked_.Held(stamp_s);
    if (held_s > options_.max_blocked_s) {
      char why[128];
      std::snprintf(why, sizeof(why), "blocked for %.0f s by an obstacle %.2f m ahead", held_s,
                    follower_.obstacle_ahead_m());
      reason_ = why;
      follower_.Stop();
      state_ = FloorGoToRoomState::kFailed;
    }
    return {};
  }
  blocked_.Reset();
  if (follow != PathFollowState::kFacing && follower_.cross_track_m() > options_.max_path_deviation_m) {
    if (!Replan(pose)) {
      follower_.Stop();
      state_ = FloorGoToRoomState::kFailed;
      return {};
    }
    command = follower_.Step(ranges_m, angle_min_rad, angle_increment_rad, pose);
  }
  return command;
}

std::string FloorGoToRoom::Status() const {
  const std::string state = FloorGoToRoomStateName(state_);
  char numbers[160];
  switch (state_) {
    case FloorGoToRoomState::kIdle:
      return state;
    case FloorGoToRoomState::kRefused:
    case FloorGoToRoomState::kFailed:
      return state + ": " + (goal_.room.empty() ? "" : "room " + goal_.room + ": ") + reason_;
    case FloorGoToRoomState::kFollowing:
      std::snprintf(numbers, sizeof(numbers), ", %s, %.2f m to go", PathFollowStateName(follower_.state()),
                    follower_.remaining_m());
      return state + ": room " + goal_.room + numbers;
    case FloorGoToRoomState::kArrived:
      std::snprintf(numbers, sizeof(numbers), ", %.3f m from the goal, yaw error %.3f rad",
                    follower_.distance_to_end_m(), follower_.yaw_error_rad());
      return state + ": room " + goal_.room + numbers;
  }
  return state;
}

}  // namespace doorplate_localization

#include "doorplate_localization/behaviour/floor_explorer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "doorplate_localization/common/room_id.h"

namespace doorplate_localization {
namespace {

void Require(bool ok, const char* field, const char* rule) {
  if (!ok) throw std::invalid_argument(std::string("FloorExplorerOptions.") + field + ": " + rule);
}

const FloorExplorerOptions& Checked(const FloorExplorerOptions& o) {
  Require(o.passes >= 1, "passes", "must be >= 1");
  Require(o.revisit_plates >= 1, "revisit_plates", "must be >= 1");
  Require(o.min_revisit_travel_m > 0, "min_revisit_travel_m", "must be > 0");
  Require(o.revisit_radius_m > 0, "revisit_radius_m", "must be > 0");
  Require(o.max_pass_distance_m > o.min_revisit_travel_m, "max_pass_distance_m", "must be > min_revisit_travel_m");
  Require(o.turn_speed_rps > 0, "turn_speed_rps", "must be > 0");
  Require(o.read_latency_window_s >= 0, "read_latency_window_s", "must be >= 0");
  Require(o.straight_before_turn_m >= 0, "straight_before_turn_m", "must be >= 0");
  Require(o.straight_bearing_rad > 0, "straight_bearing_rad", "must be > 0");
  Require(o.turn_heading_tolerance_rad > 0 && o.turn_heading_tolerance_rad < M_PI / 2, "turn_heading_tolerance_rad",
          "must be in (0, pi/2)");
  Require(o.turn_tolerance_rad >= 0 && o.turn_tolerance_rad < M_PI / 2, "turn_tolerance_rad", "must be in [0, pi/2)");
  return o;
}

}  // namespace

const char* ExplorePhaseName(ExplorePhase phase) {
  switch (phase) {
    case ExplorePhase::kFollow: return "follow";
    case ExplorePhase::kTurnAround: return "turn_around";
    case ExplorePhase::kDone: return "done";
  }
  return "?";
}

const char* PassEndName(PassEnd end) {
  switch (end) {
    case PassEnd::kNotEnded: return "not_ended";
    case PassEnd::kPlatesRevisited: return "plates_revisited";
    case PassEnd::kPoseRevisited: return "pose_revisited";
    case PassEnd::kMaxDistance: return "max_distance";
  }
  return "?";
}

FloorExplorer::FloorExplorer(const FloorExplorerOptions& options)
    : options_(Checked(options)), steering_(options.steering) {}

FloorExplorer::StepRecord FloorExplorer::RecordAt(double stamp_s) const {
  const StepRecord now{stamp_s, total_distance_m_, pass_distance_m(), last_pose_.theta_rad,
                       straight_m_ >= options_.straight_before_turn_m,
                       phase_ == ExplorePhase::kFollow && !turn_pending_, pass_};
  if (history_.empty() || !std::isfinite(stamp_s) || stamp_s >= history_.back().stamp_s) return now;
  // The last step at or before the stamp (the oldest one kept if the stamp is older still).
  auto it = std::upper_bound(history_.begin(), history_.end(), stamp_s,
                             [](double t, const StepRecord& r) { return t < r.stamp_s; });
  return it == history_.begin() ? *it : *std::prev(it);
}

void FloorExplorer::OnPlateRead(const std::string& text, double stamp_s) {
  const std::string id = CanonicalRoomId(text);
  if (id.empty() || phase_ == ExplorePhase::kDone) return;
  const StepRecord at = RecordAt(stamp_s);  // where the robot was when the camera saw the plate
  const auto it = first_reads_.find(id);
  if (it == first_reads_.end()) {
    first_reads_[id] = {at.distance_m, at.heading_rad, at.pass};
    known_run_.clear();
    drift_samples_.clear();
    return;
  }
  // Not evidence of a closed loop: a turn round or a corner (the camera sweeps over plates read on the way
  // in, e.g. at the mouth of a dead-end branch on the way out), the start of a pass (pass 2 begins beside
  // the walls pass 1 saw), the same plate again a few metres on; nor a reading from before this pass's
  // state (a late report of a plate seen before a turn round).
  if (!at.following || !at.on_straight || at.pass != pass_ || phase_ != ExplorePhase::kFollow || turn_pending_ ||
      at.pass_distance_m < options_.min_revisit_travel_m ||
      at.distance_m - it->second.distance_m < options_.min_revisit_travel_m) {
    return;
  }
  if (std::find(known_run_.begin(), known_run_.end(), id) == known_run_.end()) {
    known_run_.push_back(id);
    // The same plate is seen square-on from the same side, so the headings of the two readings differ only by
    // the odometry's heading drift in between.
    if (it->second.pass == pass_) drift_samples_.push_back(NormalizeAngle(at.heading_rad - it->second.heading_rad));
  }
  if (static_cast<int>(known_run_.size()) >= options_.revisit_plates) EndPass(PassEnd::kPlatesRevisited);
}

void FloorExplorer::EndPass(PassEnd why) {
  last_pass_end_ = why;
  ++passes_ended_;
  // The corridor the pass started in, in today's odometry heading: its first straight heading plus the
  // drift the re-read plates show (their first readings came after it in the same pass).
  double drift_rad = 0.0;
  for (const double d : drift_samples_) drift_rad += d / static_cast<double>(drift_samples_.size());
  turn_heading_set_ = pass_heading_set_;
  turn_heading_rad_ = NormalizeAngle(pass_heading_rad_ + drift_rad);
  known_run_.clear();
  drift_samples_.clear();
  if (pass_ >= options_.passes) {
    phase_ = ExplorePhase::kDone;
    return;
  }
  turn_pending_ = true;  // the turn waits for a straight stretch of the pass's first corridor
  turn_pending_since_m_ = total_distance_m_;
}

VelocityCommand FloorExplorer::Step(const std::vector<float>& ranges_m, double angle_min_rad,
                                    double angle_increment_rad, const Pose2D& pose, double stamp_s) {
  const VelocityCommand command = Advance(ranges_m, angle_min_rad, angle_increment_rad, pose);
  if (std::isfinite(stamp_s)) {
    if (!history_.empty() && stamp_s < history_.back().stamp_s) history_.clear();  // time jumped back
    history_.push_back(RecordAt(stamp_s));
    while (history_.size() > 1 && stamp_s - history_.front().stamp_s > options_.read_latency_window_s) {
      history_.pop_front();
    }
  }
  return command;
}

VelocityCommand FloorExplorer::Advance(const std::vector<float>& ranges_m, double angle_min_rad,
                                       double angle_increment_rad, const Pose2D& pose) {
  if (!has_pose_) {
    has_pose_ = true;
    last_pose_ = pass_start_pose_ = pose;
  }
  const Pose2D previous = last_pose_;
  total_distance_m_ += Norm(pose.Position() - previous.Position());
  const double yaw_change = NormalizeAngle(pose.theta_rad - previous.theta_rad);
  last_pose_ = pose;

  if (phase_ == ExplorePhase::kFollow) {
    const bool straight = last_steering_.wall_found &&
                          std::fabs(last_steering_.target_bearing_rad) <= options_.straight_bearing_rad;
    straight_m_ = straight ? straight_m_ + Norm(pose.Position() - previous.Position()) : 0.0;
    if (straight_m_ >= options_.straight_before_turn_m && !pass_heading_set_) {
      pass_heading_set_ = true;  // the direction of the corridor the pass started in
      pass_heading_rad_ = pose.theta_rad;
    }
    // Turn round beside a straight wall, heading as the pass started (corrected for the odometry's drift):
    // back in the corridor it started in, not in a side corridor (where turning round and following the same
    // side would re-trace the pass just ended). Without a heading (no straight stretch in the whole pass), or
    // still no such place after driving 2 × min_revisit_travel_m more, any straight stretch will do.
    const bool heading_ok = !turn_heading_set_ ||
                            total_distance_m_ - turn_pending_since_m_ > 2.0 * options_.min_revisit_travel_m ||
                            std::fabs(NormalizeAngle(pose.theta_rad - turn_heading_rad_)) <=
                                options_.turn_heading_tolerance_rad;
    if (turn_pending_ && straight_m_ >= options_.straight_before_turn_m && heading_ok) {
      turn_pending_ = false;
      phase_ = ExplorePhase::kTurnAround;
      turned_rad_ = 0.0;
    }
  }
  if (phase_ == ExplorePhase::kTurnAround) {
    turned_rad_ += std::fabs(yaw_change);
    if (turned_rad_ < M_PI - options_.turn_tolerance_rad) {
      const double away = options_.steering.wall_side == "left" ? -1.0 : 1.0;
      return {0.0, away * options_.turn_speed_rps};
    }
    phase_ = ExplorePhase::kFollow;
    ++pass_;
    pass_start_pose_ = pose;
    pass_start_distance_m_ = total_distance_m_;
    left_start_ = false;
    pass_heading_set_ = false;
    straight_m_ = 0.0;
  }
  if (phase_ == ExplorePhase::kFollow && !turn_pending_) {
    const double from_start = Norm(pose.Position() - pass_start_pose_.Position());
    if (from_start > options_.revisit_radius_m) left_start_ = true;
    if (pass_distance_m() >= options_.max_pass_distance_m) {
      EndPass(PassEnd::kMaxDistance);
    } else if (left_start_ && pass_distance_m() >= options_.min_revisit_travel_m &&
               from_start <= options_.revisit_radius_m &&
               std::fabs(NormalizeAngle(pose.theta_rad - pass_start_pose_.theta_rad)) <= M_PI / 4) {
      EndPass(PassEnd::kPoseRevisited);
    }
  }
  if (phase_ != ExplorePhase::kFollow) return {};  // the turn starts at the next step; done: stop
  last_steering_ = steering_.Step(ranges_m, angle_min_rad, angle_increment_rad);
  return last_steering_.command;
}

}  // namespace doorplate_localization

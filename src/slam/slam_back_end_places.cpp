// The back end's scan budget on mapped ground (SlamBackEndOptions::max_nodes_per_place): which earlier
// nodes are other visits of a place, and the turn-arounds by odometry that tell one visit from the next.
#include <algorithm>
#include <cmath>
#include <optional>

#include "doorplate_localization/slam/slam_back_end.h"

namespace doorplate_localization {

int SlamBackEnd::TurnAroundsAt(const Pose2D& odometry_pose) const {
  if (nodes_.empty() || !(options_.place_turn_around_rad > 0)) return turn_arounds_;
  const double heading =
      unwrapped_heading_rad_ + NormalizeAngle(odometry_pose.theta_rad - nodes_.back().odometry.theta_rad);
  return turn_arounds_ + (std::abs(heading - turn_reference_rad_) >= options_.place_turn_around_rad ? 1 : 0);
}

void SlamBackEnd::NoteTurnArounds(const Pose2D& odometry_pose) {
  const int turns = TurnAroundsAt(odometry_pose);
  if (!nodes_.empty()) {
    unwrapped_heading_rad_ += NormalizeAngle(odometry_pose.theta_rad - nodes_.back().odometry.theta_rad);
  }
  if (turns > turn_arounds_) turn_arounds_ = turns, turn_reference_rad_ = unwrapped_heading_rad_;
}

std::optional<int> SlamBackEnd::FullPlaceAnchor(const Pose2D& front_end_pose, const Pose2D& odometry_pose) const {
  if (options_.max_nodes_per_place <= 0) return std::nullopt;
  const double path_m = OdometryPathTo(odometry_pose);
  const int turn_arounds_now = TurnAroundsAt(odometry_pose);
  int count = 0, nearest = -1;
  double nearest_d = options_.place_radius_m;
  // Earlier visits only: the nodes of this visit (a turn on the spot makes a dozen in one place) map it.
  const int earlier_than = num_nodes() + 1 - options_.loop_closure_min_separation;  // i + separation <= new
  for (int i = 0; i < earlier_than; ++i) {
    if (!nodes_[i].has_points) continue;
    const Pose2D& p = nodes_[i].front_end;
    const double d = Norm(p.Position() - front_end_pose.Position());
    if (d >= options_.place_radius_m ||
        std::abs(NormalizeAngle(p.theta_rad - front_end_pose.theta_rad)) > options_.place_max_heading_diff_rad) {
      continue;
    }
    const double moved_m = Norm(odometry_pose.Position() - nodes_[i].odometry.Position());
    const double driven_m = path_m - nodes_[i].odometry_path_m;
    const bool turned_round = nodes_[i].turn_arounds < turn_arounds_now;
    if (!turned_round && moved_m > std::max(options_.place_radius_m,
                                            options_.place_max_odometry_displacement_fraction * driven_m)) {
      continue;  // the same pass, driven on while the front end's pose stood still: not a revisit
    }
    ++count;
    if (d < nearest_d) nearest_d = d, nearest = i;
  }
  if (count < options_.max_nodes_per_place) return std::nullopt;
  return nearest;
}

}  // namespace doorplate_localization

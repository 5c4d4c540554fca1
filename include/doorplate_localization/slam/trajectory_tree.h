// Particle trajectories as a tree of shared nodes (as in gmapping): a particle holds its newest node;
// resampling copies the pointer, so particles with a common ancestor share their common history
// instead of copying it. Nodes are immutable once made.
#pragma once

#include <memory>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct TrajectoryPoint {
  int scan_index = 0;  // caller's index of the scan processed at this pose
  Pose2D pose;         // base_link in the map frame
};

class TrajectoryNode {
 public:
  TrajectoryNode(TrajectoryPoint point, std::shared_ptr<const TrajectoryNode> parent)
      : point_(point), parent_(std::move(parent)) {}
  // Frees a long chain without recursing once per node (histories can be 10^5 nodes deep).
  ~TrajectoryNode();
  TrajectoryNode(const TrajectoryNode&) = delete;
  TrajectoryNode& operator=(const TrajectoryNode&) = delete;

  const TrajectoryPoint& point() const { return point_; }
  const std::shared_ptr<const TrajectoryNode>& parent() const { return parent_; }

 private:
  TrajectoryPoint point_;
  mutable std::shared_ptr<const TrajectoryNode> parent_;  // mutable only for the destructor's unlinking
};

using TrajectoryHandle = std::shared_ptr<const TrajectoryNode>;

// A new newest node after `head` (which may be null for the first pose).
TrajectoryHandle ExtendTrajectory(const TrajectoryHandle& head, const TrajectoryPoint& point);

// The history ending at `head`, oldest first.
std::vector<TrajectoryPoint> UnrollTrajectory(const TrajectoryHandle& head);

}  // namespace doorplate_localization

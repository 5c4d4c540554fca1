#include "doorplate_localization/slam/trajectory_tree.h"

#include <algorithm>

namespace doorplate_localization {

TrajectoryNode::~TrajectoryNode() {
  // Take over the chain of ancestors that only this node keeps alive, one at a time: each is
  // destroyed after its own parent link was moved out, so no destructor recurses.
  std::shared_ptr<const TrajectoryNode> next = std::move(parent_);
  while (next && next.use_count() == 1) {
    std::shared_ptr<const TrajectoryNode> after = std::move(next->parent_);
    next = std::move(after);
  }
}

TrajectoryHandle ExtendTrajectory(const TrajectoryHandle& head, const TrajectoryPoint& point) {
  return std::make_shared<const TrajectoryNode>(point, head);
}

std::vector<TrajectoryPoint> UnrollTrajectory(const TrajectoryHandle& head) {
  std::vector<TrajectoryPoint> points;
  for (const TrajectoryNode* n = head.get(); n != nullptr; n = n->parent().get()) {
    points.push_back(n->point());
  }
  std::reverse(points.begin(), points.end());
  return points;
}

}  // namespace doorplate_localization

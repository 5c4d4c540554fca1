#include "doorplate_localization/slam/trajectory_tree.h"

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

TEST(Trajectory, UnrollsOldestFirst) {
  TrajectoryHandle head;
  for (int i = 0; i < 4; ++i) head = ExtendTrajectory(head, {i * 10, {double(i), 0, 0}});
  const std::vector<TrajectoryPoint> points = UnrollTrajectory(head);
  ASSERT_EQ(points.size(), 4u);
  EXPECT_EQ(points.front().scan_index, 0);
  EXPECT_EQ(points.back().scan_index, 30);
  EXPECT_EQ(points.back().pose.x_m, 3.0);
}

TEST(Trajectory, BranchesShareTheirCommonHistoryInsteadOfCopyingIt) {
  const TrajectoryHandle root = ExtendTrajectory(nullptr, {0, {}});
  const TrajectoryHandle common = ExtendTrajectory(root, {1, {1, 0, 0}});
  const TrajectoryHandle a = ExtendTrajectory(common, {2, {2, 0, 0}});
  const TrajectoryHandle b = ExtendTrajectory(common, {2, {2, 1, 0}});
  EXPECT_EQ(a->parent().get(), b->parent().get());
  EXPECT_EQ(common.use_count(), 3);  // `common` itself, and the two branches
  EXPECT_EQ(UnrollTrajectory(a)[1].pose.x_m, UnrollTrajectory(b)[1].pose.x_m);
}

TEST(Trajectory, ADroppedBranchFreesOnlyItsOwnNodes) {
  const TrajectoryHandle common = ExtendTrajectory(nullptr, {0, {}});
  std::weak_ptr<const TrajectoryNode> leaf;
  {
    const TrajectoryHandle branch = ExtendTrajectory(common, {1, {}});
    leaf = branch;
  }
  EXPECT_TRUE(leaf.expired());
  EXPECT_EQ(UnrollTrajectory(common).size(), 1u);
}

TEST(Trajectory, ALongHistoryIsFreedWithoutDeepRecursion) {
  TrajectoryHandle head;
  for (int i = 0; i < 300000; ++i) head = ExtendTrajectory(head, {i, {}});
  head.reset();  // would overflow the stack if every node freed its parent recursively
  SUCCEED();
}

}  // namespace
}  // namespace doorplate_localization

#include "go_to_room_conversions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include <tf2/LinearMath/Quaternion.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

namespace doorplate_localization {
namespace {

TEST(GoToRoomConversions, TheGoalPoseCarriesFrameStampPositionAndYaw) {
  const geometry_msgs::PoseStamped goal = ToGoalPoseMsg({8.5, 1.4, M_PI / 2}, "map", ros::Time(12, 5));
  EXPECT_EQ(goal.header.frame_id, "map");
  EXPECT_EQ(goal.header.stamp, ros::Time(12, 5));
  EXPECT_DOUBLE_EQ(goal.pose.position.x, 8.5);
  EXPECT_DOUBLE_EQ(goal.pose.position.y, 1.4);
  EXPECT_DOUBLE_EQ(goal.pose.position.z, 0.0);
  EXPECT_NEAR(tf2::getYaw(goal.pose.orientation), M_PI / 2, 1e-9);
}

TEST(GoToRoomConversions, ATwistHasOnlyForwardSpeedAndYawRate) {
  const geometry_msgs::Twist twist = ToTwistMsg({0.3, -0.2});
  EXPECT_DOUBLE_EQ(twist.linear.x, 0.3);
  EXPECT_DOUBLE_EQ(twist.angular.z, -0.2);
  EXPECT_EQ(twist.linear.y, 0.0);
  EXPECT_EQ(twist.angular.x, 0.0);
}

TEST(GoToRoomConversions, APathHasOnePoseOfItsFrameAndStampPerWaypoint) {
  const nav_msgs::Path path = ToPathMsg({{1.0, 2.0}, {3.5, -1.0}}, "map", ros::Time(7, 0));
  EXPECT_EQ(path.header.frame_id, "map");
  ASSERT_EQ(path.poses.size(), 2u);
  EXPECT_EQ(path.poses[1].header.frame_id, "map");
  EXPECT_EQ(path.poses[1].header.stamp, ros::Time(7, 0));
  EXPECT_DOUBLE_EQ(path.poses[1].pose.position.x, 3.5);
  EXPECT_DOUBLE_EQ(path.poses[1].pose.position.y, -1.0);
  EXPECT_DOUBLE_EQ(path.poses[1].pose.orientation.w, 1.0);
  EXPECT_TRUE(ToPathMsg({}, "map", ros::Time(7, 0)).poses.empty());
}

TEST(StatusThrottle, PublishesEachNewStateAtOnceAndNewNumbersAtMostOnceASecond) {
  StatusThrottle throttle;
  EXPECT_TRUE(throttle.Due("idle", 0.0));
  EXPECT_FALSE(throttle.Due("idle", 5.0)) << "the same text again";
  EXPECT_TRUE(throttle.Due("following: room 205, 12.0 m to go", 5.1));
  EXPECT_FALSE(throttle.Due("following: room 205, 11.9 m to go", 5.5));
  EXPECT_TRUE(throttle.Due("following: room 205, 11.5 m to go", 6.2));
  EXPECT_TRUE(throttle.Due("arrived: room 205", 6.3)) << "a new state is never held back";
}

}  // namespace
}  // namespace doorplate_localization

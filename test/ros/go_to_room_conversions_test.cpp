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

}  // namespace
}  // namespace doorplate_localization

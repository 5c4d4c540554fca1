#include "go_to_room_conversions.h"

#include "doorplate_localization/ros/pose_conversions.h"

namespace doorplate_localization {

geometry_msgs::PoseStamped ToGoalPoseMsg(const Pose2D& pose, const std::string& frame_id, const ros::Time& stamp) {
  geometry_msgs::PoseStamped msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  msg.pose = ToPoseMsg(pose);
  return msg;
}

geometry_msgs::Twist ToTwistMsg(const VelocityCommand& command) {
  geometry_msgs::Twist twist;
  twist.linear.x = command.linear_mps;
  twist.angular.z = command.angular_rps;
  return twist;
}

}  // namespace doorplate_localization

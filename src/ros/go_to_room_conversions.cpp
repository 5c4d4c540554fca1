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

nav_msgs::Path ToPathMsg(const std::vector<Vec2>& waypoints, const std::string& frame_id, const ros::Time& stamp) {
  nav_msgs::Path path;
  path.header.frame_id = frame_id;
  path.header.stamp = stamp;
  for (const Vec2& p : waypoints) {
    geometry_msgs::PoseStamped pose;
    pose.header = path.header;
    pose.pose.position.x = p.x;
    pose.pose.position.y = p.y;
    pose.pose.orientation.w = 1.0;
    path.poses.push_back(pose);
  }
  return path;
}

bool StatusThrottle::Due(const std::string& status, double now_s) {
  const std::string state = status.substr(0, status.find(':'));
  if (status == last_status_) return false;
  if (state == last_state_ && now_s - last_time_s_ < 1.0) return false;
  last_status_ = status;
  last_state_ = state;
  last_time_s_ = now_s;
  return true;
}

geometry_msgs::Twist ToTwistMsg(const VelocityCommand& command) {
  geometry_msgs::Twist twist;
  twist.linear.x = command.linear_mps;
  twist.angular.z = command.angular_rps;
  return twist;
}

}  // namespace doorplate_localization

// Message conversions of GoToRoomNodelet (poses, camera side and plate texts are shared with the other
// nodelets: pose_conversions.h, text_detection_conversions.h). Pure functions: no node handle, no clock;
// stamps and frames are passed in. Units follow the messages: metres, radians, m/s, rad/s.
#pragma once

#include <string>
#include <vector>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Path.h>
#include <ros/time.h>

#include "doorplate_localization/behaviour/wall_follower.h"
#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

// A goal pose for rviz: `pose` in `frame_id` at height 0, rotation yaw only.
geometry_msgs::PoseStamped ToGoalPoseMsg(const Pose2D& pose, const std::string& frame_id, const ros::Time& stamp);

// A planned path for rviz: one pose per waypoint (in `frame_id`, height 0, identity rotation).
nav_msgs::Path ToPathMsg(const std::vector<Vec2>& waypoints, const std::string& frame_id, const ros::Time& stamp);

// ~status's rate: a status is due when its state (the text before ':') changes, and at most once a second
// (`now_s`, any clock) while only the rest (the numbers) changes; never the same text twice in a row.
class StatusThrottle {
 public:
  bool Due(const std::string& status, double now_s);  // true: publish it now (it counts as published)

 private:
  std::string last_status_, last_state_;
  double last_time_s_ = 0.0;
};

// A velocity command for base_link: linear.x and angular.z, the rest 0.
geometry_msgs::Twist ToTwistMsg(const VelocityCommand& command);

}  // namespace doorplate_localization

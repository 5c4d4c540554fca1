// Message conversions of GoToRoomNodelet (poses, camera side and plate texts are shared with the other
// nodelets: pose_conversions.h, text_detection_conversions.h). Pure functions: no node handle, no clock;
// stamps and frames are passed in. Units follow the messages: metres, radians, m/s, rad/s.
#pragma once

#include <string>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <ros/time.h>

#include "doorplate_localization/behaviour/wall_follower.h"
#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

// A goal pose for rviz: `pose` in `frame_id` at height 0, rotation yaw only.
geometry_msgs::PoseStamped ToGoalPoseMsg(const Pose2D& pose, const std::string& frame_id, const ros::Time& stamp);

// A velocity command for base_link: linear.x and angular.z, the rest 0.
geometry_msgs::Twist ToTwistMsg(const VelocityCommand& command);

}  // namespace doorplate_localization

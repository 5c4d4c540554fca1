// Planar poses <-> geometry_msgs, the map -> odom correction, and a camera's viewing direction from tf;
// shared by every nodelet and tool (library doorplate_ros_conversions). Pure functions: no node handle,
// no clock, no tf buffer; stamps and frame ids are passed in. Units: metres, radians. Frames follow
// REP-103 (x forward, y left, z up); a planar pose is x, y and the yaw about z, and the z, roll and pitch
// of an incoming 3D pose are dropped.
#pragma once

#include <optional>
#include <string>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>
#include <tf2/LinearMath/Vector3.h>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/sensors/plate_reading.h"

namespace doorplate_localization {

// --- planar pose -> message ---
// A rotation about z by `yaw_rad` (a unit quaternion; yaw beyond ±pi wraps to the same orientation).
geometry_msgs::Quaternion ToYawQuaternionMsg(double yaw_rad);
// A planar pose (child in parent) as a 3D pose / transform at height z_m; rotation is yaw only.
geometry_msgs::Pose ToPoseMsg(const Pose2D& pose, double z_m = 0.0);
geometry_msgs::Transform ToTransformMsg(const Pose2D& pose, double z_m = 0.0);
geometry_msgs::TransformStamped ToTransformStampedMsg(const Pose2D& child_in_parent, const std::string& parent_frame,
                                                      const std::string& child_frame, const ros::Time& stamp,
                                                      double z_m = 0.0);

// --- message -> planar pose ---
// True if every number of the pose (position and quaternion) is finite.
bool IsFinitePose(const geometry_msgs::Pose& pose);
// sqrt(x² + y² + z² + w²): 1 for a rotation; ~0 for an unset (all-zero) quaternion.
double QuaternionNorm(const geometry_msgs::Quaternion& q);
// x, y and the yaw of the rotated x axis (= tf2::getYaw; a non-unit quaternion is used as if normalized, a
// zero one gives yaw 0). Throws std::invalid_argument for a non-finite position/translation or rotation
// (tf2 itself never stores one, so a throw means a message that did not come through tf2).
Pose2D ToPose2D(const geometry_msgs::Transform& transform);
Pose2D ToPose2D(const geometry_msgs::Pose& pose);

// Axis `axis` (a unit vector of the child frame) expressed in the parent frame, from the child's rotation
// in the parent; a non-unit quaternion is normalized, a zero one counts as the identity.
tf2::Vector3 ChildAxisInParent(const geometry_msgs::Quaternion& child_in_parent, const tf2::Vector3& axis);

// --- map -> odom ---
// map -> odom from the same instant's base_link in map (the SLAM / filter estimate) and base_link in odom
// (the odometry the estimate was made with): map_T_odom = map_T_base ⊕ (odom_T_base)⁻¹. Publish it with
// ToTransformStampedMsg(MapToOdom(...), map_frame, odom_frame, stamp).
Pose2D MapToOdom(const Pose2D& base_in_map, const Pose2D& base_in_odom);

// --- cameras ---
// The camera's optical axis (CameraAxis, sensors/plate_reading.h) from its optical frame (z forward, x right,
// y down; the sensor_msgs/Image convention) in base_link. Returns "" and fills *axis, or the problem (an
// optical axis more than 25° out of the floor plane, where a plate bearing is meaningless); *axis is left alone on error. A plate seen at image bearing b lies at
// yaw_rad + bearing_sign * b in base_link (BearingInBase).
std::string ToCameraAxis(const geometry_msgs::Transform& optical_in_base, CameraAxis* axis);

// Which side of base_link a camera looks to: true = left (+y), false = right (−y); nullopt when
// ToCameraAxis refuses the frame or the axis is within 45° of straight ahead or behind (not a sideways
// camera, so a plate's side is unknown).
std::optional<bool> CameraLooksLeft(const geometry_msgs::Transform& optical_in_base);

}  // namespace doorplate_localization

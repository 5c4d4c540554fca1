#include "doorplate_localization/ros/pose_conversions.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <tf2/LinearMath/Quaternion.h>
#include <tf2/LinearMath/Vector3.h>
#include <tf2/utils.h>

namespace doorplate_localization {
namespace {

bool IsFinite(const geometry_msgs::Quaternion& q) {
  return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w);
}

// The quaternion divided by its largest component: the same rotation, without the overflow (components
// near 1e300) or underflow (near 1e-300) in tf2::getYaw's products that made a finite quaternion's yaw NaN
// (a fuzzing find, issue 18: a map message with such an origin was accepted with a NaN origin yaw).
geometry_msgs::Quaternion Rescaled(const geometry_msgs::Quaternion& q) {
  const double m = std::max({std::fabs(q.x), std::fabs(q.y), std::fabs(q.z), std::fabs(q.w)});
  if (!(m > 0.0)) return q;
  geometry_msgs::Quaternion s;
  s.x = q.x / m, s.y = q.y / m, s.z = q.z / m, s.w = q.w / m;
  return s;
}

}  // namespace

geometry_msgs::Quaternion ToYawQuaternionMsg(double yaw_rad) {
  geometry_msgs::Quaternion q;  // setRPY(0, 0, yaw): x = y = 0
  q.z = std::sin(yaw_rad / 2.0);
  q.w = std::cos(yaw_rad / 2.0);
  return q;
}

geometry_msgs::Pose ToPoseMsg(const Pose2D& pose, double z_m) {
  geometry_msgs::Pose msg;
  msg.position.x = pose.x_m;
  msg.position.y = pose.y_m;
  msg.position.z = z_m;
  msg.orientation = ToYawQuaternionMsg(pose.theta_rad);
  return msg;
}

geometry_msgs::Transform ToTransformMsg(const Pose2D& pose, double z_m) {
  geometry_msgs::Transform msg;
  msg.translation.x = pose.x_m;
  msg.translation.y = pose.y_m;
  msg.translation.z = z_m;
  msg.rotation = ToYawQuaternionMsg(pose.theta_rad);
  return msg;
}

geometry_msgs::TransformStamped ToTransformStampedMsg(const Pose2D& child_in_parent, const std::string& parent_frame,
                                                      const std::string& child_frame, const ros::Time& stamp,
                                                      double z_m) {
  geometry_msgs::TransformStamped msg;
  msg.header.frame_id = parent_frame;
  msg.header.stamp = stamp;
  msg.child_frame_id = child_frame;
  msg.transform = ToTransformMsg(child_in_parent, z_m);
  return msg;
}

bool IsFinitePose(const geometry_msgs::Pose& pose) {
  return std::isfinite(pose.position.x) && std::isfinite(pose.position.y) && std::isfinite(pose.position.z) &&
         IsFinite(pose.orientation);
}

double QuaternionNorm(const geometry_msgs::Quaternion& q) {
  return std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
}

Pose2D ToPose2D(const geometry_msgs::Transform& transform) {
  const auto& t = transform.translation;
  if (!std::isfinite(t.x) || !std::isfinite(t.y) || !IsFinite(transform.rotation)) {
    throw std::invalid_argument("transform with a non-finite translation or rotation");
  }
  return {t.x, t.y, tf2::getYaw(Rescaled(transform.rotation))};
}

Pose2D ToPose2D(const geometry_msgs::Pose& pose) {
  geometry_msgs::Transform t;
  t.translation.x = pose.position.x;
  t.translation.y = pose.position.y;
  t.rotation = pose.orientation;
  return ToPose2D(t);
}

tf2::Vector3 ChildAxisInParent(const geometry_msgs::Quaternion& child_in_parent, const tf2::Vector3& axis) {
  tf2::Quaternion q(child_in_parent.x, child_in_parent.y, child_in_parent.z, child_in_parent.w);
  if (q.length2() < 1e-12) return axis;
  return tf2::quatRotate(q.normalized(), axis);
}

Pose2D MapToOdom(const Pose2D& base_in_map, const Pose2D& base_in_odom) {
  return base_in_map.Compose(base_in_odom.Inverse());
}

std::string ToCameraAxis(const geometry_msgs::Transform& optical_in_base, CameraAxis* axis) {
  if (!IsFinite(optical_in_base.rotation)) return "the camera's rotation is not finite";
  const tf2::Vector3 view = ChildAxisInParent(optical_in_base.rotation, tf2::Vector3(0, 0, 1));
  if (std::fabs(view.z()) > std::sin(25.0 * M_PI / 180.0)) {
    std::ostringstream problem;
    problem << "the camera's optical axis points " << std::asin(std::clamp(view.z(), -1.0, 1.0)) * 180.0 / M_PI
            << " deg out of the floor plane (at most 25 deg)";
    return problem.str();
  }
  const tf2::Vector3 image_left = -ChildAxisInParent(optical_in_base.rotation, tf2::Vector3(1, 0, 0));
  axis->yaw_rad = std::atan2(view.y(), view.x());
  axis->bearing_sign = view.cross(image_left).z() >= 0.0 ? 1.0 : -1.0;
  return "";
}

std::optional<bool> CameraLooksLeft(const geometry_msgs::Transform& optical_in_base) {
  CameraAxis axis;
  if (!ToCameraAxis(optical_in_base, &axis).empty()) return std::nullopt;
  const double side = std::sin(axis.yaw_rad), ahead = std::cos(axis.yaw_rad);
  if (std::fabs(side) <= std::fabs(ahead)) return std::nullopt;
  return side > 0.0;
}

}  // namespace doorplate_localization

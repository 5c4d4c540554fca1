#include "doorplate_localization/ros/tf_lookup.h"

#include <stdexcept>

#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/ros/pose_conversions.h"

namespace doorplate_localization {
namespace {

// Frame names come from messages: a 1 MB frame_id is quoted by its start only (tf2's reason quotes it too).
std::string NoTf(const std::string& target, const std::string& source, const char* reason) {
  return "no tf from '" + limits::TruncateForLog(source) + "' to '" + limits::TruncateForLog(target) +
         "': " + limits::TruncateForLog(reason, 4 * limits::kMaxLoggedTextBytes);
}

}  // namespace

std::optional<geometry_msgs::Transform> LookupTransform(const tf2_ros::Buffer& buffer, const std::string& target,
                                                        const std::string& source, const ros::Time& stamp,
                                                        double timeout_s, std::string* problem) {
  try {
    return buffer.lookupTransform(target, source, stamp, ros::Duration(timeout_s)).transform;
  } catch (const tf2::TransformException& e) {
    *problem = NoTf(target, source, e.what());
  }
  return std::nullopt;
}

std::optional<geometry_msgs::Transform> LookupTransform(const tf2::BufferCore& buffer, const std::string& target,
                                                        const std::string& source, const ros::Time& stamp,
                                                        std::string* problem) {
  try {
    return buffer.lookupTransform(target, source, stamp).transform;
  } catch (const tf2::TransformException& e) {
    *problem = NoTf(target, source, e.what());
  }
  return std::nullopt;
}

std::optional<Pose2D> LookupPlanarPose(const tf2_ros::Buffer& buffer, const std::string& target,
                                       const std::string& source, const ros::Time& stamp, double timeout_s,
                                       std::string* problem) {
  const std::optional<geometry_msgs::Transform> transform =
      LookupTransform(buffer, target, source, stamp, timeout_s, problem);
  if (!transform) return std::nullopt;
  try {
    return ToPose2D(*transform);
  } catch (const std::invalid_argument& e) {  // a non-finite transform
    *problem = "tf from '" + source + "' to '" + target + "': " + e.what();
  }
  return std::nullopt;
}

}  // namespace doorplate_localization

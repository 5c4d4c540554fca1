#include "doorplate_localization/ros/tf_lookup.h"

#include <cstdio>
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

std::optional<geometry_msgs::TransformStamped> LookupStamped(const tf2_ros::Buffer& buffer, const std::string& target,
                                                             const std::string& source, const ros::Time& stamp,
                                                             double timeout_s, std::string* problem) {
  try {
    return buffer.lookupTransform(target, source, stamp, ros::Duration(timeout_s));
  } catch (const tf2::TransformException& e) {
    *problem = NoTf(target, source, e.what());
  }
  return std::nullopt;
}

std::optional<Pose2D> PlanarPose(const geometry_msgs::Transform& transform, const std::string& target,
                                 const std::string& source, std::string* problem) {
  try {
    return ToPose2D(transform);
  } catch (const std::invalid_argument& e) {  // a non-finite transform
    *problem = "tf from '" + source + "' to '" + target + "': " + e.what();
  }
  return std::nullopt;
}

}  // namespace

std::optional<geometry_msgs::Transform> LookupTransform(const tf2_ros::Buffer& buffer, const std::string& target,
                                                        const std::string& source, const ros::Time& stamp,
                                                        double timeout_s, std::string* problem) {
  const auto stamped = LookupStamped(buffer, target, source, stamp, timeout_s, problem);
  if (!stamped) return std::nullopt;
  return stamped->transform;
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
  return PlanarPose(*transform, target, source, problem);
}

std::optional<Pose2D> LookupLatestPlanarPose(const tf2_ros::Buffer& buffer, const std::string& target,
                                             const std::string& source, const ros::Time& needed_at, double max_lag_s,
                                             double timeout_s, std::string* problem) {
  const auto latest = LookupStamped(buffer, target, source, ros::Time(0), timeout_s, problem);
  if (!latest) return std::nullopt;
  const double lag_s = (needed_at - latest->header.stamp).toSec();
  if (lag_s > max_lag_s) {
    char text[160];
    std::snprintf(text, sizeof(text), " is %.3f s older than needed (at %.3f s; limit %.3f s)", lag_s,
                  needed_at.toSec(), max_lag_s);
    *problem = "the latest tf from '" + limits::TruncateForLog(source) + "' to '" + limits::TruncateForLog(target) +
               "'" + text;
    return std::nullopt;
  }
  return PlanarPose(latest->transform, target, source, problem);
}

}  // namespace doorplate_localization

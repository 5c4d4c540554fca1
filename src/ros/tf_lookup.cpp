#include "doorplate_localization/ros/tf_lookup.h"

#include <stdexcept>

#include "doorplate_localization/ros/pose_conversions.h"

namespace doorplate_localization {

std::optional<Pose2D> LookupPlanarPose(const tf2_ros::Buffer& buffer, const std::string& target,
                                       const std::string& source, const ros::Time& stamp, double timeout_s,
                                       std::string* problem) {
  try {
    return ToPose2D(buffer.lookupTransform(target, source, stamp, ros::Duration(timeout_s)).transform);
  } catch (const tf2::TransformException& e) {
    *problem = "no tf from '" + source + "' to '" + target + "': " + e.what();
  } catch (const std::invalid_argument& e) {  // a non-finite transform
    *problem = "tf from '" + source + "' to '" + target + "': " + e.what();
  }
  return std::nullopt;
}

}  // namespace doorplate_localization

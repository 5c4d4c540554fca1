#include "doorplate_localization/ros/scan_conversions.h"

#include <cmath>
#include <sstream>
#include <string>

#include "doorplate_localization/common/limits.h"

namespace doorplate_localization {

std::string ValidateScan(const sensor_msgs::LaserScan& scan) {
  std::ostringstream problem;
  if (scan.header.frame_id.empty()) {
    problem << "header.frame_id is empty";
  } else if (scan.ranges.empty()) {
    problem << "no ranges";
  } else if (scan.ranges.size() > limits::kMaxScanBeams) {
    problem << scan.ranges.size() << " ranges, more than the limit of " << limits::kMaxScanBeams
            << " (limits::kMaxScanBeams)";
  } else if (!std::isfinite(scan.angle_increment) || scan.angle_increment == 0.0f) {
    problem << "angle_increment must be finite and non-zero, got " << scan.angle_increment;
  } else if (!std::isfinite(scan.angle_min)) {
    problem << "angle_min must be finite, got " << scan.angle_min;
  } else if (std::fabs(scan.angle_increment) * (scan.ranges.size() - 1) > 2.0 * M_PI + 1e-3) {
    problem << scan.ranges.size() << " beams of " << scan.angle_increment << " rad span more than a full turn";
  } else if (!(scan.range_max > scan.range_min) || !std::isfinite(scan.range_max) || scan.range_min < 0.0f) {
    problem << "need 0 <= range_min < range_max < inf, got range_min " << scan.range_min << ", range_max "
            << scan.range_max;
  } else {
    // angle_min .. angle_max at angle_increment must make about ranges.size() beams. Drivers disagree on
    // whether angle_max is the last beam's angle or one increment past it: one beam either way is allowed.
    const double span_beams =
        (static_cast<double>(scan.angle_max) - scan.angle_min) / scan.angle_increment + 1.0;
    if (!std::isfinite(span_beams) || std::fabs(span_beams - static_cast<double>(scan.ranges.size())) > 1.5) {
      problem << scan.ranges.size() << " ranges, but angle_min " << scan.angle_min << " .. angle_max "
              << scan.angle_max << " at increment " << scan.angle_increment << " make "
              << (std::isfinite(span_beams) ? std::to_string(std::lround(span_beams)) : std::string("no whole number of"))
              << " beams";
    }
  }
  return problem.str();
}

bool IsValidRange(const sensor_msgs::LaserScan& scan, float r) {
  return std::isfinite(r) && r >= scan.range_min && r <= scan.range_max;
}

}  // namespace doorplate_localization

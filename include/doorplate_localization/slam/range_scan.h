// One planar laser scan as the SLAM core consumes it, independent of ROS and of the log format.
// Frames: beam angles are in the laser frame; `laser_pose` is the laser frame in base_link.
// Units: metres, radians. REP-117: a beam with no echo is +inf; NaN, negatives and values below
// `min_range_m` are invalid and skipped.
#pragma once

#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/sensors/plate_range.h"

namespace doorplate_localization {

struct RangeScan {
  double angle_min_rad = 0.0;        // angle of beam 0 in the laser frame
  double angle_increment_rad = 0.0;  // angle between consecutive beams
  double min_range_m = 0.0;          // shorter readings are invalid
  std::vector<float> ranges_m;       // +inf: no echo (the beam saw free space as far as the device sees)
  Pose2D laser_pose;                 // laser frame in base_link

  double BeamAngle(int i) const { return angle_min_rad + i * angle_increment_rad; }
};

// The scan's beams as the shared sensor rules read them (no max range: every finite reading is an echo).
inline BeamGeometry BeamGeometryOf(const RangeScan& scan) {
  BeamGeometry g;
  g.angle_min_rad = scan.angle_min_rad;
  g.angle_increment_rad = scan.angle_increment_rad;
  g.min_range_m = scan.min_range_m;
  g.laser_pose = scan.laser_pose;
  return g;
}

}  // namespace doorplate_localization

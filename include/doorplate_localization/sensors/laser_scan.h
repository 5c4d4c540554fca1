// One planar laser scan, the core's only scan type: what the simulator produces, the mapping session and the
// localization session consume, and the ROS, CARMEN and MRPT-rawlog readers convert into.
// Frames: beam angles are in the laser frame (x forward, counter-clockwise, REP-103); `laser_pose` places the
// laser frame in base_link (the mounting pose). Units: metres, radians.
// Ranges follow REP-117: +inf = no echo within max range, -inf = too close, NaN = error; an echo is a finite
// reading in [min_range_m, max_range_m).
#pragma once

#include <limits>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/sensors/plate_range.h"

namespace doorplate_localization {

struct LaserScan {
  double angle_min_rad = 0.0;        // angle of ranges_m[0]
  double angle_increment_rad = 0.0;  // between consecutive beams (may be negative: upside-down mountings)
  double min_range_m = 0.0;          // shorter readings are invalid (sensor_msgs/LaserScan range_min)
  // Readings at or beyond this are no echo (range_max). +inf: the reader already wrote every no-echo beam
  // as +inf (the SLAM readers do), so every finite reading >= min_range_m is an echo. The localizer's beam
  // model needs a finite value (ValidateLocalizationScan).
  double max_range_m = std::numeric_limits<double>::infinity();
  std::vector<float> ranges_m;
  Pose2D laser_pose;                 // laser frame in base_link

  double BeamAngle(int i) const { return angle_min_rad + i * angle_increment_rad; }
};

// The scan's beams as the shared sensor rules read them (sensors/plate_range.h).
inline BeamGeometry BeamGeometryOf(const LaserScan& scan) {
  BeamGeometry g;
  g.angle_min_rad = scan.angle_min_rad;
  g.angle_increment_rad = scan.angle_increment_rad;
  g.min_range_m = scan.min_range_m;
  g.max_range_m = scan.max_range_m;
  g.laser_pose = scan.laser_pose;
  return g;
}

}  // namespace doorplate_localization

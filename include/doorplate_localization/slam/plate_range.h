// Where a doorplate lies along its bearing in one laser scan. A plate hangs on a wall, so besides the echoes
// right along the bearing (PlateRangeAlongBearing, text_slam.h) the wall's line around it tells its range,
// also when something stands between the robot and the plate (a person, a trolley): the echoes along the
// bearing then hit that, the echoes either side of it still trace the wall.
// Frames: the bearing and the returned range are in base_link (the scan's beams are in the laser frame,
// RangeScan::laser_pose places it). Units: metres, radians.
#pragma once

#include <optional>

#include "doorplate_localization/slam/range_scan.h"

namespace doorplate_localization {

struct WallRangeOptions {
  double window_rad = 1.0;          // echoes within ± this of the bearing (from base_link) are fitted
  double inlier_m = 0.04;           // an echo this close to a line supports it (door recesses: a few cm)
  int min_inliers = 12;             // fewer supporting echoes: no wall line
  double min_span_m = 1.0;          // the echoes on it span less: no wall (a person's front, a post)
  double max_incidence_rad = 1.2;   // the bearing meets the line at most this far from its normal (else it
                                    // is not the plate's wall: e.g. a corridor's end wall seen along it)
};

// Throws std::invalid_argument naming the field ("WallRangeOptions.window_rad ...") of a bad option.
void ValidateWallRangeOptions(const WallRangeOptions& options);

// The range from base_link along `bearing_rad` to the straight line most echoes within the window lie on:
// the strongest line of a Hough transform of the echoes (cv::HoughLinesPointSet, lines whose normal is
// within max_incidence_rad of the bearing, rho bins of inlier_m), refined by a least-squares fit
// (cv::fitLine) to the echoes within inlier_m of it. Of the transform's candidates the one whose echoes span
// the longest stretch is the wall (a person before the plate has more echoes per metre, a shorter front).
// Deterministic (no random draws). nullopt when no candidate has min_inliers echoes spanning min_span_m, or
// the ray meets the line behind the robot.
std::optional<double> WallRangeAlongBearing(const RangeScan& scan, double bearing_rad, const WallRangeOptions& options);

}  // namespace doorplate_localization

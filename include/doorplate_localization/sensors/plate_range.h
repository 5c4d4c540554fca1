// Where a doorplate lies along its bearing in one laser scan: the one rule of the mapping session
// (slam/mapping_session.h) and of the localization session (mcl/text_amcl_session.h) for the range of a
// plate reading (the paper's text observation z = (text, bearing, range)).
// The echoes right along the bearing give the range, unless something stands between the robot and the
// plate (a person, a trolley): a plate hangs on a wall, and the echoes either side of that thing still
// trace the wall's line, so when the echoes along the bearing are clearly shorter than that line, the
// line's range is taken.
// Frames: the bearing and every returned range are in base_link (beam angles are in the laser frame,
// BeamGeometry::laser_pose places it in base_link). Units: metres, radians.
#pragma once

#include <limits>
#include <optional>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

// A planar scan's beams: ranges_m[i] is measured at angle_min_rad + i * angle_increment_rad (laser frame).
// An echo is a finite reading in [min_range_m, max_range_m) (REP-117: +inf and max-range readings are no
// echo; NaN, -inf and shorter readings are invalid).
struct BeamGeometry {
  double angle_min_rad = 0.0;
  double angle_increment_rad = 0.0;
  double min_range_m = 0.0;
  double max_range_m = std::numeric_limits<double>::infinity();
  Pose2D laser_pose;  // the laser frame in base_link
};

struct WallRangeOptions {
  double window_rad = 1.0;          // echoes within ± this of the bearing (from base_link) are fitted
  double inlier_m = 0.04;           // an echo this close to a line supports it (door recesses: a few cm)
  int min_inliers = 12;             // fewer supporting echoes: no wall line
  double min_length_m = 1.0;        // the echoes on it cover less (gaps count <= 0.25 m): no wall (a person's
                                    // front, a post)
  double max_incidence_rad = 1.2;   // the bearing meets the line at most this far from its normal (else it
                                    // is not the plate's wall: e.g. a corridor's end wall seen along it)
};

struct PlateRangeOptions {
  double beam_window_rad = 0.03;    // the echoes along the bearing: their median within ± this of it
  // When that median is at least this much shorter than the wall line's range, something stood before the
  // plate and the wall line's range is taken. 0: off (the echoes along the bearing only).
  double occluded_margin_m = 0.15;
  WallRangeOptions wall;
};

// A plate's range and where it came from.
struct PlateRange {
  double range_m = 0.0;      // base_link -> plate
  bool from_wall = false;    // true: the wall line's (something stood before the plate)
};

// Throw std::invalid_argument naming the field ("WallRangeOptions.window_rad ...",
// "PlateRangeOptions.beam_window_rad ...") of a bad option.
void ValidateWallRangeOptions(const WallRangeOptions& options);
void ValidatePlateRangeOptions(const PlateRangeOptions& options);

// The median distance from base_link of the echoes whose end points, seen from base_link, lie within
// ± window_rad of `bearing_rad`. nullopt when there is none, or
// the geometry or the bearing is unusable (no ranges, zero increment, non-finite bearing).
std::optional<double> EchoRangeAlongBearing(const std::vector<float>& ranges_m, const BeamGeometry& geometry,
                                            double bearing_rad, double window_rad);

// The range from base_link along `bearing_rad` to the straight line most echoes within the window lie on:
// the strongest lines of a Hough transform of the echoes (cv::HoughLinesPointSet, lines whose normal is
// within max_incidence_rad of the bearing, rho bins of inlier_m), refined by a least-squares fit
// (cv::fitLine) to the echoes within inlier_m of it. Of the transform's candidates the one whose echoes cover
// the longest stretch of line is the wall (a person before the plate has more echoes per metre, a shorter
// front). Deterministic (no random draws). nullopt when no candidate has min_inliers echoes covering
// min_length_m, or
// the ray meets the line behind the robot.
std::optional<double> WallRangeAlongBearing(const std::vector<float>& ranges_m, const BeamGeometry& geometry,
                                            double bearing_rad, const WallRangeOptions& options);

// The rule: EchoRangeAlongBearing, replaced by WallRangeAlongBearing when options.occluded_margin_m > 0 and
// the wall line lies at least that much farther. nullopt when there is no echo along the bearing.
std::optional<PlateRange> PlateRangeAlongBearing(const std::vector<float>& ranges_m, const BeamGeometry& geometry,
                                                 double bearing_rad, const PlateRangeOptions& options);

}  // namespace doorplate_localization

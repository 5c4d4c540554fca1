// Reseeding from a doorplate reading (the paper's key idea, sec. 3.4: "matches the recognized room
// number with a prebuilt text map and computes the most likely pose"): robot poses drawn from the
// reading's likelihood. For a landmark with a compatible text (chosen with probability ∝ its match
// probability), the robot stands in front of the plate and sees it at the measured bearing:
//  - corridor prior (probability parallel_heading_probability): the robot drives along the plate's
//    wall (the paper's wall-following robot), heading parallel to it ± parallel_heading_stddev_rad;
//    heading + bearing gives the direction to the plate, and the robot stands back along it at the
//    measured range (± range_stddev_m) or, without a range, at a distance from the wall drawn in the
//    free band below;
//  - otherwise any heading: with a range, at r (± range_stddev_m) from the plate at an angle from its
//    normal drawn uniformly within ±max_view_angle_rad; without, at a distance along the normal drawn
//    in the free band, shifted along the wall by N(0, lateral_stddev_m); the heading then makes the
//    plate appear at the bearing (± heading_stddev_rad).
// The free band is [typical_view_distance_min_m, typical_view_distance_max_m] from the wall, cut to the
// free space measured by ray-casting the grid from the plate along its normal (minus wall_clearance_m).
// Candidates outside free space, without line of sight to the plate or seeing it more than
// max_view_angle_rad off its normal are redrawn. Without a grid (null) the free-space cut and checks are
// skipped.
#pragma once

#include <memory>
#include <random>
#include <vector>

#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/mcl/localization_grid.h"
#include "doorplate_localization/sensors/plate_reading.h"
#include "doorplate_localization/mcl/text_match.h"

namespace doorplate_localization {

struct PlatePoseSamplerOptions {
  double range_stddev_m = 0.2;
  double heading_stddev_rad = 0.05;
  double min_view_distance_m = 0.3;
  double max_view_angle_rad = 1.22;             // 70° off the plate's normal
  double typical_view_distance_min_m = 1.0;     // robot-to-wall distance while reading, without a range
  double typical_view_distance_max_m = 2.0;
  double lateral_stddev_m = 0.5;                // along the wall, without a range (readings come abeam)
  double parallel_heading_probability = 0.7;    // share of poses from the corridor prior
  double parallel_heading_stddev_rad = 0.1;
  double wall_clearance_m = 0.2;                // keep this far from the wall facing the plate
  double line_of_sight_tolerance_m = 0.15;
  int max_attempts_per_pose = 30;
  TextMatchOptions text_match;
};

class PlatePoseSampler {
 public:
  // Throws std::invalid_argument naming the field of a bad option or a null map.
  PlatePoseSampler(std::shared_ptr<const TextMap> text_map, std::shared_ptr<const LocalizationGrid> grid,
                   const PlatePoseSamplerOptions& options);

  // Up to `count` poses (base_link in the map frame) consistent with the reading; fewer if candidates
  // keep failing the free-space / line-of-sight checks, none if no landmark text is compatible.
  // Throws std::invalid_argument for an invalid reading.
  std::vector<Pose2D> Sample(const PlateReading& reading, int count, std::mt19937_64& rng) const;

 private:
  bool SampleAt(const TextLandmark& plate, const PlateReading& reading, std::mt19937_64& rng, Pose2D* pose) const;
  // The band of distances from the plate's wall the robot may stand at, without a range; false if none.
  bool DepthBand(const TextLandmark& plate, double* lo, double* hi) const;
  // Free distance from the plate along its facing normal (ray cast), metres.
  double FreeDepth(const TextLandmark& plate) const;

  const std::shared_ptr<const TextMap> text_map_;
  const std::shared_ptr<const LocalizationGrid> grid_;
  const PlatePoseSamplerOptions options_;
  const TextMatcher matcher_;
};

}  // namespace doorplate_localization

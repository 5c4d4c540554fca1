// Corridor following (paper Section 3.2): keep a fixed distance from one wall with the laser while the
// sideways camera faces the other wall; stop before the wall at the corridor's end.
// Input frame: laser ranges in base_link (beam i at angle_min_rad + i * angle_increment_rad, x forward,
// y left); non-finite ranges (REP-117 ±inf, NaN) are ignored. Output: a velocity command for base_link.
#pragma once

#include <string>
#include <vector>

#include "doorplate_localization/behaviour/isolated_returns.h"

namespace doorplate_localization {

struct WallFollowerOptions {
  std::string wall_side = "right";      // the wall to follow: "right" (camera looks left) or "left"
  double wall_distance_m = 0.6;         // d_wall in the paper
  double cruise_speed_mps = 0.4;
  double end_stop_distance_m = 0.7;     // stop when the wall ahead is this close
  double slow_down_distance_m = 1.5;    // start slowing down from here
  double distance_gain_rad_per_m = 1.5; // heading correction per metre of distance error
  double max_heading_correction_rad = 0.35;
  double heading_gain_per_s = 1.8;      // angular speed per radian of heading error
  double max_angular_speed_rps = 0.8;
  double side_sector_min_deg = 50.0;    // beams between these angles from straight ahead, on the followed
  double side_sector_max_deg = 130.0;   //   side, are fitted with a line as the wall
  double side_max_range_m = 3.0;        // farther points are not the wall (open doors, side corridors)
  double front_half_width_m = 0.3;      // returns ahead within this lateral band count as "the wall ahead"
  double width_sector_half_angle_deg = 30.0;  // corridor width from minima within ±this of straight left/right
  IsolatedReturnOptions isolated_returns;  // returns without neighbours are no obstacle (isolated_returns.h)
};

// What the robot sees of its corridor, from one scan.
struct CorridorObservation {
  bool wall_found = false;
  double wall_distance_m = 0.0;   // perpendicular distance to the followed wall's fitted line
  double wall_angle_rad = 0.0;    // wall direction relative to the robot's heading (0 = parallel)
  double front_distance_m = 0.0;  // distance ahead to the nearest return within ±front_half_width_m (+inf if none)
  double width_m = 0.0;           // left minimum + right minimum ranges around ±90° (paper Sec. 4.2), 0 if unknown
};

struct VelocityCommand {
  double linear_mps = 0.0;
  double angular_rps = 0.0;
};

enum class WallFollowState { kFollowing, kNoWall, kEndReached };

class WallFollower {
 public:
  // Throws std::invalid_argument naming the field of an invalid option.
  explicit WallFollower(const WallFollowerOptions& options);

  CorridorObservation Observe(const std::vector<float>& ranges_m, double angle_min_rad,
                              double angle_increment_rad) const;
  // The command for this observation, and the resulting state (kEndReached: the command is a stop).
  VelocityCommand Command(const CorridorObservation& observation, WallFollowState* state) const;

  const WallFollowerOptions& options() const { return options_; }

 private:
  const WallFollowerOptions options_;
  const double side_sign_;  // -1 for a right wall (negative angles), +1 for a left wall
};

}  // namespace doorplate_localization

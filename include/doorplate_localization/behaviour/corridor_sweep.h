// Corridor sweep (paper Sections 3.2-3.4): follow one wall out to the corridor's end, turn around in
// place, follow the other wall back. The sideways camera therefore faces the far wall on the way out and
// the other wall on the way back, so every doorplate of a straight corridor is passed once per sweep.
// Both legs keep the same robot side to a wall (WallFollowerOptions::wall_side); after the 180° turn that
// side faces the other physical wall.
// Input each step: one laser scan in base_link (as WallFollower::Observe) and the odometry pose (base_link
// in odom; only its yaw is used, to measure the turn). Output: a velocity command for base_link.
#pragma once

#include <vector>

#include "doorplate_localization/behaviour/wall_follower.h"
#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct CorridorSweepOptions {
  WallFollowerOptions follower;        // used on both legs
  double turn_speed_rps = 0.6;         // in-place rotation speed, away from the followed wall
  // The turn ends once the odometry yaw has changed by at least pi - turn_tolerance_rad AND the wall
  // fit of the followed side is parallel within parallel_tolerance_rad; or, whatever the laser says,
  // once it has changed by pi + turn_tolerance_rad (the follower then corrects the rest).
  double turn_tolerance_rad = 0.35;
  double parallel_tolerance_rad = 0.08;
  // Approach: after the turn the followed wall is the far one (corridor width − wall distance away).
  // During the turn and at the start of each leg, until the fitted wall is within approach_tolerance_m
  // of follower.wall_distance_m, the wall fit uses the followed side's beams from
  // follower.side_sector_min_deg to approach_sector_max_deg from straight ahead (near the corridor's
  // end, beams further back hit the end wall and bend the line) up to approach_max_range_m.
  double approach_sector_max_deg = 90.0;
  double approach_max_range_m = 3.0;
  double approach_tolerance_m = 0.15;
  // Wall gate: once a leg has reached the wall distance, returns on the followed side farther than
  // wall_gate_m from the previous step's fitted wall line are ignored by the fit (not by the
  // end-of-corridor check), and the wall counts as not found when the follower's side sector keeps less
  // than min_wall_span_m of it (measured along the line). So alcoves, open doors and side corridors on
  // the followed side leave the robot going straight instead of pulling it in.
  double wall_gate_m = 0.15;
  double min_wall_span_m = 0.6;
};

enum class SweepPhase { kFollowOut, kTurnAround, kFollowBack, kDone };

// "follow_out", "turn_around", "follow_back", "done".
const char* SweepPhaseName(SweepPhase phase);

class CorridorSweep {
 public:
  // Throws std::invalid_argument naming the field of an invalid option (follower fields included).
  explicit CorridorSweep(const CorridorSweepOptions& options);

  // One control step. `odom_pose` is base_link in the odom frame at the scan's time. Returns the command
  // to apply until the next step; a zero command once phase() is kDone.
  VelocityCommand Step(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad,
                       const Pose2D& odom_pose);

  SweepPhase phase() const { return phase_; }
  // What the last Step saw of the corridor (for logging and experiments).
  const CorridorObservation& last_observation() const { return last_observation_; }
  const CorridorSweepOptions& options() const { return options_; }

  // Starts a new sweep in kFollowOut.
  void Reset();

 private:
  VelocityCommand Turn(const CorridorObservation& observation, const Pose2D& odom_pose);
  // The follower's observation with the wall fitted only to returns within wall_gate_m of wall_.
  CorridorObservation ObserveGated(const std::vector<float>& ranges_m, double angle_min_rad,
                                   double angle_increment_rad) const;

  const CorridorSweepOptions options_;
  const WallFollower follower_;
  const WallFollower approach_observer_;  // the follower with the approach sector and range
  SweepPhase phase_ = SweepPhase::kFollowOut;
  CorridorObservation last_observation_;
  bool approaching_ = true;       // the current leg has not yet reached the wall distance
  bool has_wall_ = false;         // wall_ holds the last fitted line of this leg
  CorridorObservation wall_;
  double turned_rad_ = 0.0;       // yaw accumulated during the current turn (unsigned)
  double last_yaw_rad_ = 0.0;     // odometry yaw at the previous turn step
};

}  // namespace doorplate_localization

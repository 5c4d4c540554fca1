// Corridor sweep (paper Sections 3.2-3.4): follow one wall out to the corridor's end, turn around in
// place, follow the other wall back. The sideways camera therefore faces the far wall on the way out and
// the other wall on the way back, so every doorplate of a straight corridor is passed once per sweep.
// Both legs keep the same robot side to a wall (WallFollowerOptions::wall_side); after the 180° turn that
// side faces the other physical wall.
// A leg ends where the wall follower stops before something ahead (WallFollowerOptions::end_stop_distance_m)
// and it is still there after end_confirm_s of standing still: a person walking through the lane or a few
// spurious laser returns (docs/results/laser-model.md) clear within a second or two, the corridor's end wall
// does not. Something narrower than end_min_width_m (a person who stopped in the lane, but also a bench or
// bed parked at the end) must stay narrow_end_confirm_s (30 s) before it counts as the end.
// Input each step: one laser scan in base_link (as WallFollower::Observe), the odometry pose (base_link in
// odom; only its yaw is used, to measure the turn) and the scan's time in seconds (any monotonic clock).
// Output: a velocity command for base_link.
#pragma once

#include <optional>
#include <vector>

#include "doorplate_localization/behaviour/hold_timer.h"
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
  // Something ahead within follower.end_stop_distance_m ends the leg only once the robot has stood still
  // before it this long (0: at once). Until then the command is a stop.
  double end_confirm_s = 4.0;
  // A corridor's end spans it; a person standing in the lane, a bench's end or a trolley is narrower. When
  // the thing ahead (the returns joined to the nearest one ahead, each within 0.15 m of the next, ahead of
  // the robot) is narrower than end_min_width_m across the robot's heading, the leg ends only after
  // narrow_end_confirm_s of standing before it (people who stop to talk walk on; a narrow dead end is
  // still an end). end_min_width_m 0: every end waits end_confirm_s only.
  double end_min_width_m = 0.8;
  double narrow_end_confirm_s = 30.0;
  // Something ahead ends a leg only while the robot runs along the leg: within end_max_wall_angle_rad of the
  // followed wall's fit (or, on the way back with no fit, of the way out's direction reversed, by odometry).
  // Stopped before something while turned further across the corridor (a turn at the far end that
  // overshot under control lag), it turns in place at turn_speed_rps until it runs within that angle again.
  // On the way out with no wall fit: wait, then end, as before.
  double end_max_wall_angle_rad = 0.35;
  // Wall direction check: a corridor's wall is straight, so during a leg its direction in the odom frame
  // (odometry yaw + fitted wall angle) stays put; it is taken once direction_settle_fits fits in a row that
  // the robot runs parallel to (within parallel_tolerance_rad) agree on it within direction_settle_spread_rad
  // (their mean): one fit across the end of a radiator or a door frame beside the robot is tilted by that
  // step, and the tilt changes as the robot passes it, while a wall's direction stays put. A fit more than
  // max_wall_turn_rad from the leg's wall direction is not the wall (glass with a room behind it, a bench, a
  // person beside the robot): the wall counts as not found, and while no wall is found the robot holds the
  // leg's wall direction. The leg's direction follows accepted fits by wall_direction_gain per step
  // (odometry's slow yaw drift). max_wall_turn_rad 0: off.
  double max_wall_turn_rad = 0.15;
  int direction_settle_fits = 5;
  double direction_settle_spread_rad = 0.04;
  double wall_direction_gain = 0.05;
  // When the gated fit has found no wall for this long, the gate's line is dropped and the next fit is made
  // from all returns again (the direction check still applies, and the line must lie no farther than
  // follower.wall_distance_m + wall_gate_m: a far parallel line is an alcove's back or a room seen through
  // glass): a gate that has locked onto something that was not the wall must not hide the wall for the
  // rest of the leg.
  double wall_gate_reset_s = 1.0;
  // When no fit has been taken for this long, the leg's wall direction is forgotten and the next fits are
  // taken unchecked until the robot runs parallel to one (a direction taken wrongly, e.g. while the robot
  // still turned after a kidnap, must not steer it across the corridor for the rest of the leg).
  double wall_reacquire_s = 8.0;
};

// The width (metres, across the robot's heading) of the thing nearest ahead in a scan in base_link (x ahead,
// y left): the returns joined to the nearest return within ±45° of straight ahead, each within 0.15 m of the
// next, while they lie ahead of the robot (x > 0). An end wall joins the side walls: the corridor's width.
// 0 when nothing is ahead.
double BlockingWidth(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad);

enum class SweepPhase { kFollowOut, kTurnAround, kFollowBack, kDone };

// "follow_out", "turn_around", "follow_back", "done".
const char* SweepPhaseName(SweepPhase phase);

class CorridorSweep {
 public:
  // Throws std::invalid_argument naming the field of an invalid option (follower fields included).
  explicit CorridorSweep(const CorridorSweepOptions& options);

  // One control step. `odom_pose` is base_link in the odom frame at the scan's time `time_s` (seconds,
  // non-decreasing over the steps). Returns the command to apply until the next step; a zero command while
  // it waits for something ahead to clear and once phase() is kDone.
  VelocityCommand Step(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad,
                       const Pose2D& odom_pose, double time_s);

  SweepPhase phase() const { return phase_; }
  // What the last Step saw of the corridor (for logging and experiments).
  const CorridorObservation& last_observation() const { return last_observation_; }
  const CorridorSweepOptions& options() const { return options_; }

  // Starts a new sweep in kFollowOut.
  void Reset();

 private:
  VelocityCommand Turn(const CorridorObservation& observation, const Pose2D& odom_pose);
  // Clears observation->wall_found when the fitted wall has turned more than max_wall_turn_rad from the
  // leg's wall direction (odom frame); otherwise updates that direction.
  void CheckWallDirection(const Pose2D& odom_pose, CorridorObservation* observation);
  // Forgets the leg's wall direction and the fits gathered towards it.
  void ForgetWallDirection();
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
  HoldTimer blocked_;                              // stopped before something ahead
  std::optional<double> wall_direction_odom_rad_;  // the leg's wall direction in the odom frame
  std::vector<double> settling_directions_odom_rad_;  // the last parallel fits in a row, until it is taken
  std::optional<double> back_direction_odom_rad_;  // the way out reversed (odom frame), set at the turn
  bool gate_dropped_ = false;     // wall_gate_reset_s passed without a wall; cleared by the next fit taken
  double last_wall_s_ = 0.0;      // time of the last step with the wall found (this leg)
};

}  // namespace doorplate_localization

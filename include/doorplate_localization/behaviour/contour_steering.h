// Wall-contour steering: the right-hand (or left-hand) rule of maze exploration, made continuous, so a
// robot follows one wall of a whole floor at a fixed distance: round corners (away from the wall where it
// meets a wall ahead, towards it where the wall turns away into a side corridor), into side corridors and
// lobbies, and back out of dead ends; past doors, open or closed (a door is too narrow to count as a way).
//
// Rule (frame: base_link, x forward, y left; the laser is taken to sit at base_link, as WallFollower does):
// candidate target points q(θ) = look_ahead_m · (cos θ, sin θ) are tried from the followed side's
// perpendicular (θ = −90° for the right wall) towards the other side, and the first one that is free is
// steered to. A point is free when no laser return lies within wall_distance_m of the outer half of the
// straight path to it (from q/2 to q) and none within robot_clearance_m of its inner half. Beside a
// straight wall at distance d the first free point is at sin θ = 2·(wall_distance_m − d) / look_ahead_m:
// ahead when d is right, towards the wall when too far, away when too close, so the distance is held
// without a separate controller. A gap in the wall narrower than 2·wall_distance_m (a door) lets no such
// path through; a side corridor does. With no return within look_ahead_m + wall_distance_m on the followed
// side (open space, or a pass starting mid-corridor) the search starts straight ahead instead, so the
// robot drives on until it meets a wall rather than circling. Behind the robot (x < 0) a return counts as
// the followed wall only within wall_distance_m + robot_clearance_m (the end of a wall it is rounding): a
// robot with its back to a wall and none beside it (at a lift door) drives away instead of circling.
//
// The radius shrinks towards a wall ahead (down to min_look_ahead_m), so the robot drives on to within
// wall_distance_m + min_look_ahead_m of a dead end's wall before it turns and its camera passes the
// plates near corridor ends.
//
// Output: the target bearing and a velocity command (pure pursuit, curvature 2·sin θ / look_ahead_m);
// a target more than rotate_in_place_deg away from the wall side (a wall ahead) is turned to on the spot.
#pragma once

#include <string>
#include <vector>

#include "doorplate_localization/behaviour/isolated_returns.h"
#include "doorplate_localization/behaviour/wall_follower.h"

namespace doorplate_localization {

struct ContourSteeringOptions {
  std::string wall_side = "right";     // the followed wall: "right" (a camera looking left sees the other) or "left"
  double wall_distance_m = 0.6;        // clearance kept from the followed wall and from every other return
  double look_ahead_m = 1.0;           // radius of the candidate target points
  double min_look_ahead_m = 0.3;       // ... shrunk to (distance ahead − wall_distance_m), not below this
  double robot_clearance_m = 0.32;     // the straight path to a target keeps this far from every return
  double angle_step_deg = 2.0;         // spacing of the candidate bearings
  double max_range_m = 4.0;            // returns farther away are ignored (they cannot block a target)
  double cruise_speed_mps = 0.4;
  double max_angular_speed_rps = 0.8;
  double rotate_in_place_deg = 60.0;   // targets beyond this, away from the wall: turn on the spot
  double min_speed_fraction = 0.25;    // speed factor at the sharpest driven turn (|θ| = rotate_in_place_deg)
  IsolatedReturnOptions isolated_returns;  // returns without neighbours are no obstacle (isolated_returns.h)
};

// One step's decision, for logging and tests.
struct ContourSteeringResult {
  bool target_found = false;           // false: no free bearing at all (boxed in): turning on the spot
  double target_bearing_rad = 0.0;     // θ of the chosen target, base_link
  double look_ahead_m = 0.0;           // the radius used this step
  bool wall_found = false;             // a return on the followed side lies within look_ahead_m + wall_distance_m
                                       // (behind the robot: within wall_distance_m + robot_clearance_m)
  VelocityCommand command;
};

class ContourSteering {
 public:
  // Throws std::invalid_argument naming the field of an invalid option.
  explicit ContourSteering(const ContourSteeringOptions& options);

  // One scan (ranges in metres, beam i at angle_min_rad + i·angle_increment_rad; non-finite and
  // non-positive ranges are ignored) → the target and the command to apply until the next scan.
  ContourSteeringResult Step(const std::vector<float>& ranges_m, double angle_min_rad,
                             double angle_increment_rad) const;

  const ContourSteeringOptions& options() const { return options_; }

 private:
  const ContourSteeringOptions options_;
  const double side_sign_;  // −1 for the right wall, +1 for the left: bearings are mirrored for the left
};

}  // namespace doorplate_localization

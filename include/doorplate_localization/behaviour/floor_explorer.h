// Floor exploration for mapping (issue 17): drive a whole floor (corridors round a courtyard, side
// corridors, lobbies, dead ends) so that the sideways camera passes every doorplate, return, and stop
// when nothing new is left. Built from ContourSteering (the wall-following rule of mazes):
//
//  - Pass 1 follows one wall (the right one by default, the camera looks left) wherever it leads. On a floor
//    whose corridors form a tree this visits every corridor in both directions, so the camera sees both
//    walls; on a ring it goes round the outer boundary (into every side corridor and out again) and the
//    camera sees the ring's inner walls.
//  - Pass 2 turns round on the spot (in the corridor pass 1 started in) and follows the same side again, which is now the other wall: on a
//    ring that is the inner (courtyard) wall, so the camera sees the ring's outer walls.
//  - A pass ends when it is back where it started. The robot knows that from the plates (the first
//    evidence a hospital robot has): once it reads `revisit_plates` distinct plates in a row that it read
//    at least `min_revisit_travel_m` of driving earlier (in this pass or the one before), it is
//    re-tracing known ground. Reads during a turn, and in a pass's first `min_revisit_travel_m`, do not
//    count (the camera sweeps over plates just read; pass 2 starts beside the walls pass 1 saw). Without plates (a laser-only run), a pass ends when `pose` comes back
//    within `revisit_radius_m` of the pass's start pose heading the same way (± 45°) after at least
//    `min_revisit_travel_m`; and a pass never drives more than `max_pass_distance_m`.
//
// Every plate read on both passes is read twice in all (ring) or more (tree), so the SLAM back end gets a
// loop closure from each re-read plate. The explorer plans nothing: it needs no map, only the scan, a
// pose for the travelled distance and turns, and the plate reads.
//
// Inputs each step: one laser scan in base_link and `pose` = base_link in a fixed frame (odom, or map
// when a SLAM estimate is at hand; only differences and the revisit check use it). Output: a velocity
// command for base_link; zero once phase() is kDone.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "doorplate_localization/behaviour/contour_steering.h"
#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct FloorExplorerOptions {
  ContourSteeringOptions steering;     // used on every pass
  int passes = 2;                      // 1: one wall only (a tree-shaped floor needs no more)
  int revisit_plates = 2;              // distinct known plates read in a row that end a pass
  double min_revisit_travel_m = 20.0;  // a plate counts as known once driven this far since its first read
  double revisit_radius_m = 1.0;       // pose-based end of a pass (runs without plates)
  double max_pass_distance_m = 1500.0;
  double turn_speed_rps = 0.6;         // the turn round between passes (on the spot, away from the wall)
  // The turn waits until the robot has driven this far beside a wall with its target within
  // straight_bearing_rad of ahead, heading within turn_heading_tolerance_rad of the direction it drove
  // at the start of the pass (measured after its first such straight stretch): so it turns in the
  // corridor it started in, not at a junction or in a side corridor, where turning round and following
  // the same side would re-trace the pass just ended. Odometry's heading drift over a pass must stay
  // below the tolerance (0.8 rad: a side corridor is 1.57 rad off). Without such a heading, or with no
  // such place within 2 × min_revisit_travel_m of the pass's end, any straight stretch will do.
  double straight_before_turn_m = 1.0;
  double straight_bearing_rad = 0.2;
  double turn_heading_tolerance_rad = 0.8;
  double turn_tolerance_rad = 0.1;     // the turn ends after π − this
};

enum class ExplorePhase { kFollow, kTurnAround, kDone };
// "follow", "turn_around", "done".
const char* ExplorePhaseName(ExplorePhase phase);

// Why the last pass ended.
enum class PassEnd { kNotEnded, kPlatesRevisited, kPoseRevisited, kMaxDistance };
const char* PassEndName(PassEnd end);

class FloorExplorer {
 public:
  // Throws std::invalid_argument naming the field of an invalid option (steering fields included).
  explicit FloorExplorer(const FloorExplorerOptions& options);

  // A plate was read now (any text; compared by CanonicalRoomId, empty ids are ignored).
  void OnPlateRead(const std::string& text);

  // One control step: the command to apply until the next step.
  VelocityCommand Step(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad,
                       const Pose2D& pose);

  ExplorePhase phase() const { return phase_; }
  int pass() const { return pass_; }                        // 1-based, the current (or last) pass
  double distance_m() const { return total_distance_m_; }   // driven since the start, all passes
  double pass_distance_m() const { return total_distance_m_ - pass_start_distance_m_; }
  PassEnd last_pass_end() const { return last_pass_end_; }
  int passes_ended() const { return passes_ended_; }
  int plates_known() const { return static_cast<int>(first_read_at_m_.size()); }
  const ContourSteeringResult& last_steering() const { return last_steering_; }
  const FloorExplorerOptions& options() const { return options_; }

 private:
  void EndPass(PassEnd why);

  const FloorExplorerOptions options_;
  const ContourSteering steering_;
  ExplorePhase phase_ = ExplorePhase::kFollow;
  int pass_ = 1;
  PassEnd last_pass_end_ = PassEnd::kNotEnded;
  int passes_ended_ = 0;
  bool has_pose_ = false;
  Pose2D last_pose_;
  Pose2D pass_start_pose_;
  double total_distance_m_ = 0.0;
  double pass_start_distance_m_ = 0.0;
  double turned_rad_ = 0.0;
  bool turn_pending_ = false;    // a pass ended; waiting for a straight stretch to turn round
  double turn_pending_since_m_ = 0.0;
  double straight_m_ = 0.0;      // driven straight beside a wall, metres
  bool pass_heading_set_ = false;
  double pass_heading_rad_ = 0.0;  // heading on the pass's first straight stretch
  std::map<std::string, double> first_read_at_m_;  // canonical id → total distance at its first read
  std::vector<std::string> known_run_;              // distinct known ids read in a row (this pass)
  bool left_start_ = false;                         // the pose went beyond revisit_radius_m of the pass start
  ContourSteeringResult last_steering_;
};

}  // namespace doorplate_localization

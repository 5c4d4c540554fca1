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
//    re-tracing known ground. Reads during a turn or before `straight_before_turn_m` of straight driving
//    beside a wall (the camera sweeps over plates just read, e.g. at the mouth of a dead-end branch on the
//    way out), and in a pass's first `min_revisit_travel_m`, do not count (pass 2 starts beside the walls
//    pass 1 saw). Without plates (a laser-only run), a pass ends when `pose` comes back
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

#include <deque>
#include <limits>
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
  // straight_bearing_rad of ahead, heading within turn_heading_tolerance_rad of the direction of its last
  // such straight stretch before the pass ended: a pass ends re-tracing the corridor it started in, so the
  // robot turns there, not in a side corridor it entered while the plate reading that ended the pass was
  // still being processed (turning round there and following the same side would re-trace the pass just
  // ended). Only the odometry's heading drift since the pass ended matters (a side corridor is 1.57 rad
  // off). With no straight stretch before the pass ended, or with no such place within
  // 2 × min_revisit_travel_m of the pass's end, any straight stretch will do.
  double straight_before_turn_m = 1.0;
  double straight_bearing_rad = 0.2;
  double turn_heading_tolerance_rad = 0.8;
  double turn_tolerance_rad = 0.1;     // the turn ends after π − this
  // A plate reading is judged by the explorer's state at the reading's stamp (where the robot was, whether it
  // was driving straight), kept for this long: the text extractor reports a plate some time after the camera
  // saw it (seconds on a loaded machine).
  double read_latency_window_s = 30.0;
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

  // A plate was read (any text; compared by CanonicalRoomId, empty ids are ignored) on the camera image of
  // time `stamp_s` (the clock of Step's stamps); NaN or a stamp at or after the last step: now.
  void OnPlateRead(const std::string& text, double stamp_s = std::numeric_limits<double>::quiet_NaN());

  // One control step at time `stamp_s` (seconds, any clock that does not go back; NaN: no reading is ever
  // dated before now): the command to apply until the next step.
  VelocityCommand Step(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad,
                       const Pose2D& pose, double stamp_s = std::numeric_limits<double>::quiet_NaN());

  ExplorePhase phase() const { return phase_; }
  int pass() const { return pass_; }                        // 1-based, the current (or last) pass
  double distance_m() const { return total_distance_m_; }   // driven since the start, all passes
  double pass_distance_m() const { return total_distance_m_ - pass_start_distance_m_; }
  PassEnd last_pass_end() const { return last_pass_end_; }
  int passes_ended() const { return passes_ended_; }
  int plates_known() const { return static_cast<int>(first_reads_.size()); }
  const ContourSteeringResult& last_steering() const { return last_steering_; }
  const FloorExplorerOptions& options() const { return options_; }

 private:
  // The explorer's state at one step, for plate readings reported late.
  struct StepRecord {
    double stamp_s = 0.0;
    double distance_m = 0.0;       // total_distance_m_
    double pass_distance_m = 0.0;
    double heading_rad = 0.0;      // pose heading (odometry)
    bool on_straight = false;      // driven straight_before_turn_m straight beside a wall
    bool following = false;        // following a wall, no turn pending
    int pass = 1;
  };
  struct FirstRead {
    double distance_m = 0.0;
    double heading_rad = 0.0;
    int pass = 1;
  };

  VelocityCommand Advance(const std::vector<float>& ranges_m, double angle_min_rad, double angle_increment_rad,
                          const Pose2D& pose);
  StepRecord RecordAt(double stamp_s) const;  // the state at the last step at or before stamp_s, else now
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
  double pass_heading_rad_ = 0.0;   // heading on the pass's first straight stretch
  bool turn_heading_set_ = false;
  double turn_heading_rad_ = 0.0;   // pass_heading_rad_ + the drift the re-read plates show: the turn's corridor
  std::map<std::string, FirstRead> first_reads_;  // canonical id → its first reading
  std::vector<std::string> known_run_;             // distinct known ids read in a row (this pass)
  std::vector<double> drift_samples_;              // heading drift shown by the run's plates, radians
  std::deque<StepRecord> history_;                 // the last read_latency_window_s of steps
  bool left_start_ = false;                         // the pose went beyond revisit_radius_m of the pass start
  ContourSteeringResult last_steering_;
};

}  // namespace doorplate_localization

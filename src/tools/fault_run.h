// Fault injection for the soak run (issue 8): a schedule of faults played one after another while the
// soak (soak_run.h) drives the robot with Text AMCL tracking it, and the measurement of how
// localization recovers from each:
//  - kCameraOff: no camera images for duration_s (so no plate readings);
//  - kLaserOff: no scans reach the localizer for duration_s (odometry continues; the corridor sweep
//    still drives on its own scans, or the robot would stop);
//  - kLocalizerRestart: the filter is replaced by a new one from scratch, as a restarted nodelet
//    would be: global localization, no initial pose, new odometry reference;
//  - kKidnap: the robot is teleported to a random free pose on its route (near where the sweep has
//    driven: not into a room behind an open door, where the sweep could not drive it out); the filter
//    is not told.
// A fault starts at first_fault_s (the first) or settle_s after the previous one recovered or gave up.
// It has recovered at the first localizer scan after the fault's end (the outage's end; the fault's
// start for a restart or kidnap) at which the estimate is within recovered_position_m and
// recovered_heading_rad of the truth and the filter's State() is kConverged.
// ROS-free. Frames: poses are base_link in the map frame. Units: metres, radians, simulated seconds.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization::tools {

enum class FaultKind { kCameraOff, kLaserOff, kLocalizerRestart, kKidnap };
const char* ToString(FaultKind kind);

struct Fault {
  FaultKind kind = FaultKind::kKidnap;
  double duration_s = 0.0;  // outages; 0 for a restart or kidnap
};

struct FaultOptions {
  std::vector<Fault> schedule;     // empty: no faults (a plain soak)
  double first_fault_s = 30.0;     // simulated time of the first fault (the filter tracks until then)
  double settle_s = 10.0;          // after a recovery, before the next fault
  double max_recovery_s = 180.0;   // after the fault's end; then it counts as not recovered
  double recovered_position_m = 0.3;
  double recovered_heading_rad = 10.0 * M_PI / 180.0;
  double kidnap_min_jump_m = 3.0;  // a kidnap moves the robot at least this far
  double kidnap_clearance_m = 0.4; // free space around the new pose and 1.5 m ahead of it
  double kidnap_max_off_route_m = 0.5;  // the new pose is at most this far from a pose already driven
};

// The issue's schedule: camera off 30 s, laser off 5 s, localizer restarted, kidnapped twice.
std::vector<Fault> IssueFaultSchedule();

struct FaultReport {
  FaultKind kind = FaultKind::kKidnap;
  double start_s = 0.0;             // simulated time the fault started
  double end_s = 0.0;               // ... and ended (the outage's end; start_s for a restart or kidnap)
  bool recovered = false;
  double recovery_s = 0.0;          // simulated time from end_s to the recovery (or to giving up)
  double recovery_distance_m = 0.0; // distance the robot drove from end_s to the recovery
  double max_error_m = 0.0;         // largest position error from start_s to the recovery
  double max_heading_error_rad = 0.0;
  double kidnap_jump_m = 0.0;       // kidnap: how far the robot was moved, from where to where
  Pose2D kidnap_from, kidnap_to;
};

// Plays the schedule: the soak asks it once per scan what to do, then tells it how the localizer did.
// Throws std::invalid_argument naming the field of a bad option.
class FaultSchedule {
 public:
  explicit FaultSchedule(const FaultOptions& options);

  // At a scan at simulated time now_s with the robot's travelled distance: the restart or kidnap the
  // soak must perform now, if one starts now. Outages start here too (see camera_off / laser_off).
  std::optional<FaultKind> Begin(double now_s, double distance_m);
  // After that scan: the localizer's error against the truth and whether it is converged. `localized`
  // false: the filter did not run on this scan (laser off), it cannot recover on it.
  void Observe(double now_s, double distance_m, double position_error_m, double heading_error_rad,
               bool converged, bool localized);
  // Records where the kidnap in progress took the robot.
  void SetKidnap(const Pose2D& from, const Pose2D& to);

  bool camera_off(double now_s) const { return Active(FaultKind::kCameraOff, now_s); }
  bool laser_off(double now_s) const { return Active(FaultKind::kLaserOff, now_s); }
  bool enabled() const { return !options_.schedule.empty(); }
  bool done() const { return next_ >= options_.schedule.size() && !current_; }
  const std::vector<FaultReport>& reports() const { return reports_; }
  const FaultOptions& options() const { return options_; }

 private:
  bool Active(FaultKind kind, double now_s) const;

  const FaultOptions options_;
  size_t next_ = 0;                    // index of the next fault to start
  std::optional<FaultReport> current_; // the fault in progress (until it recovers or gives up)
  double end_distance_m_ = 0.0;        // travelled distance at the current fault's end
  bool end_seen_ = false;
  double next_start_s_ = 0.0;
  std::vector<FaultReport> reports_;
};

}  // namespace doorplate_localization::tools

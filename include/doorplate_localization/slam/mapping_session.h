// MappingSession: the one run loop of text SLAM. The mapping nodelet (src/ros/slam_mapping_nodelet.cpp),
// the experiment (`doorplate_eval map`) and the offline tools (doorplate_map_log, _rawlog, _bag) feed it
// scans and plate sightings with the odometry at their stamps, and publish or score what it returns; none
// of them calls TextSlam itself. ROS-free.
//
// Frames: `map` (the odometry frame at the first processed scan; the grid, the trajectory and the plates
// are in it), `odom` (odometry: base_link in odom), `base_link` (plate bearings and the laser's mounting
// are in it). Units: metres, radians, seconds. Stamps are any monotonic clock in seconds (ROS time,
// simulated time, a log's), the same one for every input.
//
// The rules, each in one place:
//  - Scans (AddScan) carry the odometry at their stamp. A scan whose stamp is not after the previous
//    scan's is refused (the session continues from the previous one). Of the scans taken, every
//    throttle_scans-th (counting every AddScan call, as gmapping's throttle_scans) goes to the filter,
//    which processes it once the robot moved slam.slam.linear_update_m or turned angular_update_rad since
//    the last processed scan (gmapping's linearUpdate / angularUpdate; the filter sees every such scan, so
//    its motion noise grows with each odometry increment), or, with temporal_update_s > 0, once that long
//    passed since the last processed scan (gmapping's temporalUpdate).
//  - Stamp order (camera_wait_s > 0, the nodelet's and the offline tools' setting): the filter's weights
//    and random draws follow the order in which scans and sightings reach it, so the session puts them in
//    stamp order, whatever order they arrived in (live: an OCR report arrives after newer scans; a bag
//    replayed: the callbacks interleave by timing). A taken scan waits until the camera has reported up to
//    its stamp (every AddPlates call, also one with no sightings, says the camera got that far: the
//    extractor publishes an array, empty or not, for every image, in image order), or until the newest
//    scan given is camera_wait_s newer than it (the camera is off or stalled: the scan goes on without
//    waiting, counted in scans_camera_wait_expired). A sighting is applied just before the first scan
//    stamped after it goes to the filter; one stamped before a scan that already went (it came later than
//    camera_wait_s) is applied at once (counted in plates_late). Flush() sends everything still waiting
//    (the end of a log). With the same seed and the same messages the result is then the same however the
//    calls interleave, as long as no report is later than camera_wait_s. Scans may come out of order too (a
//    tf filter hands on the one whose odometry came first): a late scan waits in its stamp's place; one
//    stamped at or before a scan already given to the filter is refused. camera_wait_s = 0 (doorplate_eval,
//    which calls in stamp order): scans go to the filter when given, sightings as below.
//  - Plate sightings (AddPlates) carry the odometry at their own stamp (tf at the detection's stamp, the
//    simulator's odometry) and are applied when they arrive, tied to the last processed scan by the
//    odometry between the two (either way in time: a sighting the OCR delivers after newer scans is placed
//    where the robot was at its stamp); the filter's weights and random draws follow the order of arrival,
//    the order the nodelet sees live. One exception: a sighting without range_m that has no scan within
//    plate_range_max_scan_age_s of its stamp while every scan received is older than it (the scans near
//    its stamp have not arrived yet: live, a laser callback queued behind a back-end solve, or a bag whose
//    detections were recorded before those scans) is held and applied by the first AddScan that takes a
//    scan stamped at or after it (in that call's MappingUpdate::plates). At most kMaxHeldPlates wait;
//    beyond that the oldest is applied at once.
//  - Plate range (a sighting without range_m): PlateRangeAlongBearing (sensors/plate_range.h,
//    slam.plate_range: the echoes along the bearing, or the wall line behind someone standing before the
//    plate, counted in plate_ranges_from_wall) in the received scan nearest in time to the sighting (ties:
//    the newer), if within plate_range_max_scan_age_s of it; else the sighting has no range
//    (PlateOutcome::kNoRange).
//  - The back end is solved by Solve() only: explicitly, or after a processed scan when
//    map_update_interval_s > 0 and that long passed (scan stamps) since the last solve. Solve() also
//    rebuilds Map() and GetTextMap() and recomputes MapToOdom(). A solve's cost grows with the trajectory
//    (an hour of driving: thousands of nodes), so live, with map_update_max_solve_share > 0, a periodic
//    solve also waits until the wall clock says the solves so far took at most that share of the time: after
//    a solve of d wall seconds the next periodic one waits d·(1/share − 1) wall seconds (counted in
//    solves_deferred per processed scan that found it due but waiting). Solves change only the outputs
//    (Map, GetTextMap, MapToOdom), never the filter nor what the back end's nodes are made of (a solve
//    leaves the newest node's fusion waiting for its scans until Flush(): TextSlam::Solve), so the final
//    Flush() and Solve() give the same to the bit whatever solves (periodic, or the nodelet's saves) ran before.
//    After a solve the heap's freed pages go back to the system (common/freed_memory.h): a solve's
//    temporaries would otherwise keep the mapper's resident memory at its largest solve's peak.
//  - map -> odom = estimate ∘ (odometry)⁻¹ at the last processed scan (TextSlam::EstimatedPose: the last
//    solve's newest node ⊕ odometry since, else the best particle), recomputed after every processed
//    scan, used plate and Solve().
// Getters are const and return what the last call left; they do no work. Deterministic for a given
// slam.slam.seed and input sequence.
#pragma once

#include <cstddef>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/sensors/laser_scan.h"
#include "doorplate_localization/slam/text_slam.h"

namespace doorplate_localization {

// camera_wait_s of the mapping nodelet and doorplate_map_bag (scan stamps): the demo's recorded reports
// came up to 3.5 s after their image (the simulator at 5x on a loaded 2-core machine).
constexpr double kDefaultCameraWaitS = 5.0;

struct MappingSessionOptions {
  TextSlamOptions slam;                      // the filter (linear/angular update thresholds), plates, back end
  int throttle_scans = 1;                    // use every n-th scan given (gmapping's throttle_scans), >= 1
  double temporal_update_s = -1.0;           // > 0: also process a scan this long after the last processed one
  double map_update_interval_s = 0.0;        // > 0: Solve() after a processed scan this long after the last solve;
                                             // 0: only when the caller calls Solve()
  double plate_range_max_scan_age_s = 0.5;   // range from a scan at most this far in time from the sighting
  double scan_history_s = 10.0;              // scans kept this long (newest's stamp) for late sightings' ranges
                                             // (an OCR report arrives seconds after its image on a busy machine)
  double camera_wait_s = 0.0;                // > 0: scans wait for the camera's reports up to their stamp, at
                                             // most this long (scan stamps), [0, 60]; 0: no waiting (see above)
  double map_update_max_solve_share = 0.0;   // in [0, 1): periodic solves take at most this share of the wall
                                             // clock (see above); 0: off (deterministic timing of the outputs,
                                             // the offline tools' setting)
};

// Throws std::invalid_argument naming the field ("MappingSessionOptions.throttle_scans ...", or
// TextSlamOptions' own message) for an option out of range.
void ValidateMappingSessionOptions(const MappingSessionOptions& options);

// What became of one plate sighting.
struct MappingPlateOutcome {
  double stamp_s = 0.0;
  PlateReading sighting;      // as given to TextSlam (range_m from the session's range rule if it had none)
  TextSlamPlateResult result;
};

// What one AddScan / AddPlates / Solve call did.
struct MappingUpdate {
  bool scan_taken = false;          // AddScan: the scan was accepted (stamp in order, not throttled away)
  bool scan_processed = false;      // the filter processed a scan in this call (a new trajectory pose / graph
                                    // node): AddScan's own, or with camera_wait_s > 0 any waiting one (also
                                    // in AddPlates and Flush)
  std::string scan_refused_reason;  // AddScan: why it was refused ("" when taken or throttled)
  std::vector<MappingPlateOutcome> plates;  // sightings applied by this call (AddScan: held ones), stamp order
  int plates_held = 0;              // AddPlates: sightings held for a scan near their stamp (see the rules)
  bool solved = false;              // Solve() ran: Map(), GetTextMap(), BackEndResult() are new
  bool map_to_odom_changed = false; // MapToOdom() was recomputed
};

struct MappingSessionCounters {
  long long scans = 0;              // AddScan calls
  long long scans_refused = 0;      // stamp not after the previous scan's
  long long scans_processed = 0;
  long long scans_camera_wait_expired = 0;  // camera_wait_s > 0: sent on without the camera's reports up to them
  long long plate_sightings = 0;    // given to AddPlates
  long long plates_held = 0;        // held for a scan near their stamp (applied later, or still waiting)
  long long plates_late = 0;        // camera_wait_s > 0: stamped before a scan the filter already had
  long long plates_used = 0;        // TextSlamPlateResult::used
  long long plate_ranges_from_wall = 0;  // ranges taken from the wall line (something stood before the plate)
  long long solves = 0;
  long long solves_deferred = 0;    // processed scans at which a periodic solve was due but the wall-clock share
                                    // (map_update_max_solve_share) made it wait
  double last_solve_wall_s = 0.0;   // wall-clock duration of the last Solve()
};

class MappingSession {
 public:
  static constexpr std::size_t kMaxHeldPlates = 256;  // sightings waiting for a scan near their stamp
  static constexpr std::size_t kMaxWaitingScans = 4096;  // scans waiting for the camera; beyond, the oldest goes

  // Throws std::invalid_argument naming the field of a bad option.
  explicit MappingSession(const MappingSessionOptions& options);

  // A scan (laser frame; its mounting in scan.laser_pose) and the odometry (base_link in odom) at its
  // stamp. Throws std::invalid_argument for a bad
  // scan geometry or a non-finite pose (ValidateScan, TextSlam::AddScan; nothing changed).
  MappingUpdate AddScan(double stamp_s, const Pose2D& base_in_odom, const LaserScan& scan);
  // Plate sightings made at `stamp_s`, with the odometry at that stamp; with no sightings, the camera's
  // progress (camera_wait_s > 0: it has reported every image up to stamp_s). Throws std::invalid_argument
  // (naming the field, "PlateReading.bearing_rad ...") for a malformed sighting or a non-finite stamp or
  // pose; nothing of the call is kept then.
  MappingUpdate AddPlates(double stamp_s, const Pose2D& base_in_odom, const std::vector<PlateReading>& sightings);
  // The end of the input: every scan waiting for the camera goes to the filter and every held sighting is
  // applied, in stamp order (a held sighting without a scan near its stamp gets kNoRange); the newest node's
  // fusion takes the scans so far (TextSlam::FinishInput). Call before the
  // last Solve() of a log; the nodelet calls it when it shuts down.
  MappingUpdate Flush();
  // Solves the back end (TextSlam::Solve), rebuilds Map() and GetTextMap() and recomputes MapToOdom(). Before the first processed scan it does nothing (solved stays false).
  MappingUpdate Solve();

  // --- state (as left by the last call; no getter does work beyond copying) ---
  bool started() const { return slam_.slam().started(); }
  // The grid and the text map built by the last Solve(); unset / empty before it.
  const std::optional<OccupancyGrid>& Map() const { return map_; }
  const TextMap& GetTextMap() const { return text_map_; }
  // base_link in map per processed scan (TextSlam::Trajectory), and the index of each such scan among the
  // AddScan calls (0-based; with camera_wait_s > 0 among the scans taken, in stamp order).
  std::vector<Pose2D> Trajectory() const { return slam_.Trajectory(); }
  const std::vector<int>& processed_scan_indices() const { return processed_scan_indices_; }
  const std::optional<SlamBackEndResult>& BackEndResult() const { return slam_.BackEndResult(); }
  // map -> odom (takes odom coordinates to map ones); unset before the first processed scan.
  const std::optional<Pose2D>& MapToOdom() const { return map_to_odom_; }
  // base_link in map at odometry `base_in_odom` (TextSlam::EstimatedPose). Requires started().
  Pose2D PoseAtOdometry(const Pose2D& base_in_odom) const { return slam_.EstimatedPose(base_in_odom); }
  // Odometry at the last processed scan.
  const Pose2D& LastProcessedOdometry() const { return slam_.slam().LastProcessedOdometry(); }
  const TextSlam& slam() const { return slam_; }
  const MappingSessionCounters& counters() const { return counters_; }
  // Sightings held for a scan near their stamp (not yet applied).
  std::size_t held_plates() const { return held_.size(); }
  // Scans taken but waiting for the camera (camera_wait_s > 0).
  std::size_t waiting_scans() const { return waiting_.size(); }
  const MappingSessionOptions& options() const { return options_; }
  // The wall clock the solve share is measured with (seconds, monotonic; default std::chrono::steady_clock);
  // tests pass a fake one.
  void SetWallClock(std::function<double()> clock) { wall_clock_ = std::move(clock); }

 private:
  struct TimedScan {
    double stamp_s;
    LaserScan scan;
  };
  struct HeldPlate {
    double stamp_s;
    Pose2D base_in_odom;
    PlateReading sighting;
  };
  struct WaitingScan {
    double stamp_s;
    Pose2D base_in_odom;
    int index;  // among the AddScan calls; with camera_wait_s > 0 among the scans taken, in stamp order
    LaserScan scan;
  };
  bool Ordering() const { return options_.camera_wait_s > 0; }
  // Why a scan of `stamp_s` is refused ("" if not): not after the previous one; with camera_wait_s > 0, not
  // after the last one given to the filter, or the stamp of one waiting (a late scan waits in its place).
  std::string RefuseScan(double stamp_s) const;
  std::string RefuseOrderedScan(double stamp_s) const;
  // The filter's update with a taken scan, then the solve rule.
  void ProcessScan(const WaitingScan& taken, MappingUpdate* update);
  // camera_wait_s > 0: sends on every waiting scan the camera has reported up to (all with `flush`), each
  // after the held sightings stamped before it.
  void SendWaitingScans(bool flush, MappingUpdate* update);
  // Applies the held sightings stamped before `stamp_s` (all with nullopt), in stamp order.
  void ApplyHeldBefore(std::optional<double> stamp_s, MappingUpdate* update);
  // nullopt with *why set (which of the two rules failed, with the stamps) when there is no range.
  std::optional<double> RangeFor(double stamp_s, double bearing_rad, std::string* why);
  // True when a scan nearer in time to `stamp_s` may still arrive: none within the age limit, none newer.
  bool ScanMayStillCome(double stamp_s) const;
  // Range rule + TextSlam::AddPlate; the outcome goes to update->plates. Returns whether it was used.
  bool ApplyPlate(double stamp_s, const Pose2D& base_in_odom, const PlateReading& given, MappingUpdate* update);
  void RefreshMapToOdom(MappingUpdate* update);

  const MappingSessionOptions options_;
  TextSlam slam_;
  std::deque<HeldPlate> held_;             // waiting for a scan near their stamp, arrival order
  std::deque<TimedScan> scans_;            // received scans within scan_history_s of the newest, newest last
  std::deque<WaitingScan> waiting_;        // camera_wait_s > 0: taken, not yet given to the filter (stamp order)
  std::optional<double> camera_stamp_s_;   // the newest AddPlates stamp (the camera reported up to it)
  std::optional<double> last_sent_stamp_s_;  // the newest scan given to the filter
  std::optional<double> last_scan_stamp_s_;
  std::optional<double> last_processed_stamp_s_, last_solve_stamp_s_;  // scan stamps
  std::function<double()> wall_clock_;
  std::optional<double> next_periodic_solve_wall_s_;  // map_update_max_solve_share > 0: not before this
  int scan_calls_ = 0;
  int ordered_index_ = 0;                  // camera_wait_s > 0: scans given to the filter so far
  std::vector<int> processed_scan_indices_;
  std::optional<OccupancyGrid> map_;
  TextMap text_map_;
  std::optional<Pose2D> map_to_odom_;
  MappingSessionCounters counters_;
};

}  // namespace doorplate_localization

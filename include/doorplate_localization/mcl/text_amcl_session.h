// TextAmclSession: the one run loop of Text AMCL. The nodelet (src/ros/text_amcl_nodelet.cpp), the
// experiment (`doorplate_eval localize`) and the soak (`doorplate_soak`) feed it odometry, scans and plate
// readings and publish or score what it returns; none of them calls TextAmcl itself. ROS-free.
//
// Frames: `map` (the occupancy grid's and the text map's frame; particles and the estimate are base_link
// there), `odom` (odometry: base_link in odom), `base_link` (the robot; plate bearings and the laser's
// mounting pose are in it). Units: metres, radians, seconds. Stamps are any monotonic clock in seconds
// (ROS time, simulated time), the same one for every input.
//
// The rules, each in one place:
//  - Scans (AddScan) carry the odometry at their stamp. amcl's gating: the filter moves once the robot
//    moved update_min_d_m or turned update_min_a_rad since its last motion update, and a scan weighs the
//    particles only after the filter moved (or was just initialized, or RequestNoMotionUpdate); it
//    resamples every resample_interval-th laser update. A scan older than the previous one is ignored
//    (the session continues from it).
//  - Ordering: every observation is weighed at the odometry pose of its own stamp. A plate reading waits
//    until the session's odometry has reached its stamp (AddOdometry or a scan's odometry, stamp >= the
//    reading's), then the filter is moved (forced, as amcl's request_nomotion_update: no gating) to the
//    odometry interpolated at the reading's stamp — forwards, or back when the reading arrives after
//    newer scans (OCR latency) — and weighed by the plate; the next scan is moved to its own stamp
//    (forced) before its laser update. No laser update is forced for a plate: the scan at hand was taken at
//    another time and has been (or will be) used at its own stamp; using it again would count it twice.
//    Readings are applied in stamp order, and before a scan with a later stamp.
//  - Plate range: PlateRangeAlongBearing (sensors/plate_range.h, plate_range: the median of the echoes
//    within ± beam_window_rad of the reading's bearing, or the wall line behind someone standing before the
//    plate; the mapping session's rule) in the scan nearest in time to the reading among the last two
//    received, if within text_range_max_scan_age_s of it. The input reading's range_m is ignored (the
//    session measures it).
//  - Unknown rooms: a reading no plate of the text map can explain (TextMatcher::Compatible with the
//    plate model's text_match options is empty) is dropped and counted when it arrives (AddPlates), before
//    any ordering; the first reading of each such room is flagged (kUnknownRoomFirst) so the caller
//    reports it once.
//  - Without a text map (or with setup.use_text false) readings are dropped when they arrive (kNoTextMap).
//  - map -> odom = estimate ∘ (odometry pose the filter was last moved to)⁻¹, recomputed after every
//    update that changed the particles' weights (a used scan, a weighed plate).
// Getters return what the last call computed; they do no work. Deterministic for a given random_seed
// and input sequence.
#pragma once

#include <cmath>
#include <deque>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/mcl/localization_scan.h"
#include "doorplate_localization/sensors/plate_reading.h"
#include "doorplate_localization/mcl/text_amcl.h"
#include "doorplate_localization/mcl/text_amcl_setup.h"
#include "doorplate_localization/mcl/text_match.h"
#include "doorplate_localization/sensors/plate_range.h"

namespace doorplate_localization {

struct TextAmclSessionOptions {
  TextAmclSetupOptions setup;  // the filter and its models (MakeTextAmcl)
  // Start: particles uniform over the free space (amcl's global_localization), else drawn from
  // N(initial_pose, initial_covariance) (map frame; x_m, y_m, theta_rad; amcl's defaults).
  bool start_with_global_localization = false;
  Pose2D initial_pose;
  Eigen::Matrix3d initial_covariance = Eigen::Vector3d(0.25, 0.25, (M_PI / 12.0) * (M_PI / 12.0)).asDiagonal();
  // Plate range from the laser (see the file comment). false: readings are bearing-only.
  bool text_use_laser_range = true;
  PlateRangeOptions plate_range;
  double text_range_max_scan_age_s = 0.5;
  // Odometry kept for readings that arrive late; an older reading is dropped (kStale).
  double odometry_history_s = 10.0;
  // Readings waiting for odometry to reach their stamp; beyond this the oldest is dropped (kStale).
  int max_pending_plate_readings = 32;
};

// What became of one plate reading.
enum class PlateDisposition {
  kWeighed,          // given to TextAmcl::UpdatePlate (result.used says whether it reweighted)
  kUnknownRoomFirst, // dropped: its room is not in the text map; the first reading of that room
  kUnknownRoom,      // dropped: the same, a room already reported
  kNoTextMap,        // dropped: laser only
  kStale,            // dropped: older than the odometry history, or pushed out of the pending queue
  kInvalid,          // dropped: ValidatePlateReading failed (detail says why)
};
const char* ToString(PlateDisposition disposition);

struct PlateReadingOutcome {
  double stamp_s = 0.0;
  PlateReading reading;  // as weighed: bearing in base_link, range_m from the session's range rule
  PlateDisposition disposition = PlateDisposition::kWeighed;
  PlateUpdateResult result;  // kWeighed only
  std::string detail;        // kInvalid: the validation problem
};

// What one AddScan / AddOdometry / AddPlates call did.
struct SessionUpdate {
  bool laser_used = false;          // AddScan: the scan weighed the particles
  std::string scan_ignored_reason;  // AddScan: why the scan was refused ("" when taken, used or gated)
  std::vector<PlateReadingOutcome> plates; // readings resolved by this call (queued earlier or now), stamp order
  int plates_pending = 0;           // readings still waiting for odometry after this call
  bool estimate_changed = false;    // Estimate(), Status() and MapToOdom() were recomputed
};

struct TextAmclSessionCounters {
  long long scans = 0;               // taken by AddScan (not refused)
  long long laser_updates = 0;       // of them, used by the filter
  long long plate_readings = 0;      // given to AddPlates
  long long plates_weighed = 0;      // kWeighed
  long long plates_used = 0;         // of them, PlateUpdateResult::used
  long long unknown_room_readings = 0;
  long long stale_readings = 0;
  long long invalid_readings = 0;
};

class TextAmclSession {
 public:
  // Builds the filter (MakeTextAmcl) on `map` with `text_map` (may be null: laser only) and starts it
  // (initial pose or global localization). Throws std::invalid_argument naming the field of a bad option
  // or an unusable map / text map.
  TextAmclSession(const TextAmclSessionOptions& options, const OccupancyGrid& map,
                  std::shared_ptr<const TextMap> text_map);

  // Goes on from `previous` (a session on the same `map`, whose text map it keeps) under new options, as
  // dynamic_reconfigure asks: the filter and its models are rebuilt from `options` and continue from the
  // previous filter (TextAmcl::ContinueFrom: the particles are kept); the odometry history, pending
  // readings, recent scans, unknown rooms, counters, estimate and map -> odom carry over. Throws
  // std::invalid_argument as the other constructor; `previous` is never changed.
  TextAmclSession(const TextAmclSessionOptions& options, const OccupancyGrid& map, const TextAmclSession& previous);

  // Restart the particles (amcl's initialpose and global_localization). MapToOdom() is unset until the
  // next update; the odometry history and pending readings are kept.
  void Initialize(const Pose2D& mean, const Eigen::Matrix3d& covariance);
  void GlobalLocalization();
  // The next scan updates the filter even without motion (amcl's request_nomotion_update).
  void RequestNoMotionUpdate();

  // Odometry (base_link in odom) at `stamp_s`; applies the readings it brings within reach. A stamp
  // older than the latest odometry is ignored (returns an empty update).
  SessionUpdate AddOdometry(double stamp_s, const Pose2D& base_in_odom);
  // A scan (laser frame, with its mounting pose in base_link) and the odometry at its stamp: applies the
  // readings up to its stamp, then the motion and laser update rules. Throws std::invalid_argument for a
  // scan ValidateLocalizationScan refuses (nothing changed).
  SessionUpdate AddScan(double stamp_s, const Pose2D& base_in_odom, const LaserScan& scan);
  // Plate readings taken at `stamp_s` (bearing in base_link; range_m ignored). Invalid ones, unknown rooms
  // and (laser only) all are dropped now; the others are applied now if odometry has reached the stamp,
  // else queued.
  SessionUpdate AddPlates(double stamp_s, const std::vector<PlateReading>& readings);

  // --- state (as left by the last call) ---
  const PoseEstimate& Estimate() const { return estimate_; }  // base_link in map: heaviest cluster
  const TextAmclStatus& Status() const { return status_; }     // state, lost reason, filter counters
  // map -> odom (the transform taking odom coordinates to map ones); unset before the first update
  // after a (re)start.
  const std::optional<Pose2D>& MapToOdom() const { return map_to_odom_; }
  // base_link in map at odometry `base_in_odom`: MapToOdom() ∘ base_in_odom, or the estimate when
  // MapToOdom() is unset. Pure arithmetic.
  Pose2D PoseAtOdometry(const Pose2D& base_in_odom) const;
  const std::vector<Particle>& particles() const { return filter_->particles(); }
  const TextAmclSessionCounters& counters() const { return counters_; }
  // Canonical ids of the unknown rooms read (at most limits::kMaxRememberedUnknownRooms).
  const std::set<std::string>& unknown_rooms() const { return unknown_rooms_; }
  bool has_text_map() const { return matcher_ != nullptr; }
  const TextAmclSessionOptions& options() const { return options_; }

 private:
  struct TimedPose {
    double stamp_s;
    Pose2D pose;
  };
  struct TimedScan {
    double stamp_s;
    LaserScan scan;
  };
  struct PendingReading {
    double stamp_s;
    PlateReading reading;
  };

  void Restarted();
  void RecordOdometry(double stamp_s, const Pose2D& base_in_odom);
  std::optional<Pose2D> OdometryAt(double stamp_s) const;
  // Applies the pending readings with stamp <= latest odometry (and drops stale ones) into *update.
  void ApplyPending(SessionUpdate* update);
  void ApplyReading(const PendingReading& pending, SessionUpdate* update);
  std::optional<double> RangeFor(double stamp_s, double bearing_rad) const;
  // Moves the filter to `base_in_odom` (forced or gated); returns whether it moved.
  bool MoveFilter(const Pose2D& base_in_odom, bool forced);
  void Refresh(SessionUpdate* update);

  const TextAmclSessionOptions options_;
  std::shared_ptr<const TextMap> text_map_;  // null: laser only
  std::unique_ptr<TextMatcher> matcher_;     // set when readings are used
  std::unique_ptr<TextAmcl> filter_;
  std::deque<TimedPose> odometry_;          // newest last, within odometry_history_s of the newest
  std::deque<PendingReading> pending_;      // stamp order
  std::deque<TimedScan> scans_;             // the last two, newest last
  std::optional<Pose2D> filter_odom_;       // odometry pose the filter was last moved to (its reference)
  bool move_at_next_scan_ = false;          // a plate moved the filter to another stamp
  std::set<std::string> unknown_rooms_;
  PoseEstimate estimate_;
  TextAmclStatus status_;
  std::optional<Pose2D> map_to_odom_;
  TextAmclSessionCounters counters_;
};

}  // namespace doorplate_localization

// RBPF SLAM with doorplate text landmarks (the seed paper's mapping stage, Sec. 3.3, eqs. 13-14): the
// laser RBPF (rbpf_slam.h) plus, per particle, the plates it has mapped. A plate's position is the
// particle's pose at the reading ⊕ (bearing, range) (range from the reading or the last scan's beam).
// A new text adds a landmark to every particle; re-reading a text near one of a particle's landmarks
// reweights the particle by how well the two positions agree (Gaussian in the wall-axis distance), which
// keeps the particles whose trajectory brought them back to the same plate (loop closure).
// Per-particle landmark lists are immutable shared nodes (like the trajectory tree), so resampling
// copies pointers. Adjacent-plate distances are also measured by odometry (eq. 13) for the text map.
// The back end (slam_back_end.h) is solved only by Solve(); every getter is const and pure: it returns
// what the filter and the last Solve() hold and does no work behind the caller's back. The run loop
// (throttling, stamps, plate ranges, when to solve) is MappingSession's (mapping_session.h).
// The laser filter runs with the degeneracy-aware proposal on (DefaultTextSlamLaserOptions).
// Frames: the map frame is the odometry frame at the first scan; base_link poses; plates on the floor
// plane. Units: metres, radians. See docs/slam.md for the design choices and their measurements.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "doorplate_localization/common/room_id.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/sensors/plate_range.h"
#include "doorplate_localization/sensors/plate_reading.h"
#include "doorplate_localization/slam/rbpf_slam.h"
#include "doorplate_localization/slam/slam_back_end.h"

namespace doorplate_localization {

// The laser filter's options for text SLAM: RbpfSlamOptions' defaults plus the degeneracy-aware proposal
// (degenerate_min_points = 10; docs/slam.md, measured on paper_real_corridor).
RbpfSlamOptions DefaultTextSlamLaserOptions();

struct TextSlamOptions {
  RbpfSlamOptions slam = DefaultTextSlamLaserOptions();
  double min_confidence = 0.5;          // readings less sure than this are ignored
  double min_plate_range_m = 0.2;       // plate ranges outside [min, max] are ignored (bad beam)
  double max_plate_range_m = 5.0;
  // A sighting's range when it has none: PlateRangeAlongBearing (sensors/plate_range.h) in the scan nearest
  // in time (MappingSession). Names: text.range_beam_window_rad, text.occluded_plate_margin_m, text.wall_range.*
  PlateRangeOptions plate_range;
  double plate_sigma_m = 0.15;          // 1-sigma error of one plate position measurement
  double association_radius_m = 3.0;    // a same-text reading this close to a particle's landmark re-observes it
  double text_likelihood_gain = 1.0;    // multiplies the re-observation log-likelihood
  double max_odometry_gap_m = 2.0;      // readings further (odometry) from the last processed scan are ignored
  // The building's room identifier format (common/room_id.h): readings whose canonical form does not fit are
  // ignored, and BuildTextMap() writes it as the text map's room_pattern. Readings are associated with
  // landmarks by canonical form ("E14295" re-observes "E14-295"; "312B" never re-observes "312A").
  std::string room_pattern = kDefaultRoomPattern;
  // The pose-graph back end (slam_back_end.h): when enabled, the map, the plates and Trajectory() come
  // from the optimized graph instead of the best particle. Its plate_sigma_m is set from the field above.
  SlamBackEndOptions back_end;
};

enum class PlateOutcome {
  kNewLandmark,          // used: first reading of this text near here, a landmark was added
  kReobserved,           // used: matched an existing landmark, particles were reweighted
  kLowConfidence,        // ignored: confidence < min_confidence
  kNoRange,              // ignored: no range (none given, or no usable beam along the bearing)
  kRangeOutOfBounds,     // ignored: range outside [min_plate_range_m, max_plate_range_m]
  kNoScanYet,            // ignored: no scan processed yet (the map frame is not defined)
  kTooFarFromLastScan,   // ignored: odometry moved more than max_odometry_gap_m since the last scan
  kNotARoomId,           // ignored: the text's canonical form does not fit room_pattern
};

struct TextSlamPlateResult {
  PlateOutcome outcome = PlateOutcome::kNoScanYet;
  int landmark_index = -1;     // index in BuildTextMap().landmarks (best particle) if used, else -1
  double range_m = 0.0;        // the range used (given or from the scan), 0 if none
  std::string reason;          // human-readable explanation (for logs)
  bool used() const { return outcome == PlateOutcome::kNewLandmark || outcome == PlateOutcome::kReobserved; }
};

class TextSlam {
 public:
  // Throws std::invalid_argument naming the field if an option is out of range.
  explicit TextSlam(const TextSlamOptions& options);

  // As RbpfSlam::AddScan (force_update: process it whatever the motion, gmapping's temporalUpdate). With the
  // back end on, a processed scan becomes a back-end node and is kept for re-rendering, unless the node was
  // added on mapped ground (SlamBackEndOptions::max_nodes_per_place: the place already holds enough scans).
  // Throws std::invalid_argument for a non-finite odometry pose (nothing is added).
  bool AddScan(const LaserScan& scan, const Pose2D& odometry_pose, int scan_index, bool force_update = false);

  // A doorplate read at the time of `odometry_pose` (base_link in odom); it is tied to the last processed
  // scan by the odometry between the two (either way in time). Never throws on a reading that is merely
  // unusable (returns why it was ignored); throws std::invalid_argument naming the field
  // ("PlateReading.bearing_rad ...", ValidatePlateReading) for NaN or out-of-range fields or an empty text.
  TextSlamPlateResult AddPlate(const PlateReading& sighting, const Pose2D& odometry_pose);

  // Solves the back end's graph over every node and plate reading so far and keeps the result for the
  // getters below (no-op with the back end off or before the first scan). The only call that solves.
  // A node whose fused points still wait for the scans after it (back_end.node_fusion.scans_after) keeps
  // waiting and takes no alignment in this solve (SlamBackEnd::Optimize's pending_node; odometry and plates
  // hold it), so solves in the middle of a run (map updates, saves) change nothing the final one computes.
  void Solve();
  // The end of the input: a node still waiting for scans after it takes its points fused with those so far
  // (the next Solve() aligns it). Scans may still follow (they are mapped as usual).
  void FinishInput();

  // The map (map_server-ready: -1 unknown, 0 free, 100 occupied): every processed scan rendered at
  // Trajectory()'s poses when the back end is on and was solved, else the best particle's map. Renders
  // the grid (cost grows with the scans); does not solve. Throws std::logic_error before the first scan.
  OccupancyGrid BuildOccupancyGrid() const;
  // base_link in the map frame at every processed scan. Back end on and solved: the last solve's poses,
  // and for scans processed since, the newest solved pose ⊕ the odometry since. Else the best particle's
  // history.
  std::vector<Pose2D> Trajectory() const;
  // The last Solve()'s result; unset with the back end off or before the first Solve().
  const std::optional<SlamBackEndResult>& BackEndResult() const { return solved_; }
  // Processed scans (back-end nodes) not yet in BackEndResult(); 0 with the back end off.
  int nodes_since_solve() const;
  // The best particle's landmarks (index = landmark id order) with adjacent distances from the map
  // (eq. 13, source "map") and from odometry (source "odometry"). Walls are labelled "wall0", "wall1",
  // ...: plates facing the same way (within 30°) on the same line (within 0.5 m across it) share one.
  TextMap BuildTextMap() const;
  // base_link in the map frame, best particle, at the last processed scan.
  Pose2D BestPose() const;
  // base_link in the map frame at `odometry_pose` (base_link in odom): the last solve's newest node ⊕ the
  // odometry since when there is a solve, so that the pose agrees with the map last built; else the best
  // particle's pose ⊕ the odometry since the last processed scan.
  Pose2D EstimatedPose(const Pose2D& odometry_pose) const;
  // The best particle's landmarks, in id order; positions from the last solve for the plates it placed.
  std::vector<SlamLandmark> BestLandmarks() const;
  const RbpfSlam& slam() const { return slam_; }
  // The back end's graph as built so far (nodes, counts); solved only by Solve().
  const SlamBackEnd& back_end() const { return back_end_; }
  const TextSlamOptions& options() const { return options_; }
  int num_landmarks() const { return next_landmark_id_; }

 private:
  const TextSlamOptions options_;
  RoomIdGrammar room_grammar_;          // options_.room_pattern
  RbpfSlam slam_;
  SlamBackEnd back_end_;
  ScanFusion node_fusion_;              // the last scans, for the back end's node points (back_end.node_fusion)
  // The latest node whose points wait for the scans after it (node index, its scan's id in node_fusion_).
  std::optional<std::pair<int, long>> node_awaiting_scans_;
  // Gives that node its points fused with the scans after it that came (SlamBackEnd::ReplaceNodePoints).
  void FinishNodeAwaitingScans();
  // The processed scans of the nodes that kept theirs (node index, scan), for re-rendering (back end on).
  std::vector<std::pair<int, LaserScan>> node_scans_;
  std::optional<SlamBackEndResult> solved_;  // the last Solve()
  int next_landmark_id_ = 0;
  // eq. 13 by odometry: per landmark id, the plate's position in the odometry frame at its first reading.
  std::vector<Vec2> first_reading_in_odom_;
};

}  // namespace doorplate_localization

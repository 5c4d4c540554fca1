// Rao-Blackwellized particle filter SLAM (gmapping's design, Grisetti et al. 2007; the seed paper's
// eqs. 5-6: p(x_1:t, m | z, u) = p(m | x_1:t, z) · p(x_1:t | z, u)). Each particle is a trajectory
// hypothesis with its own log-odds map (eqs. 1-4). The proposal is a scan match against the
// particle's own map with the odometry prediction as prior (scan_matcher.h), searched around a step
// that one wide search on the best particle's map corrected first; weights come from the scan
// likelihood at the proposed pose; resampling happens when Neff drops below a threshold. See
// docs/slam.md for the choices and their measurements.
// Maps are tiled and copy-on-write, trajectories are trees of shared nodes: resampling copies
// pointers. Frames: the map frame is the odometry frame at the first scan. Units: metres, radians.
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "doorplate_localization/sensors/odometry_motion_model.h"
#include "doorplate_localization/sensors/laser_scan.h"
#include "doorplate_localization/slam/scan_matcher.h"
#include "doorplate_localization/slam/slam_landmark.h"
#include "doorplate_localization/slam/tiled_grid.h"
#include "doorplate_localization/slam/trajectory_tree.h"

namespace doorplate_localization {

struct RbpfSlamOptions {
  int num_particles = 50;
  double linear_update_m = 0.5;        // process a scan after this much driving...
  double angular_update_rad = 0.25;    // ...or this much turning since the last processed one
  double resample_neff_ratio = 0.5;    // resample when Neff < ratio × num_particles
  double likelihood_gain = 0.01;       // tempers scan log-likelihoods into log-weights (beams correlate)
  double max_usable_range_m = 30.0;    // longer beams only clear free space, up to here
  double no_return_clear_range_m = 10.0;  // beams without echo (+inf) clear free space up to here
  int max_match_points = 360;          // scan points used by the matcher (evenly subsampled)
  // Echoes longer than this are mapped but not matched (0: no limit). Set it a little below the laser's
  // range: the map ends where the previous scans reached, so the last metre of a scan lands in unknown
  // cells ahead, and matching it pulls the pose back (a corridor map shrinks; docs/slam.md).
  double max_match_range_m = 0.0;
  double mean_trajectory_radius_m = 0.5;  // MeanTrajectory() averages histories this close to the best
  // Degeneracy-aware proposal (docs/slam.md): the scan's surface normals give its information about
  // position, Σ n nᵀ over echoes with a local line fit (in "points": a wall seen head-on by k beams adds
  // k along its normal). Along the eigenvector of the smaller eigenvalue λ (a corridor's axis) the
  // proposal keeps the share clamp((λ − k)/k, 0, 1) of the match's correction, k = this: none below k
  // (odometry only: the particle's odometry sample), all of it above 2k (e.g. an end wall in range);
  // across it the match wins. 0 = off (the laser-only default, as on the real logs).
  double degenerate_min_points = 0.0;
  std::uint64_t seed = 1;
  TiledGridOptions grid;
  ScanMatcherOptions matcher;
  OdometryMotionModelOptions motion = MapperOdometryDefaults();  // linear law, see odometry_motion_model.h
};

struct SlamParticle {
  Pose2D pose;                   // base_link in the map frame at the last processed scan
  double log_weight = 0.0;       // since the last resampling
  double log_score = 0.0;        // tempered log-likelihood of the whole history (ranks particles)
  TiledGrid map;
  TrajectoryHandle trajectory;   // newest node; ancestors shared with other particles
  SlamLandmarksHandle landmarks; // text landmarks (text_slam.h); shared with other particles, null if none
};

// Counters over the whole run, for progress lines and tests.
struct RbpfSlamStats {
  int scans_seen = 0;
  int scans_processed = 0;
  int resamplings = 0;
  long matches = 0;        // per-particle proposals that used the scan match
  long weak_matches = 0;   // ...that kept the odometry prediction (weak match)
  long rejected_jumps = 0; // ...that kept it because the match jumped too far
  int degenerate_scans = 0; // processed scans whose position was constrained along one axis only
  double last_neff = 0.0;
};

class RbpfSlam {
 public:
  explicit RbpfSlam(const RbpfSlamOptions& options);

  // Feeds one scan and the odometry pose (base_link in the odometry frame) at its time. Returns true
  // if the scan was processed: the first scan, or after the update thresholds were exceeded, or
  // `force_update` (gmapping's temporalUpdate: process it whatever the motion).
  // `scan_index` is recorded in the trajectories. Throws std::invalid_argument on a bad scan geometry.
  bool AddScan(const LaserScan& scan, const Pose2D& odometry_pose, int scan_index, bool force_update = false);

  // Hook for other evidence (e.g. text landmarks): calls log_likelihood once per particle, in order,
  // with the particle itself; adds the result to its log-weight (untempered) and resamples if Neff
  // drops below the threshold.
  void ReweightParticles(const std::function<double(const SlamParticle&)>& log_likelihood);
  // The same, but the callback may also replace the particle's landmarks (*landmarks starts as the
  // particle's own handle). Resampling then copies the new handles.
  void UpdateLandmarksAndReweight(
      const std::function<double(const SlamParticle&, SlamLandmarksHandle* landmarks)>& update);

  const std::vector<SlamParticle>& particles() const { return particles_; }
  // The particle with the highest weight (ties: highest history score).
  const SlamParticle& BestParticle() const;
  std::vector<TrajectoryPoint> BestTrajectory() const { return UnrollTrajectory(BestParticle().trajectory); }
  // The posterior mean of the trajectory: per processed scan, the weighted mean pose of the particles
  // whose histories stay within mean_trajectory_radius_m (RMS) of the best particle's, i.e. of the
  // best particle's mode (in a symmetric corridor other modes are not averaged in). It is the estimate
  // with the least expected squared position error; the map stays the best particle's.
  std::vector<TrajectoryPoint> MeanTrajectory() const;
  double Neff() const;
  // Bytes held by the tiles of all particles' maps, each shared tile counted once.
  std::size_t MapMemoryBytes() const;
  const RbpfSlamStats& stats() const { return stats_; }
  // True once the first scan was added (the map frame exists).
  bool started() const { return started_; }
  // Odometry pose (base_link in odom) at the last processed scan: a particle's pose at another odometry
  // pose o is particle.pose ⊕ (LastProcessedOdometry()⁻¹ ⊕ o).
  const Pose2D& LastProcessedOdometry() const { return last_odometry_; }
  const RbpfSlamOptions& options() const { return options_; }
  // Adds `scan` taken at `pose` (base_link in the map frame) to `map` by the filter's own beam rules
  // (echoes, cut beams, no-echo beams; docs/slam.md "Ranges"): how a back end re-renders a trajectory.
  void IntegrateScanInto(TiledGrid* map, const LaserScan& scan, const Pose2D& pose) const;
  // The scan's echoes used for matching (at most max_match_points, evenly subsampled), in base_link.
  std::vector<Vec2> MatchPoints(const LaserScan& scan) const { return PrepareScan(scan, /*match_only=*/true).match; }

 private:
  struct ScanPoints {
    Vec2 origin;                                   // the laser in base_link
    std::vector<Vec2> match;                       // endpoints used by the matcher, base_link
    enum class BeamEnd { kHit, kCut, kNoReturn };  // echo; echo beyond the usable range; no echo (+inf)
    std::vector<std::pair<Vec2, BeamEnd>> integrate;  // every usable beam's end (base_link) and kind
    Vec2 degenerate_axis;                          // base_link unit vector the scan does not fix...
    bool degenerate = false;                       // ...if its information is below degenerate_min_points
    double along_axis_gain = 1.0;                  // share of the correction kept along that axis, 0-1
  };
  // match_only: only `match` (the back end's node points, every scan at the laser's rate): no beam list to
  // integrate, no degeneracy axis.
  ScanPoints PrepareScan(const LaserScan& scan, bool match_only = false) const;
  int BestIndex() const;
  void Integrate(TiledGrid& map, const Pose2D& pose, const ScanPoints& points) const;
  // Resamples if Neff is low; then, if `scan` is given, adds it to every particle's map (once per
  // distinct parent) and appends the pose to the trajectories.
  void FinishStep(const ScanPoints* scan, int scan_index);

  const RbpfSlamOptions options_;
  const OdometryMotionModel motion_;
  const ScanMatcher matcher_;
  std::mt19937_64 rng_;
  std::vector<SlamParticle> particles_;
  bool started_ = false;
  Pose2D last_odometry_;           // odometry at the last processed scan
  Pose2D last_received_odometry_;  // odometry at the last scan fed
  StepSpread pending_spread_;      // motion spread accumulated since the last processed scan
  int last_scan_index_ = -1;
  RbpfSlamStats stats_;
};

}  // namespace doorplate_localization

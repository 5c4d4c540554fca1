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

#include "doorplate_localization/slam/motion_model.h"
#include "doorplate_localization/slam/range_scan.h"
#include "doorplate_localization/slam/scan_matcher.h"
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
  double mean_trajectory_radius_m = 0.5;  // MeanTrajectory() averages histories this close to the best
  std::uint64_t seed = 1;
  TiledGridOptions grid;
  ScanMatcherOptions matcher;
  MotionModelOptions motion;
};

struct SlamParticle {
  Pose2D pose;                   // base_link in the map frame at the last processed scan
  double log_weight = 0.0;       // since the last resampling
  double log_score = 0.0;        // tempered log-likelihood of the whole history (ranks particles)
  TiledGrid map;
  TrajectoryHandle trajectory;   // newest node; ancestors shared with other particles
};

// Counters over the whole run, for progress lines and tests.
struct RbpfSlamStats {
  int scans_seen = 0;
  int scans_processed = 0;
  int resamplings = 0;
  long matches = 0;        // per-particle proposals that used the scan match
  long weak_matches = 0;   // ...that kept the odometry prediction (weak match)
  long rejected_jumps = 0; // ...that kept it because the match jumped too far
  double last_neff = 0.0;
};

class RbpfSlam {
 public:
  explicit RbpfSlam(const RbpfSlamOptions& options);

  // Feeds one scan and the odometry pose (base_link in the odometry frame) at its time. Returns true
  // if the scan was processed: the first scan, or after the update thresholds were exceeded.
  // `scan_index` is recorded in the trajectories. Throws std::invalid_argument on a bad scan geometry.
  bool AddScan(const RangeScan& scan, const Pose2D& odometry_pose, int scan_index);

  // Hook for other evidence (e.g. text landmarks): calls log_likelihood once per particle, in order,
  // with the particle itself; adds the result to its log-weight (untempered) and resamples if Neff
  // drops below the threshold.
  void ReweightParticles(const std::function<double(const SlamParticle&)>& log_likelihood);

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
  const RbpfSlamOptions& options() const { return options_; }

 private:
  struct ScanPoints {
    Vec2 origin;                                   // the laser in base_link
    std::vector<Vec2> match;                       // endpoints used by the matcher, base_link
    std::vector<std::pair<Vec2, bool>> integrate;  // every usable beam's end and whether it hit
  };
  ScanPoints PrepareScan(const RangeScan& scan) const;
  int BestIndex() const;
  void Integrate(SlamParticle& particle, const ScanPoints& points) const;
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

// Text AMCL: an amcl-compatible Monte Carlo localizer (KLD-sampling, Augmented MCL recovery,
// cluster-based estimate, amcl's parameter names and update gating) that also uses doorplate readings:
// a reading reweights the particles by the plate likelihood model and, while the filter is not
// converged or when the reading contradicts its estimate (kidnapping), reseeds a share of them at the
// plates with a compatible text (paper sec. 3.4). The models are swappable interfaces passed in by
// shared_ptr (as nav2_amcl's plugins and PRBonn/tmcl's ReNMCL).
//
// Frames: particles and the estimate are base_link in the map frame; odometry poses are base_link in
// the odom frame; scans are in the laser frame with their mounting pose. Units: metres, radians.
//
// Health (State()):
//  - kConverged: the heaviest cluster holds > converged_cluster_weight of the weight, its position
//    std dev (largest eigenvalue of the x/y covariance) is < converged_stddev_m and its heading std dev
//    < converged_heading_stddev_rad; after global localization with a text model, also a plate reading
//    used since (converge_after_plate).
//  - kLost: latched when w_fast / w_slow drops below lost_likelihood_ratio (recent scans fit much worse
//    than usual), or when the filter was converged and a confident plate reading is not explained by
//    the heaviest cluster (kidnap: every compatible plate is inconsistent with the estimate). Cleared by
//    a resampling after which the filter is converged again (and w_fast / w_slow is back above the ratio).
//  - kTracking: otherwise (the filter runs but its belief is spread or multimodal).
// Deterministic: every random draw comes from one std::mt19937_64 seeded with random_seed.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "doorplate_localization/mcl/augmented_mcl.h"
#include "doorplate_localization/mcl/kld_sampler.h"
#include "doorplate_localization/mcl/laser_model.h"
#include "doorplate_localization/mcl/localization_grid.h"
#include "doorplate_localization/mcl/motion_model.h"
#include "doorplate_localization/mcl/plate_pose_sampler.h"
#include "doorplate_localization/mcl/pose_clusters.h"
#include "doorplate_localization/mcl/resampler.h"
#include "doorplate_localization/mcl/text_observation_model.h"

namespace doorplate_localization {

enum class LocalizationState { kTracking, kConverged, kLost };
enum class LostReason { kNone, kLikelihoodCollapse, kPlateContradiction };
const char* ToString(LocalizationState state);
const char* ToString(LostReason reason);

struct TextAmclOptions {
  // --- amcl's filter parameters (same names and defaults, units appended to the names) ---
  int min_particles = 100;
  int max_particles = 5000;
  double kld_err = 0.01;             // see kld_sampler.h for the exact meaning of both
  double kld_z = 0.99;
  double update_min_d_m = 0.2;       // translation that triggers a filter update
  double update_min_a_rad = M_PI / 6.0;  // rotation that triggers a filter update
  int resample_interval = 2;         // laser updates per resampling
  // Augmented MCL (augmented_mcl.h). ON by default (amcl ships 0.0 = off). 0 and 0 disable it.
  // Random particles are injected with probability max(0, 1 - (w_fast / w_slow) / lost_likelihood_ratio)
  // (the book's and amcl's rule when lost_likelihood_ratio is 1). The mean likelihood fed to the
  // averages leaves out the particles injected at the last resampling: random poses fit badly, and
  // counting them would lower w_fast, inject more, and spiral into a uniform cloud.
  double recovery_alpha_slow = 0.001;
  double recovery_alpha_fast = 0.1;
  // amcl zeroes both averages after every injection (one burst per collapse); the book does not.
  bool recovery_reset_after_injection = false;
  PoseBinSize histogram_bin;         // KLD and clustering bins (amcl: 0.5 m × 0.5 m × 10°)
  // --- doorplates ---
  double text_min_confidence = 0.5;  // readings below this are ignored
  // Share of the particles replaced by poses sampled at the plates compatible with a reading, when the
  // filter is not converged (global localization: no compatible plate may be missed) or the reading
  // contradicts the converged estimate (kidnapping). The reading contradicts the estimate when the
  // heaviest cluster's mean plate likelihood is below text_explained_ratio × the likelihood of an
  // unexplained reading. A converged filter that explains the reading reseeds nothing, so a repeated
  // room number does not revive the other plate's hypothesis once the filter knows where it is.
  double text_reseed_fraction = 0.2;
  double text_explained_ratio = 3.0;
  // --- health (see the file comment) ---
  double converged_cluster_weight = 0.9;
  double converged_stddev_m = 0.3;
  double converged_heading_stddev_rad = 0.35;
  // After GlobalLocalization(), with a text model, kConverged waits until a plate reading has been used:
  // scans alone cannot tell a symmetric floor's corners, or a corridor's two ends, apart. Measured on the
  // ring floor (docs/results/floor-localize.md): 1 wrong convergence in 90 trials, a quarter turn off after
  // 5 m of laser only, without a plate read. Initialize() (a known pose) does not wait.
  bool converge_after_plate = true;
  double lost_likelihood_ratio = 0.5;  // (0, 1]: lost below it; injection starts below it
  std::uint64_t random_seed = 1;
};

// The models the filter runs; grid, motion, laser and resampler are required. Without `text`, readings
// are ignored; without `plate_sampler`, readings reweight but never reseed.
struct TextAmclModels {
  std::shared_ptr<const LocalizationGrid> grid;  // global localization and random particles: free cells
  std::shared_ptr<MotionModel> motion;
  std::shared_ptr<LaserModel> laser;
  std::shared_ptr<Resampler> resampler;
  std::shared_ptr<TextObservationModel> text;
  std::shared_ptr<PlatePoseSampler> plate_sampler;
};

// The estimate as amcl publishes it on amcl_pose: the heaviest cluster's mean with the covariance of the
// WHOLE particle set (amcl_node.cpp: "report the overall filter covariance, rather than the covariance for
// the highest-weight cluster"), so a second hypothesis far away shows as a large covariance, which users
// gate on. The cluster's own covariance (what ~state's converged rule reads) is kept beside it.
struct PoseEstimate {
  Pose2D pose;                                         // mean of the heaviest cluster
  // (x_m, y_m, theta_rad) of all particles about their weighted mean (SetStatistics, pose_clusters.h):
  // weighted x/y block, heading -2 ln R, x/y-heading terms 0.
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d cluster_covariance = Eigen::Matrix3d::Zero();  // the same over the heaviest cluster only
  double cluster_weight = 0.0;                         // share of the weight in that cluster
  int cluster_count = 0;
};

struct PlateUpdateResult {
  bool used = false;                 // the reading reweighted the particles
  std::string ignored_reason;        // why not, when !used
  double explained_ratio = 0.0;      // weighted mean plate likelihood / unexplained likelihood, before
  double best_cluster_explained_ratio = 0.0;  // the same over the heaviest cluster
  bool contradicted_estimate = false;  // converged, and the heaviest cluster does not explain it (kidnap)
  int reseeded_particles = 0;
};

struct TextAmclStatus {
  LocalizationState state = LocalizationState::kTracking;
  LostReason lost_reason = LostReason::kNone;
  int particle_count = 0;
  double best_cluster_weight = 0.0;
  double position_stddev_m = 0.0;     // of the heaviest cluster
  double heading_stddev_rad = 0.0;
  double w_fast_over_w_slow = 1.0;
  int laser_updates = 0;
  int resamples = 0;
  int plate_updates = 0;
  int last_random_particles = 0;      // injected by the last resampling
  int total_random_particles = 0;
  int total_reseeded_particles = 0;
  int plate_contradictions = 0;
};

class TextAmcl {
 public:
  // Throws std::invalid_argument naming the field of a bad option, a missing model or a grid without a
  // free cell (NoFreeCellProblem: global localization and random particles need free space), so that
  // neither can fail later. The filter starts empty: call Initialize or GlobalLocalization.
  TextAmcl(const TextAmclOptions& options, TextAmclModels models);

  // max_particles particles drawn from N(mean, covariance) (x_m, y_m, theta_rad; positive
  // semi-definite, else std::invalid_argument). Resets the recovery averages and the odometry
  // reference (the pose holds at the next odometry reading); the next scan is used.
  void Initialize(const Pose2D& mean, const Eigen::Matrix3d& covariance);
  // max_particles particles uniform over the free cells with uniform headings (amcl's
  // global_localization service). Resets like Initialize.
  void GlobalLocalization();

  // Feeds the odometry pose (base_link in odom). The first call (after construction, Initialize or
  // GlobalLocalization) only stores it as the reference and returns false. Later calls move the
  // particles by the motion since the last filter update once it exceeds update_min_d_m or
  // update_min_a_rad (or after ForceUpdate) and return true; otherwise they return false and the
  // particles stay put (amcl's gating: no update while standing still).
  bool UpdateOdometry(const Pose2D& odom_pose);
  // Weighs the particles with a scan if the filter moved since the last scan update (or was just
  // initialized, or ForceUpdate was called); resamples every resample_interval-th update. Returns
  // whether the scan was used. Throws std::invalid_argument for an unusable scan (ValidateLocalizationScan).
  bool UpdateLaser(const LaserScan& scan);
  // Reweights (and maybe reseeds) with a doorplate reading, at any time. Throws std::invalid_argument
  // for an invalid reading (ValidatePlateReading); see PlateUpdateResult for what happened.
  PlateUpdateResult UpdatePlate(const PlateReading& reading);
  // Goes on from `previous` (a filter on the same map) under this filter's options and models: takes its
  // particles and weights, odometry reference, pending and forced updates, resampling count, recovery
  // averages (under this filter's alphas), health state, counters and random stream. The particle count
  // moves to this filter's KLD bounds at its next resampling; its health rules apply from its next update.
  // (amcl's dynamic_reconfigure instead redraws the particles around the last published pose.)
  void ContinueFrom(const TextAmcl& previous);
  // The next odometry/scan pair updates the filter even without motion (amcl's request_nomotion_update).
  void ForceUpdate() { force_update_ = true; }

  bool initialized() const { return !particles_.empty(); }
  // The heaviest cluster's mean, the whole set's covariance and the cluster's (PoseEstimate). Throws
  // std::logic_error before initialization.
  PoseEstimate Estimate() const;
  LocalizationState State() const { return state_; }
  TextAmclStatus Status() const;
  const std::vector<Particle>& particles() const { return particles_; }
  const ClusterResult& Clusters() const;
  const TextAmclOptions& options() const { return options_; }

 private:
  void Resample();
  // Re-evaluates the health state; a latched kLost clears only when `after_resample`.
  void UpdateHealth(bool after_resample);
  bool Converged(const PoseCluster& best) const;
  void ReplaceParticles(const std::vector<Pose2D>& poses);
  int ReseedFromPlate(const PlateReading& reading, std::vector<double>* log_likelihoods);

  const TextAmclOptions options_;
  const TextAmclModels models_;
  std::mt19937_64 rng_;
  KldSampler kld_;
  AugmentedMclAverages recovery_;
  std::vector<Particle> particles_;
  std::vector<char> counted_;            // per particle: 0 if injected at random by the last resampling
  std::vector<double> log_likelihoods_;  // scratch

  Pose2D last_odom_;
  bool has_odom_ = false;
  bool pending_update_ = false;  // moved (or initialized) since the last scan update
  bool force_update_ = false;
  int resample_counter_ = 0;

  LocalizationState state_ = LocalizationState::kTracking;
  LostReason lost_reason_ = LostReason::kNone;
  bool awaiting_plate_ = false;  // converge_after_plate: global localization, no plate reading used since
  TextAmclStatus counters_;

  mutable ClusterResult clusters_;
  mutable bool clusters_valid_ = false;
};

}  // namespace doorplate_localization

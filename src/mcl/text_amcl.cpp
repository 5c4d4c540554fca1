#include "doorplate_localization/mcl/text_amcl.h"

#include <algorithm>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace doorplate_localization {
namespace {

KldSamplerOptions KldOptions(const TextAmclOptions& o) {
  KldSamplerOptions k;
  k.min_particles = o.min_particles;
  k.max_particles = o.max_particles;
  k.kld_err = o.kld_err;
  k.kld_z = o.kld_z;
  k.bin_size = o.histogram_bin;
  return k;
}

void Require(bool ok, const std::string& field, const std::string& rule, double value) {
  if (!ok) throw std::invalid_argument("TextAmcl: " + field + ": " + rule + ", got " + std::to_string(value));
}

}  // namespace

const char* ToString(LocalizationState state) {
  switch (state) {
    case LocalizationState::kTracking: return "tracking";
    case LocalizationState::kConverged: return "converged";
    case LocalizationState::kLost: return "lost";
  }
  return "?";
}

const char* ToString(LostReason reason) {
  switch (reason) {
    case LostReason::kNone: return "none";
    case LostReason::kLikelihoodCollapse: return "likelihood_collapse";
    case LostReason::kPlateContradiction: return "plate_contradiction";
  }
  return "?";
}

TextAmcl::TextAmcl(const TextAmclOptions& options, TextAmclModels models)
    : options_(options),
      models_(std::move(models)),
      rng_(options.random_seed),
      kld_(KldOptions(options)),
      recovery_(options.recovery_alpha_slow, options.recovery_alpha_fast) {
  if (!models_.grid) throw std::invalid_argument("TextAmcl: models.grid: must not be null");
  if (!models_.motion) throw std::invalid_argument("TextAmcl: models.motion: must not be null");
  if (!models_.laser) throw std::invalid_argument("TextAmcl: models.laser: must not be null");
  if (!models_.resampler) throw std::invalid_argument("TextAmcl: models.resampler: must not be null");
  const std::string no_free = NoFreeCellProblem(*models_.grid);
  if (!no_free.empty()) throw std::invalid_argument("TextAmcl: models.grid: " + no_free);
  const auto& o = options_;
  Require(o.update_min_d_m >= 0.0, "update_min_d_m", "must be >= 0", o.update_min_d_m);
  Require(o.update_min_a_rad >= 0.0, "update_min_a_rad", "must be >= 0", o.update_min_a_rad);
  Require(o.resample_interval >= 1, "resample_interval", "must be >= 1", o.resample_interval);
  Require(o.text_min_confidence >= 0.0 && o.text_min_confidence <= 1.0, "text_min_confidence", "must be in [0, 1]",
          o.text_min_confidence);
  Require(o.text_reseed_fraction >= 0.0 && o.text_reseed_fraction <= 1.0, "text_reseed_fraction",
          "must be in [0, 1]", o.text_reseed_fraction);
  Require(o.text_explained_ratio >= 1.0, "text_explained_ratio", "must be >= 1", o.text_explained_ratio);
  Require(o.converged_cluster_weight > 0.0 && o.converged_cluster_weight <= 1.0, "converged_cluster_weight",
          "must be in (0, 1]", o.converged_cluster_weight);
  Require(o.converged_stddev_m > 0.0, "converged_stddev_m", "must be > 0", o.converged_stddev_m);
  Require(o.converged_heading_stddev_rad > 0.0, "converged_heading_stddev_rad", "must be > 0",
          o.converged_heading_stddev_rad);
  Require(o.lost_likelihood_ratio > 0.0 && o.lost_likelihood_ratio <= 1.0, "lost_likelihood_ratio",
          "must be in (0, 1]", o.lost_likelihood_ratio);
}

void TextAmcl::ContinueFrom(const TextAmcl& previous) {
  rng_ = previous.rng_;
  recovery_.TakeAveragesFrom(previous.recovery_);
  particles_ = previous.particles_;
  counted_ = previous.counted_;
  last_odom_ = previous.last_odom_;
  has_odom_ = previous.has_odom_;
  pending_update_ = previous.pending_update_;
  force_update_ = previous.force_update_;
  resample_counter_ = previous.resample_counter_;
  state_ = previous.state_;
  lost_reason_ = previous.lost_reason_;
  awaiting_plate_ = previous.awaiting_plate_;
  counters_ = previous.counters_;
  clusters_valid_ = false;
}

void TextAmcl::ReplaceParticles(const std::vector<Pose2D>& poses) {
  particles_.clear();
  const double w = poses.empty() ? 0.0 : 1.0 / poses.size();
  for (const Pose2D& p : poses) particles_.push_back({p, w});
  counted_.assign(particles_.size(), 1);
  recovery_.Reset();
  has_odom_ = false;  // the new pose holds at the next odometry reading, which becomes the reference
  pending_update_ = true;
  resample_counter_ = 0;
  state_ = LocalizationState::kTracking;
  lost_reason_ = LostReason::kNone;
  clusters_valid_ = false;
  UpdateHealth(true);
}

void TextAmcl::Initialize(const Pose2D& mean, const Eigen::Matrix3d& covariance) {
  if (!covariance.allFinite() || !covariance.isApprox(covariance.transpose(), 1e-9)) {
    throw std::invalid_argument("TextAmcl::Initialize: covariance: must be finite and symmetric");
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(covariance);
  if (eig.eigenvalues().minCoeff() < -1e-9) {
    throw std::invalid_argument("TextAmcl::Initialize: covariance: must be positive semi-definite");
  }
  const Eigen::Matrix3d transform =
      eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  awaiting_plate_ = false;
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Pose2D> poses(options_.max_particles);
  for (Pose2D& p : poses) {
    const Eigen::Vector3d d = transform * Eigen::Vector3d(gauss(rng_), gauss(rng_), gauss(rng_));
    p = {mean.x_m + d.x(), mean.y_m + d.y(), NormalizeAngle(mean.theta_rad + d.z())};
  }
  ReplaceParticles(poses);
}

void TextAmcl::GlobalLocalization() {
  awaiting_plate_ = options_.converge_after_plate && models_.text != nullptr;
  std::vector<Pose2D> poses(options_.max_particles);
  for (Pose2D& p : poses) p = models_.grid->SampleFreePose(rng_);
  ReplaceParticles(poses);
}

bool TextAmcl::UpdateOdometry(const Pose2D& odom_pose) {
  if (!has_odom_) {
    last_odom_ = odom_pose;
    has_odom_ = true;
    return false;
  }
  const double moved = std::hypot(odom_pose.x_m - last_odom_.x_m, odom_pose.y_m - last_odom_.y_m);
  const double turned = std::fabs(NormalizeAngle(odom_pose.theta_rad - last_odom_.theta_rad));
  if (moved < options_.update_min_d_m && turned < options_.update_min_a_rad && !force_update_) return false;
  models_.motion->Predict(last_odom_, odom_pose, &particles_, rng_);
  last_odom_ = odom_pose;
  pending_update_ = true;
  clusters_valid_ = false;
  return true;
}

bool TextAmcl::UpdateLaser(const LaserScan& scan) {
  const std::string error = ValidateLocalizationScan(scan);
  if (!error.empty()) throw std::invalid_argument(error);
  if (particles_.empty() || !(pending_update_ || force_update_)) return false;
  pending_update_ = force_update_ = false;
  models_.laser->LogLikelihoods(scan, particles_, &log_likelihoods_);
  recovery_.Update(LogMeanLikelihood(log_likelihoods_, particles_, &counted_));
  ApplyLogLikelihoods(log_likelihoods_, &particles_);
  ++counters_.laser_updates;
  clusters_valid_ = false;
  if (recovery_.initialized() && recovery_.FastToSlowRatio() < options_.lost_likelihood_ratio &&
      state_ != LocalizationState::kLost) {
    state_ = LocalizationState::kLost;
    lost_reason_ = LostReason::kLikelihoodCollapse;
  }
  if (++resample_counter_ % options_.resample_interval == 0) Resample();
  return true;
}

const ClusterResult& TextAmcl::Clusters() const {
  if (!clusters_valid_) {
    clusters_ = ClusterParticles(particles_, options_.histogram_bin);
    clusters_valid_ = true;
  }
  return clusters_;
}

PoseEstimate TextAmcl::Estimate() const {
  const ClusterResult& c = Clusters();
  if (c.clusters.empty()) throw std::logic_error("TextAmcl::Estimate: not initialized (no particles)");
  const PoseCluster& best = c.clusters.front();
  PoseEstimate estimate;
  estimate.pose = best.mean;
  estimate.covariance = SetStatistics(particles_).covariance;  // amcl's amcl_pose covariance
  estimate.cluster_covariance = best.covariance;
  estimate.cluster_weight = best.weight;
  estimate.cluster_count = static_cast<int>(c.clusters.size());
  return estimate;
}

TextAmclStatus TextAmcl::Status() const {
  TextAmclStatus s = counters_;
  s.state = state_;
  s.lost_reason = lost_reason_;
  s.particle_count = static_cast<int>(particles_.size());
  s.w_fast_over_w_slow = recovery_.FastToSlowRatio();
  const ClusterResult& c = Clusters();
  if (!c.clusters.empty()) {
    const PoseCluster& best = c.clusters.front();
    s.best_cluster_weight = best.weight;
    s.position_stddev_m = PositionStddev(best);
    s.heading_stddev_rad = HeadingStddev(best);
  }
  return s;
}

}  // namespace doorplate_localization

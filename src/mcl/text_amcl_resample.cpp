// TextAmcl's resampling (KLD-sampling with Augmented MCL's random particles) and health state.
#include <algorithm>
#include <cmath>

#include "doorplate_localization/mcl/text_amcl.h"

namespace doorplate_localization {

void TextAmcl::Resample() {
  if (particles_.empty()) return;
  NormalizeWeights(&particles_);
  const double random_probability = recovery_.RandomParticleProbability(options_.lost_likelihood_ratio);
  // KLD-sampling decides how many particles the next generation needs: draw samples one at a time
  // (random poses with Augmented MCL's probability, else from the weighted set) until their histogram
  // bins satisfy Fox's bound. The random poses are kept; the rest are then chosen by the Resampler
  // (low-variance by default), which Fox's sequential draw cannot use directly.
  std::vector<double> cumulative(particles_.size());
  double total = 0.0;
  for (size_t i = 0; i < particles_.size(); ++i) cumulative[i] = total += particles_[i].weight;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Pose2D> random_poses;
  kld_.Reset();
  while (!kld_.Enough()) {
    if (random_probability > 0.0 && unit(rng_) < random_probability) {
      random_poses.push_back(models_.grid->SampleFreePose(rng_));
      kld_.Add(random_poses.back());
    } else {
      const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), unit(rng_) * total);
      const size_t i = std::min<size_t>(it - cumulative.begin(), particles_.size() - 1);
      kld_.Add(particles_[i].pose);
    }
  }
  const int count = kld_.samples();
  const std::vector<int> selected =
      models_.resampler->Select(particles_, count - static_cast<int>(random_poses.size()), rng_);
  std::vector<Particle> next;
  next.reserve(count);
  const double w = 1.0 / count;
  for (int i : selected) next.push_back({particles_[i].pose, w});
  for (const Pose2D& p : random_poses) next.push_back({p, w});
  particles_.swap(next);
  counted_.assign(particles_.size(), 1);
  std::fill(counted_.end() - random_poses.size(), counted_.end(), 0);
  clusters_valid_ = false;

  ++counters_.resamples;
  counters_.last_random_particles = static_cast<int>(random_poses.size());
  counters_.total_random_particles += static_cast<int>(random_poses.size());
  if (!random_poses.empty() && options_.recovery_reset_after_injection) recovery_.Reset();
  UpdateHealth(true);
}

bool TextAmcl::Converged(const PoseCluster& best) const {
  return best.weight > options_.converged_cluster_weight && PositionStddev(best) < options_.converged_stddev_m &&
         HeadingStddev(best) < options_.converged_heading_stddev_rad;
}

void TextAmcl::UpdateHealth(bool after_resample) {
  const ClusterResult& c = Clusters();
  const bool converged = !awaiting_plate_ && !c.clusters.empty() && Converged(c.clusters.front());
  if (state_ == LocalizationState::kLost) {
    const bool likelihood_ok = recovery_.FastToSlowRatio() >= options_.lost_likelihood_ratio;
    if (!(after_resample && converged && likelihood_ok)) return;
    lost_reason_ = LostReason::kNone;
  }
  state_ = converged ? LocalizationState::kConverged : LocalizationState::kTracking;
}

}  // namespace doorplate_localization

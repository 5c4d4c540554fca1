// TextAmcl's doorplate update: reweighting, kidnap detection and reseeding at the read plates.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "doorplate_localization/mcl/text_amcl.h"

namespace doorplate_localization {

int TextAmcl::ReseedFromPlate(const PlateReading& reading, std::vector<double>* log_likelihoods) {
  const int wanted = static_cast<int>(std::lround(options_.text_reseed_fraction * particles_.size()));
  if (!models_.plate_sampler || wanted <= 0) return 0;
  const std::vector<Pose2D> poses = models_.plate_sampler->Sample(reading, wanted, rng_);
  if (poses.empty()) return 0;
  // Replace the particles that explain the reading least (ties: lowest index first).
  std::vector<int> order(particles_.size());
  std::iota(order.begin(), order.end(), 0);
  std::partial_sort(order.begin(), order.begin() + poses.size(), order.end(), [&](int a, int b) {
    const double la = (*log_likelihoods)[a], lb = (*log_likelihoods)[b];
    return la < lb || (la == lb && a < b);
  });
  std::vector<Particle> seeds;
  const double mean_weight = 1.0 / particles_.size();  // weights are normalized
  for (const Pose2D& p : poses) seeds.push_back({p, mean_weight});
  std::vector<double> seed_log_likelihoods;
  models_.text->LogLikelihoods(reading, seeds, &seed_log_likelihoods);
  for (size_t k = 0; k < seeds.size(); ++k) {
    particles_[order[k]] = seeds[k];
    counted_[order[k]] = 1;
    (*log_likelihoods)[order[k]] = seed_log_likelihoods[k];
  }
  return static_cast<int>(seeds.size());
}

PlateUpdateResult TextAmcl::UpdatePlate(const PlateReading& reading) {
  const std::string error = ValidatePlateReading(reading);
  if (!error.empty()) throw std::invalid_argument(error);
  PlateUpdateResult result;
  if (!models_.text) {
    result.ignored_reason = "no text observation model";
    return result;
  }
  if (particles_.empty()) {
    result.ignored_reason = "not initialized";
    return result;
  }
  if (reading.confidence < options_.text_min_confidence) {
    result.ignored_reason = "confidence " + std::to_string(reading.confidence) + " below text_min_confidence " +
                            std::to_string(options_.text_min_confidence);
    return result;
  }
  NormalizeWeights(&particles_);
  std::vector<double> ll;
  models_.text->LogLikelihoods(reading, particles_, &ll);
  const double unexplained = models_.text->UnexplainedLogLikelihood(reading);
  // How well the whole set, and the heaviest cluster alone, explain the reading.
  const ClusterResult& clusters = Clusters();
  double explained = 0.0, best_explained = 0.0, best_weight = 0.0;
  for (size_t i = 0; i < particles_.size(); ++i) {
    const double ratio = particles_[i].weight * std::exp(ll[i] - unexplained);
    explained += ratio;
    if (clusters.particle_cluster[i] == 0) {
      best_explained += ratio;
      best_weight += particles_[i].weight;
    }
  }
  result.explained_ratio = explained;
  result.best_cluster_explained_ratio = best_weight > 0.0 ? best_explained / best_weight : 0.0;
  const bool converged = state_ == LocalizationState::kConverged;
  result.contradicted_estimate = converged && result.best_cluster_explained_ratio < options_.text_explained_ratio;
  if (!converged || result.contradicted_estimate) result.reseeded_particles = ReseedFromPlate(reading, &ll);

  ApplyLogLikelihoods(ll, &particles_);
  clusters_valid_ = false;
  result.used = true;
  awaiting_plate_ = false;
  ++counters_.plate_updates;
  counters_.total_reseeded_particles += result.reseeded_particles;
  if (result.contradicted_estimate) {
    ++counters_.plate_contradictions;
    state_ = LocalizationState::kLost;
    lost_reason_ = LostReason::kPlateContradiction;
  } else {
    UpdateHealth(false);
  }
  return result;
}

}  // namespace doorplate_localization

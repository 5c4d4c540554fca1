#include "doorplate_localization/mcl/particle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace doorplate_localization {

double NormalizeWeights(std::vector<Particle>* particles) {
  if (particles->empty()) return 0.0;
  double total = 0.0;
  for (const Particle& p : *particles) total += p.weight;
  if (!(total > 0.0) || !std::isfinite(total)) {
    const double uniform = 1.0 / particles->size();
    for (Particle& p : *particles) p.weight = uniform;
    return 0.0;
  }
  for (Particle& p : *particles) p.weight /= total;
  return total;
}

double EffectiveSampleSize(const std::vector<Particle>& particles) {
  double sum = 0.0, sum_sq = 0.0;
  for (const Particle& p : particles) {
    sum += p.weight;
    sum_sq += p.weight * p.weight;
  }
  return sum_sq > 0.0 ? sum * sum / sum_sq : 0.0;
}

double ApplyLogLikelihoods(const std::vector<double>& log_likelihoods, std::vector<Particle>* particles) {
  if (log_likelihoods.size() != particles->size()) {
    throw std::invalid_argument("ApplyLogLikelihoods: " + std::to_string(log_likelihoods.size()) +
                                " log-likelihoods for " + std::to_string(particles->size()) + " particles");
  }
  if (particles->empty()) return -std::numeric_limits<double>::infinity();
  double prior_total = 0.0;
  for (const Particle& p : *particles) prior_total += p.weight;
  if (!(prior_total > 0.0) || !std::isfinite(prior_total)) {
    NormalizeWeights(particles);  // degenerate prior: start from uniform weights
    prior_total = 1.0;
  }
  double max_ll = -std::numeric_limits<double>::infinity();
  for (double ll : log_likelihoods) {
    if (!std::isnan(ll)) max_ll = std::max(max_ll, ll);
  }
  // No particle explains the measurement at all (or a model returned +inf): keep the weights.
  if (!std::isfinite(max_ll)) return -std::numeric_limits<double>::infinity();
  double scaled_total = 0.0;
  for (size_t i = 0; i < particles->size(); ++i) {
    const double ll = log_likelihoods[i];
    Particle& p = (*particles)[i];
    p.weight *= std::isnan(ll) ? 0.0 : std::exp(ll - max_ll);
    scaled_total += p.weight;
  }
  NormalizeWeights(particles);
  return max_ll + std::log(scaled_total / prior_total);
}

double LogMeanLikelihood(const std::vector<double>& log_likelihoods, const std::vector<Particle>& particles,
                         const std::vector<char>* counted) {
  const size_t n = std::min(log_likelihoods.size(), particles.size());
  bool any = false;
  for (size_t i = 0; counted != nullptr && i < n && !any; ++i) any = (*counted)[i] != 0;
  const auto use = [&](size_t i) { return !any || (*counted)[i] != 0; };
  double max_ll = -std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < n; ++i) {
    if (use(i) && !std::isnan(log_likelihoods[i])) max_ll = std::max(max_ll, log_likelihoods[i]);
  }
  if (!std::isfinite(max_ll)) return -std::numeric_limits<double>::infinity();
  double weighted = 0.0, total = 0.0;
  for (size_t i = 0; i < n; ++i) {
    if (!use(i)) continue;
    const double w = particles[i].weight;
    total += w;
    if (!std::isnan(log_likelihoods[i])) weighted += w * std::exp(log_likelihoods[i] - max_ll);
  }
  if (!(total > 0.0)) return -std::numeric_limits<double>::infinity();
  return max_ll + std::log(weighted / total);
}

}  // namespace doorplate_localization

// Particles of the Monte Carlo localizer and the weight arithmetic shared by every update.
// Frame: a particle's pose is base_link in the map frame (metres, radians).
#pragma once

#include <vector>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

// One weighted hypothesis of the robot pose.
struct Particle {
  Pose2D pose;
  double weight = 0.0;  // normalized over the set after every update (sums to 1)
};

// Scales the weights to sum to 1. Returns the sum before scaling; when it is 0 or not finite the
// weights become uniform (1/N) and 0 is returned. No-op (returns 0) on an empty set.
double NormalizeWeights(std::vector<Particle>* particles);

// Kish's effective sample size 1 / Σ w² of normalized weights (N for uniform weights, 1 for one
// particle holding all the weight). 0 for an empty set.
double EffectiveSampleSize(const std::vector<Particle>& particles);

// Bayes update in the log domain: w_i ← w_i · exp(log_likelihoods[i]), then normalizes. Robust to
// likelihoods far below DBL_MIN (products of hundreds of beam probabilities): only differences of
// log-likelihoods matter for the new weights. Returns log( Σ w_i p_i / Σ w_i ) with the weights before
// the update, i.e. the log of the weighted mean likelihood — the measurement's evidence that Augmented
// MCL averages (Thrun et al., Probabilistic Robotics, table 8.3). Throws std::invalid_argument if the
// sizes differ; a NaN log-likelihood counts as -inf (the particle gets weight 0).
double ApplyLogLikelihoods(const std::vector<double>& log_likelihoods, std::vector<Particle>* particles);

// log( Σ w_i p_i / Σ w_i ) over the particles whose `counted` flag is non-zero (all particles when
// `counted` is null or flags none), with p_i = exp(log_likelihoods[i]), before any update. -inf if no
// counted particle has a finite log-likelihood.
double LogMeanLikelihood(const std::vector<double>& log_likelihoods, const std::vector<Particle>& particles,
                         const std::vector<char>* counted = nullptr);

}  // namespace doorplate_localization

// Resampling: which particles survive into the next generation, in proportion to their weights.
#pragma once

#include <random>
#include <vector>

#include "doorplate_localization/mcl/particle.h"

namespace doorplate_localization {

class Resampler {
 public:
  virtual ~Resampler() = default;

  // Indexes of `count` particles drawn with probability proportional to their weights (which need not
  // be normalized but must not all be 0: then every particle is equally likely). Empty if count <= 0
  // or there are no particles.
  virtual std::vector<int> Select(const std::vector<Particle>& particles, int count, std::mt19937_64& rng) const = 0;
};

// Low-variance (systematic) resampling (Thrun et al., Probabilistic Robotics, table 4.4): one random
// offset, then `count` evenly spaced pointers through the cumulative weights. Particle i is selected
// floor(count·w_i) or ceil(count·w_i) times — no sampling variance beyond that rounding. Indexes are
// returned in ascending order.
class LowVarianceResampler : public Resampler {
 public:
  std::vector<int> Select(const std::vector<Particle>& particles, int count, std::mt19937_64& rng) const override;
};

// Independent (multinomial) draws: amcl's sampler. Higher variance; kept for comparison and tests.
class MultinomialResampler : public Resampler {
 public:
  std::vector<int> Select(const std::vector<Particle>& particles, int count, std::mt19937_64& rng) const override;
};

}  // namespace doorplate_localization

// KLD-sampling (Fox, "Adapting the sample size in particle filters through KLD-sampling", IJRR 2003;
// Thrun et al., Probabilistic Robotics, table 8.4): the number of particles needed so that, with
// probability 1 - δ, the KL divergence between the particle approximation and the true posterior stays
// below kld_err, given that the samples occupy k bins of the pose histogram:
//   n = (k - 1) / (2 kld_err) · (1 - 2 / (9 (k - 1)) + sqrt(2 / (9 (k - 1))) · kld_z)³
// kld_z is the upper 1 - δ quantile of the standard normal, used as given — exactly as amcl uses its
// kld_z parameter, so amcl's default 0.99 means z = 0.99 (1 - δ ≈ 0.84), not "99 %"; set 2.326 for
// 1 - δ = 0.99. The count is clamped to [min_particles, max_particles]. With k <= 1 (every sample in one
// bin: a converged filter) the bound is 0 and min_particles is used — amcl returned max_particles
// there (ros-planning/navigation #1159).
#pragma once

#include <unordered_set>

#include "doorplate_localization/mcl/pose_histogram.h"

namespace doorplate_localization {

struct KldSamplerOptions {
  int min_particles = 100;
  int max_particles = 5000;
  double kld_err = 0.01;   // bound on the KL divergence (amcl's kld_err)
  double kld_z = 0.99;     // standard normal quantile z_{1-δ} (amcl's kld_z, see above)
  PoseBinSize bin_size;    // histogram bins (amcl: 0.5 m, 0.5 m, 10°)
};

class KldSampler {
 public:
  // Throws std::invalid_argument naming the field of a bad option (max_particles above
  // limits::kMaxParticles too, before anything is reserved).
  explicit KldSampler(const KldSamplerOptions& options);

  // Fox's bound for k occupied bins, unclamped and not rounded; 0 for k <= 1.
  static double FoxBound(int occupied_bins, double kld_err, double kld_z);
  // ceil(FoxBound) clamped to [min_particles, max_particles].
  int RequiredParticles(int occupied_bins) const;

  // Incremental use while drawing samples: Reset(), then Add() each new sample's pose; Enough() tells
  // when the samples drawn so far reach the bound for the bins they occupy (or max_particles).
  void Reset();
  void Add(const Pose2D& pose);
  bool Enough() const;
  int samples() const { return samples_; }
  int occupied_bins() const { return static_cast<int>(bins_.size()); }

  const KldSamplerOptions& options() const { return options_; }

 private:
  const KldSamplerOptions options_;
  std::unordered_set<std::uint64_t> bins_;
  int samples_ = 0;
};

}  // namespace doorplate_localization

#include "doorplate_localization/mcl/kld_sampler.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "doorplate_localization/common/limits.h"

namespace doorplate_localization {

KldSampler::KldSampler(const KldSamplerOptions& options) : options_(options) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("KldSampler: " + what); };
  if (options.min_particles < 1) fail("min_particles: must be >= 1, got " + std::to_string(options.min_particles));
  if (options.max_particles < options.min_particles) {
    fail("max_particles: must be >= min_particles (" + std::to_string(options.min_particles) + "), got " +
         std::to_string(options.max_particles));
  }
  if (options.max_particles > limits::kMaxParticles) {  // before reserving for them
    fail("max_particles: must be <= " + std::to_string(limits::kMaxParticles) + " (limits::kMaxParticles), got " +
         std::to_string(options.max_particles));
  }
  if (!(options.kld_err > 0.0 && std::isfinite(options.kld_err))) {
    fail("kld_err: must be > 0, got " + std::to_string(options.kld_err));
  }
  if (!(options.kld_z > 0.0 && std::isfinite(options.kld_z))) {
    fail("kld_z: must be > 0, got " + std::to_string(options.kld_z));
  }
  if (!(options.bin_size.xy_m > 0.0) || !(options.bin_size.theta_rad > 0.0)) {
    fail("bin_size: xy_m and theta_rad must be > 0");
  }
  bins_.reserve(static_cast<size_t>(options.max_particles));
}

double KldSampler::FoxBound(int occupied_bins, double kld_err, double kld_z) {
  if (occupied_bins <= 1) return 0.0;
  const double k1 = occupied_bins - 1.0;
  const double b = 2.0 / (9.0 * k1);
  const double x = 1.0 - b + std::sqrt(b) * kld_z;
  return k1 / (2.0 * kld_err) * x * x * x;
}

int KldSampler::RequiredParticles(int occupied_bins) const {
  const double n = std::ceil(FoxBound(occupied_bins, options_.kld_err, options_.kld_z));
  return static_cast<int>(std::clamp<double>(n, options_.min_particles, options_.max_particles));
}

void KldSampler::Reset() {
  bins_.clear();
  samples_ = 0;
}

void KldSampler::Add(const Pose2D& pose) {
  bins_.insert(BinKey(BinOf(pose, options_.bin_size)));
  ++samples_;
}

bool KldSampler::Enough() const {
  return samples_ >= options_.max_particles || samples_ >= RequiredParticles(occupied_bins());
}

}  // namespace doorplate_localization

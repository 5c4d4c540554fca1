#include "doorplate_localization/mcl/augmented_mcl.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

// log((1 - a) e^x + a e^y) for a in [0, 1], without leaving the log domain.
double LogBlend(double x, double y, double a) {
  if (a <= 0.0) return x;
  if (a >= 1.0) return y;
  const double u = std::log1p(-a) + x, v = std::log(a) + y;
  const double m = std::max(u, v);
  return m + std::log(std::exp(u - m) + std::exp(v - m));
}

}  // namespace

AugmentedMclAverages::AugmentedMclAverages(double alpha_slow, double alpha_fast)
    : alpha_slow_(alpha_slow), alpha_fast_(alpha_fast) {
  if (!(alpha_slow >= 0.0 && alpha_slow <= alpha_fast && alpha_fast <= 1.0)) {
    throw std::invalid_argument("AugmentedMclAverages: recovery_alpha_slow/recovery_alpha_fast: need 0 <= slow (" +
                                std::to_string(alpha_slow) + ") <= fast (" + std::to_string(alpha_fast) + ") <= 1");
  }
}

void AugmentedMclAverages::Update(double log_w_avg) {
  if (!std::isfinite(log_w_avg)) return;
  if (!initialized_) {
    log_w_slow_ = log_w_fast_ = log_w_avg;
    initialized_ = true;
    return;
  }
  log_w_slow_ = LogBlend(log_w_slow_, log_w_avg, alpha_slow_);
  log_w_fast_ = LogBlend(log_w_fast_, log_w_avg, alpha_fast_);
}

void AugmentedMclAverages::TakeAveragesFrom(const AugmentedMclAverages& other) {
  initialized_ = other.initialized_;
  log_w_slow_ = other.log_w_slow_;
  log_w_fast_ = other.log_w_fast_;
}

void AugmentedMclAverages::Reset() {
  initialized_ = false;
  log_w_slow_ = log_w_fast_ = 0.0;
}

double AugmentedMclAverages::FastToSlowRatio() const {
  return initialized_ ? std::exp(log_w_fast_ - log_w_slow_) : 1.0;
}

double AugmentedMclAverages::RandomParticleProbability(double onset_ratio) const {
  return std::max(0.0, 1.0 - FastToSlowRatio() / onset_ratio);
}

}  // namespace doorplate_localization

// Augmented MCL's recovery from failures (Thrun et al., Probabilistic Robotics, table 8.3; amcl's
// recovery_alpha_slow/fast): a short- and a long-term average of the measurement likelihood,
//   w_slow += α_slow (w_avg - w_slow),  w_fast += α_fast (w_avg - w_fast),
// and during resampling each particle is replaced by a random pose with probability
// max(0, 1 - w_fast / w_slow): when recent measurements fit much worse than usual, the robot is
// probably lost. An onset ratio r < 1 makes injection start only below it,
// max(0, 1 - (w_fast / w_slow) / r), so the ordinary dip of a tight initial cloud spreading out (ratio
// ~0.8) does not inject. Kept as logarithms so averages of products of hundreds of beam probabilities
// never underflow. The first measurement initializes both averages (amcl does the same).
#pragma once

namespace doorplate_localization {

class AugmentedMclAverages {
 public:
  // Throws std::invalid_argument unless 0 <= alpha_slow <= alpha_fast <= 1 (alpha 0 = that average never
  // moves; both 0 disables injection).
  AugmentedMclAverages(double alpha_slow, double alpha_fast);

  // Folds in one measurement's log mean likelihood (log w_avg). Non-finite values are ignored.
  void Update(double log_w_avg);
  // Forgets both averages (after (re)initialization; amcl also does this after every injection).
  void Reset();
  // Takes `other`'s averages (and whether it has any), keeping this one's alphas: a filter reconfigured with
  // new alphas goes on from where the old one was.
  void TakeAveragesFrom(const AugmentedMclAverages& other);

  bool initialized() const { return initialized_; }
  // w_fast / w_slow; 1 before the first measurement.
  double FastToSlowRatio() const;
  // max(0, 1 - (w_fast / w_slow) / onset_ratio): the share of random particles to inject when
  // resampling; onset_ratio 1 is the book's rule. Requires onset_ratio > 0.
  double RandomParticleProbability(double onset_ratio = 1.0) const;
  double log_w_slow() const { return log_w_slow_; }
  double log_w_fast() const { return log_w_fast_; }

 private:
  const double alpha_slow_;
  const double alpha_fast_;
  bool initialized_ = false;
  double log_w_slow_ = 0.0;
  double log_w_fast_ = 0.0;
};

}  // namespace doorplate_localization

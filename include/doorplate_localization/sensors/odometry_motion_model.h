// The odometry motion model of both filters (Thrun et al., Probabilistic Robotics, table 5.6): the
// motion between two odometry poses is a first rotation toward the direction of travel (rot1), a
// translation (trans) and a second rotation (rot2), each disturbed by zero-mean Gaussian noise that
// grows with the rotations and the translation. The localizer samples the three components (amcl's
// sample_motion_model_odometry); the mapper uses one isotropic spread of the end pose as its scan
// matcher's search window and prior. They differ in how noise grows (the noise law) and in two rules,
// all options of this one model:
//
//   law             rotation noise of rot_i           translation noise
//   kDiffCorrected  σ² = a_rr·rot_i² + a_rt·trans²    σ² = a_tt·trans² + a_tr·(rot1² + rot2²)  (book)
//   kDiff           σ  = a_rr·rot_i² + a_rt·trans²    σ  = a_tt·trans² + a_tr·(rot1² + rot2²)  (amcl "diff")
//   kLinear         σ  = a_rr·|rot_i| + a_rt·trans    σ  = a_tt·trans + a_tr·(|rot1| + |rot2|) (gmapping)
//
// Poses are base_link in the odom frame; metres and radians.
#pragma once

#include <random>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

enum class OdometryNoiseLaw {
  // amcl's "diff-corrected" (nav2's DifferentialMotionModel): the book's variances.
  kDiffCorrected,
  // amcl's "diff": the variance term used as the standard deviation (the unit-mixing bug of
  // ros-planning/navigation #20, kept for configurations tuned against it).
  kDiff,
  // Standard deviations proportional to the motion (gmapping's srr/srt/str/stt): the mapper's.
  kLinear,
};

// How the noise treats a move shorter than min_translation_for_heading_m (no first rotation is
// computed for it: rot1 = 0, rot2 = the whole turn).
enum class ShortMoveRule {
  // A turn in place: the rotations' noise is that of rot1 = 0 and rot2 (amcl).
  kTurnInPlace,
  // The direction of travel is lost in the wheel noise, and so is how the turn split into rot1 and
  // rot2: the noise takes rot1 as a quarter turn and rot2 as a quarter turn plus the turn (mapper).
  kDirectionUnknown,
};

struct OdometryMotionModelOptions {
  OdometryNoiseLaw noise_law = OdometryNoiseLaw::kDiffCorrected;
  // Noise coefficients (amcl's odom_alpha1..4, gmapping's stt, str, srr, srt). Units follow the law:
  // for kDiffCorrected rad²/rad², rad²/m², m²/m², m²/rad²; for kLinear rad/rad, rad/m, m/m, m/rad.
  double rot_noise_from_rot = 0.2;      // alpha1, stt: rotation noise from the rotations
  double rot_noise_from_trans = 0.2;    // alpha2, str: rotation noise from the translation
  double trans_noise_from_trans = 0.2;  // alpha3, srr: translation noise from the translation
  double trans_noise_from_rot = 0.2;    // alpha4, srt: translation noise from the rotations
  // Below this translation the travel direction is undefined: rot1 = 0 (see ShortMoveRule).
  double min_translation_for_heading_m = 0.01;
  ShortMoveRule short_move_rule = ShortMoveRule::kTurnInPlace;
  // A rotation of about a half turn counts as that much less for the noise: a robot reversing
  // straight back (rot1 = rot2 = pi) is no noisier than one driving forward (amcl). When false,
  // reversing is a half turn each way and much noisier.
  bool reverse_is_forward = true;
};

// The options the mapper uses by default (gmapping-like linear standard deviations).
OdometryMotionModelOptions MapperOdometryDefaults();

// One motion split into its components, or the standard deviations of their noise.
struct OdometryStep {
  double rot1_rad = 0.0;
  double trans_m = 0.0;
  double rot2_rad = 0.0;
};

// Isotropic standard deviations of one motion's end pose.
struct StepSpread {
  double linear_m = 0.0;     // position: along the move and across it (the larger of the two)
  double angular_rad = 0.0;  // heading
};

// Noisy copies of one motion for many start poses (the localizer's particles): each start pose
// (any frame) moves by rot1, trans, rot2, each disturbed by its standard deviation. The draws (rot1,
// trans, rot2 per pose) come from one Gaussian stream over all poses.
class OdometryStepSampler {
 public:
  OdometryStepSampler(const OdometryStep& motion, const OdometryStep& stddev) : motion_(motion), stddev_(stddev) {}
  Pose2D Sample(const Pose2D& from, std::mt19937_64& rng);

 private:
  const OdometryStep motion_, stddev_;
  std::normal_distribution<double> unit_{0.0, 1.0};
};

class OdometryMotionModel {
 public:
  // Throws std::invalid_argument naming a negative or non-finite coefficient or threshold.
  explicit OdometryMotionModel(const OdometryMotionModelOptions& options);

  // The motion from `before` to `after` as (rot1, trans, rot2), without noise; rot1 = 0 below
  // min_translation_for_heading_m.
  OdometryStep Decompose(const Pose2D& before, const Pose2D& after) const;
  // Standard deviations of the noise on rot1, trans and rot2 of `motion` under the noise law.
  OdometryStep NoiseStddev(const OdometryStep& motion) const;
  // Isotropic spread of the motion from `before` to `after` (from NoiseStddev: position from the
  // translation noise and the first rotation's noise at the travelled distance, heading from both
  // rotations' noise).
  StepSpread Spread(const Pose2D& before, const Pose2D& after) const;
  // Spread of two motions in a row (variances add).
  static StepSpread Accumulate(const StepSpread& a, const StepSpread& b);
  // `from` moved by `delta` (the end pose in the start pose's frame), plus Gaussian noise of
  // `spread` on x, y and heading of the result (rng draws: x, y, heading).
  static Pose2D SampleIsotropic(const Pose2D& from, const Pose2D& delta, const StepSpread& spread,
                                std::mt19937_64& rng);

 private:
  const OdometryMotionModelOptions options_;
};

}  // namespace doorplate_localization

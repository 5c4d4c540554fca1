// Odometry motion model of the particle filter (Thrun et al., Probabilistic Robotics, table 5.6): an
// odometry increment is a first rotation toward the direction of travel, a translation and a second
// rotation, each disturbed by Gaussian noise whose standard deviation grows with the rotations and
// the translation (AMCL's alpha1..4 roles, as standard deviations). Moving backwards or sideways
// means large rotations, hence a large heading uncertainty, as real wheel odometry has.
#pragma once

#include <random>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct MotionModelOptions {
  double rot_stddev_rad_per_rad = 0.1;    // alpha1: rotation noise per radian turned
  double rot_stddev_rad_per_m = 0.05;     // alpha2: rotation noise per metre driven
  double trans_stddev_m_per_m = 0.1;      // alpha3: translation noise per metre driven
  double trans_stddev_m_per_rad = 0.05;   // alpha4: translation noise per radian turned
  double min_translation_m = 0.05;        // shorter moves: direction unknown (see motion_model.cpp)
};

// Isotropic standard deviations of one odometry step's end pose.
struct StepSpread {
  double linear_m = 0.0;    // position: along the move and across it (the larger of the two)
  double angular_rad = 0.0; // heading
};

class OdometryMotionModel {
 public:
  explicit OdometryMotionModel(const MotionModelOptions& options);

  // Spread of one odometry increment `odometry_delta` (the end pose in the start pose's frame).
  StepSpread Spread(const Pose2D& odometry_delta) const;
  // Spread of two increments in a row (variances add).
  static StepSpread Accumulate(const StepSpread& a, const StepSpread& b);
  // `from` moved by `odometry_delta`, plus Gaussian noise of `spread` (position and heading, map
  // frame) drawn from `rng`.
  static Pose2D Sample(const Pose2D& from, const Pose2D& odometry_delta, const StepSpread& spread,
                       std::mt19937_64& rng);

 private:
  const MotionModelOptions options_;
};

}  // namespace doorplate_localization

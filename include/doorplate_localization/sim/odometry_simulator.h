// Wheel odometry with random and systematic error, integrated from the true motion.
#pragma once

#include <random>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/sim/sensor_options.h"

namespace doorplate_localization {

class OdometrySimulator {
 public:
  // `start_odom_pose` is the odometry frame reading at the start (usually identity). Throws
  // std::invalid_argument naming the field for invalid slip options (negative scale_stddev, a
  // non-positive scale_correlation_length_m, |turn_rotation_error_rad_per_rad| >= 0.5).
  explicit OdometrySimulator(const OdometryNoiseOptions& options, Pose2D start_odom_pose = {});

  // Feeds one true motion step (from `true_before` to `true_after`, world frame) and returns the new
  // noisy odometry pose (base_link in odom). The step is decomposed into rot1, trans, rot2 (Thrun et
  // al., Probabilistic Robotics, table 5.6) and each part gets noise whose variance is proportional to
  // the motion, so the result does not depend on how finely the motion is stepped. With slip enabled
  // (OdometrySlipOptions) the translation is further scaled by the slowly varying scale error (advanced
  // over the true distance of the step, exactly, so also independent of the stepping) and grows by
  // turn_scale_error_m_per_rad × |rot1 + rot2|, and rot1, rot2 are scaled by 1 + turn_rotation_error.
  Pose2D Update(const Pose2D& true_before, const Pose2D& true_after, std::mt19937_64& rng);

  const Pose2D& pose() const { return odom_pose_; }
  // Distance the odometry believes it drove, metres (always >= 0).
  double odometer_m() const { return odometer_m_; }
  // The slowly varying part of the scale error at the current position (0 with slip off or before the
  // first step).
  double slip_scale_error() const { return slip_scale_error_; }

 private:
  const OdometryNoiseOptions options_;
  Pose2D odom_pose_;
  double odometer_m_ = 0.0;
  bool slip_started_ = false;       // the process's first value is drawn at the first step
  double slip_scale_error_ = 0.0;

  // Advances the Ornstein–Uhlenbeck scale error over `distance_m` of true travel.
  void AdvanceSlipScale(double distance_m, std::mt19937_64& rng);
};

}  // namespace doorplate_localization

// Wheel odometry with random and systematic error, integrated from the true motion.
#pragma once

#include <random>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/sim/sensor_options.h"

namespace doorplate_localization {

class OdometrySimulator {
 public:
  // `start_odom_pose` is the odometry frame reading at the start (usually identity).
  explicit OdometrySimulator(const OdometryNoiseOptions& options, Pose2D start_odom_pose = {});

  // Feeds one true motion step (from `true_before` to `true_after`, world frame) and returns the new
  // noisy odometry pose (base_link in odom). The step is decomposed into rot1, trans, rot2 (Thrun et
  // al., Probabilistic Robotics, table 5.6) and each part gets noise whose variance is proportional to
  // the motion, so the result does not depend on how finely the motion is stepped.
  Pose2D Update(const Pose2D& true_before, const Pose2D& true_after, std::mt19937_64& rng);

  const Pose2D& pose() const { return odom_pose_; }
  // Distance the odometry believes it drove, metres (always >= 0).
  double odometer_m() const { return odometer_m_; }

 private:
  const OdometryNoiseOptions options_;
  Pose2D odom_pose_;
  double odometer_m_ = 0.0;
};

}  // namespace doorplate_localization

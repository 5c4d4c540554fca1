// The motion (prediction) step of the localizer: one interface, swappable models (as nav2_amcl's
// MotionModel plugins and PRBonn/tmcl's MotionModel).
#pragma once

#include <random>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/mcl/particle.h"

namespace doorplate_localization {

class MotionModel {
 public:
  virtual ~MotionModel() = default;

  // Moves every particle (base_link in the map frame) by the motion the odometry measured between
  // `odom_before` and `odom_after` (base_link in the odom frame), each with its own sampled noise.
  // Weights are left untouched.
  virtual void Predict(const Pose2D& odom_before, const Pose2D& odom_after, std::vector<Particle>* particles,
                       std::mt19937_64& rng) const = 0;
};

}  // namespace doorplate_localization

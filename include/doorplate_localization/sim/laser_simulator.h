// Simulated 2D laser: casts every beam against the world's surfaces at the laser's mounting height.
#pragma once

#include <memory>
#include <random>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/sensors/laser_scan.h"
#include "doorplate_localization/sim/laser_error_model.h"
#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

class LaserSimulator {
 public:
  // The error model is the one options.error_model names (MakeLaserErrorModel); throws
  // std::invalid_argument naming the field of a bad model choice or parameter.
  explicit LaserSimulator(const LaserOptions& options);
  // Any other error model (options.error_model and its parameters are then ignored).
  LaserSimulator(const LaserOptions& options, std::shared_ptr<const LaserErrorModel> error_model);

  // Noise-free distance along every beam from the laser at `robot_pose` (base_link in world);
  // +inf where nothing is hit within max_range_m. The scan's laser_pose is the mounting pose (MountPose),
  // its max_range_m the device's. If `incidence_rad` is given it receives, per beam, the
  // angle between the beam and the normal of the surface it hits, in [0, pi/2] (0: head-on), NaN where
  // the beam hits nothing within max_range_m.
  LaserScan CastExact(const World& world, const Pose2D& robot_pose,
                          std::vector<float>* incidence_rad = nullptr) const;
  // CastExact with the error model's noise, dropouts, ... drawn from `rng`.
  LaserScan Simulate(const World& world, const Pose2D& robot_pose, std::mt19937_64& rng) const;

  const LaserOptions& options() const { return options_; }
  const LaserErrorModel& error_model() const { return *error_model_; }
  // Laser frame pose in base_link.
  Pose2D MountPose() const;

 private:
  const LaserOptions options_;
  std::shared_ptr<const LaserErrorModel> error_model_;
};

}  // namespace doorplate_localization

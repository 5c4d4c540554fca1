// Simulated 2D laser: casts every beam against the world's surfaces at the laser's mounting height.
#pragma once

#include <random>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

// One scan in the laser frame, REP-117: a beam with no echo within max_range_m is +inf.
struct SimulatedScan {
  double angle_min_rad = 0.0;
  double angle_increment_rad = 0.0;
  double min_range_m = 0.0;
  double max_range_m = 0.0;
  std::vector<float> ranges_m;
};

class LaserSimulator {
 public:
  explicit LaserSimulator(const LaserOptions& options);

  // Noise-free distance along every beam from the laser at `robot_pose` (base_link in world);
  // +inf where nothing is hit within max_range_m.
  SimulatedScan CastExact(const World& world, const Pose2D& robot_pose) const;
  // CastExact plus range noise and dropouts drawn from `rng`.
  SimulatedScan Simulate(const World& world, const Pose2D& robot_pose, std::mt19937_64& rng) const;

  const LaserOptions& options() const { return options_; }
  // Laser frame pose in base_link.
  Pose2D MountPose() const;

 private:
  const LaserOptions options_;
};

}  // namespace doorplate_localization

#include "doorplate_localization/sim/laser_simulator.h"

#include <cmath>
#include <limits>

namespace doorplate_localization {

LaserSimulator::LaserSimulator(const LaserOptions& options) : options_(options) {}

Pose2D LaserSimulator::MountPose() const {
  return {options_.mount_x_m, options_.mount_y_m, options_.mount_yaw_rad};
}

SimulatedScan LaserSimulator::CastExact(const World& world, const Pose2D& robot_pose) const {
  SimulatedScan scan;
  scan.angle_min_rad = options_.angle_min_rad;
  scan.angle_increment_rad = 2.0 * M_PI / options_.num_beams;
  scan.min_range_m = options_.min_range_m;
  scan.max_range_m = options_.max_range_m;
  scan.ranges_m.assign(options_.num_beams, std::numeric_limits<float>::infinity());

  // Only surfaces that span the scan plane's height are seen.
  std::vector<const Segment*> visible;
  for (const Surface& s : world.surfaces) {
    if (s.z_min_m <= options_.mount_height_m && options_.mount_height_m <= s.z_max_m) visible.push_back(&s.segment);
  }
  const Pose2D laser = robot_pose.Compose(MountPose());
  for (int i = 0; i < options_.num_beams; ++i) {
    const double angle = laser.theta_rad + scan.angle_min_rad + i * scan.angle_increment_rad;
    const Vec2 dir{std::cos(angle), std::sin(angle)};
    double best = std::numeric_limits<double>::infinity();
    for (const Segment* seg : visible) {
      if (const auto t = RaySegmentDistance(laser.Position(), dir, *seg); t && *t < best) best = *t;
    }
    if (best < options_.min_range_m) {
      scan.ranges_m[i] = -std::numeric_limits<float>::infinity();  // REP-117: too close to measure
    } else if (best <= options_.max_range_m) {
      scan.ranges_m[i] = static_cast<float>(best);
    }
  }
  return scan;
}

SimulatedScan LaserSimulator::Simulate(const World& world, const Pose2D& robot_pose, std::mt19937_64& rng) const {
  SimulatedScan scan = CastExact(world, robot_pose);
  std::normal_distribution<double> noise(0.0, options_.range_noise_stddev_m);
  std::bernoulli_distribution dropout(options_.dropout_probability);
  for (float& r : scan.ranges_m) {
    // Draw both for every beam so the random stream does not depend on the geometry.
    const double n = noise(rng);
    const bool lost = dropout(rng);
    if (!std::isfinite(r)) continue;
    if (lost) {
      r = std::numeric_limits<float>::infinity();
      continue;
    }
    const double noisy = r + n;
    r = noisy > options_.max_range_m ? std::numeric_limits<float>::infinity()
                                     : static_cast<float>(std::max(noisy, options_.min_range_m));
  }
  return scan;
}

}  // namespace doorplate_localization

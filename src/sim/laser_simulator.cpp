#include "doorplate_localization/sim/laser_simulator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace doorplate_localization {
namespace {

// Angle between a beam (unit `dir`) and the normal of the segment it hits, in [0, pi/2].
float IncidenceAngle(Vec2 dir, const Segment& s) {
  const Vec2 along = s.b - s.a;
  const double length = Norm(along);
  if (length <= 0.0) return 0.0f;
  const double cos_incidence = std::fabs(dir.x * along.y - dir.y * along.x) / length;  // |dir . normal|
  return static_cast<float>(std::acos(std::min(1.0, cos_incidence)));
}

}  // namespace

LaserSimulator::LaserSimulator(const LaserOptions& options)
    : LaserSimulator(options, MakeLaserErrorModel(options)) {}

LaserSimulator::LaserSimulator(const LaserOptions& options, std::shared_ptr<const LaserErrorModel> error_model)
    : options_(options), error_model_(std::move(error_model)) {
  if (!error_model_) throw std::invalid_argument("LaserSimulator: error_model must not be null");
}

Pose2D LaserSimulator::MountPose() const {
  return {options_.mount_x_m, options_.mount_y_m, options_.mount_yaw_rad};
}

LaserScan LaserSimulator::CastExact(const World& world, const Pose2D& robot_pose,
                                        std::vector<float>* incidence_rad) const {
  LaserScan scan;
  scan.angle_min_rad = options_.angle_min_rad;
  scan.angle_increment_rad = 2.0 * M_PI / options_.num_beams;
  scan.min_range_m = options_.min_range_m;
  scan.max_range_m = options_.max_range_m;
  scan.laser_pose = MountPose();
  scan.ranges_m.assign(options_.num_beams, std::numeric_limits<float>::infinity());
  if (incidence_rad) incidence_rad->assign(options_.num_beams, std::numeric_limits<float>::quiet_NaN());

  // Only surfaces that span the scan plane's height are seen; glass (reflect probability < 1) returns a
  // beam only when GlassReturnsBeam says so, otherwise the beam passes through.
  std::vector<const Segment*> visible;
  std::vector<const Surface*> glass;
  for (const Surface& s : world.surfaces) {
    if (!(s.z_min_m <= options_.mount_height_m && options_.mount_height_m <= s.z_max_m)) continue;
    if (s.laser_reflect_probability < 1.0) glass.push_back(&s); else visible.push_back(&s.segment);
  }
  const Pose2D laser = robot_pose.Compose(MountPose());
  for (int i = 0; i < options_.num_beams; ++i) {
    const double angle = laser.theta_rad + scan.angle_min_rad + i * scan.angle_increment_rad;
    const Vec2 dir{std::cos(angle), std::sin(angle)};
    double best = std::numeric_limits<double>::infinity();
    const Segment* hit = nullptr;
    for (const Segment* seg : visible) {
      if (const auto t = RaySegmentDistance(laser.Position(), dir, *seg); t && *t < best) best = *t, hit = seg;
    }
    for (const Surface* g : glass) {
      const auto t = RaySegmentDistance(laser.Position(), dir, g->segment);
      if (t && *t < best && GlassReturnsBeam(*g, laser.Position(), angle)) best = *t, hit = &g->segment;
    }
    if (incidence_rad && hit && best <= options_.max_range_m) (*incidence_rad)[i] = IncidenceAngle(dir, *hit);
    if (best < options_.min_range_m) {
      scan.ranges_m[i] = -std::numeric_limits<float>::infinity();  // REP-117: too close to measure
    } else if (best <= options_.max_range_m) {
      scan.ranges_m[i] = static_cast<float>(best);
    }
  }
  return scan;
}

LaserScan LaserSimulator::Simulate(const World& world, const Pose2D& robot_pose, std::mt19937_64& rng) const {
  std::vector<float> incidence;
  LaserScan scan = CastExact(world, robot_pose, error_model_->NeedsIncidence() ? &incidence : nullptr);
  // 360° device: the last beam's neighbour is the first.
  error_model_->Apply(&scan.ranges_m, incidence, scan.min_range_m, scan.max_range_m, true, rng);
  return scan;
}

}  // namespace doorplate_localization

#include "doorplate_localization/sim/simulator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "doorplate_localization/sim/people.h"

namespace doorplate_localization {
namespace {

// Separate random streams per sensor, so that e.g. rendering images on demand never changes the odometry.
std::mt19937_64 Stream(std::uint64_t seed, std::uint64_t stream) {
  std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                    static_cast<std::uint32_t>(stream)};
  return std::mt19937_64(seq);
}

constexpr double kBumperHeightM = 0.3;  // surfaces lower than this stop the robot

}  // namespace

Simulator::Simulator(World world, const SimulatorOptions& options)
    : world_(std::move(world)),
      options_(options),
      odom_rng_(Stream(options.seed, 1)),
      laser_rng_(Stream(options.seed, 2)),
      camera_rng_(Stream(options.seed, 3)),
      laser_(world_.sensors.laser),
      odometry_(world_.sensors.odometry),
      true_pose_(world_.start_pose) {
  if (world_.surfaces.empty()) BuildSurfaces(world_);
  PlacePeople(world_, time_s_);
  camera_ = std::make_unique<CameraRenderer>(world_, world_.sensors.camera);
}

void Simulator::SetCommand(double linear_mps, double angular_rps) {
  if (!std::isfinite(linear_mps) || !std::isfinite(angular_rps)) linear_mps = angular_rps = 0.0;
  linear_mps_ = std::clamp(linear_mps, -options_.max_linear_speed_mps, options_.max_linear_speed_mps);
  angular_rps_ = std::clamp(angular_rps, -options_.max_angular_speed_rps, options_.max_angular_speed_rps);
}

double Simulator::Clearance(const Pose2D& pose) const {
  double clearance = std::numeric_limits<double>::infinity();
  for (const Surface& s : world_.surfaces) {
    if (s.z_min_m > kBumperHeightM || s.kind == SurfaceKind::kPerson) continue;
    clearance = std::min(clearance, PointSegmentDistance(pose.Position(), s.segment));
  }
  return clearance;
}

void Simulator::Step() {
  const double dt = options_.physics_step_s;
  // Exact unicycle motion over the step (an arc, or a line when not turning).
  Pose2D next = true_pose_;
  const double dtheta = angular_rps_ * dt;
  if (std::fabs(dtheta) < 1e-9) {
    next.x_m += linear_mps_ * dt * std::cos(true_pose_.theta_rad);
    next.y_m += linear_mps_ * dt * std::sin(true_pose_.theta_rad);
  } else {
    const double radius = linear_mps_ / angular_rps_;
    next.x_m += radius * (std::sin(true_pose_.theta_rad + dtheta) - std::sin(true_pose_.theta_rad));
    next.y_m -= radius * (std::cos(true_pose_.theta_rad + dtheta) - std::cos(true_pose_.theta_rad));
  }
  next.theta_rad = NormalizeAngle(true_pose_.theta_rad + dtheta);
  time_s_ += dt;
  // Moving into a wall is refused; moving away from one we already touch is allowed.
  const double clearance = Clearance(next);
  bumped_ = clearance < world_.robot_radius_m && clearance < Clearance(true_pose_);
  if (bumped_) return;  // the command stays; the robot pushes against the wall without moving
  distance_travelled_m_ += Norm(next.Position() - true_pose_.Position());
  odometry_.Update(true_pose_, next, odom_rng_);
  true_pose_ = next;
}

void Simulator::Teleport(const Pose2D& pose) { true_pose_ = pose; }

void Simulator::ChangeWorld(World floor_world, const Pose2D& pose) {
  world_ = std::move(floor_world);
  if (world_.surfaces.empty()) BuildSurfaces(world_);
  PlacePeople(world_, time_s_);
  people_time_s_ = time_s_;
  camera_ = std::make_unique<CameraRenderer>(world_, world_.sensors.camera);
  true_pose_ = pose;
  linear_mps_ = angular_rps_ = 0.0;
  bumped_ = false;
}

void Simulator::UpdatePeople() {
  if (world_.people.empty() || people_time_s_ == time_s_) return;
  PlacePeople(world_, time_s_);
  people_time_s_ = time_s_;
}

LaserScan Simulator::Scan() {
  UpdatePeople();
  return laser_.Simulate(world_, true_pose_, laser_rng_);
}

cv::Mat Simulator::CameraImage() {
  UpdatePeople();
  return camera_->Render(true_pose_, linear_mps_, angular_rps_, camera_rng_);
}

}  // namespace doorplate_localization

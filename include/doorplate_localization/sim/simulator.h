// The corridor world simulator as a library: a differential-drive robot moving on command through a
// World, with laser, odometry and camera on it. Deterministic for a given seed. No ROS.
#pragma once

#include <cstdint>
#include <memory>
#include <random>

#include <opencv2/core.hpp>

#include "doorplate_localization/sim/camera_renderer.h"
#include "doorplate_localization/sim/laser_simulator.h"
#include "doorplate_localization/sim/odometry_simulator.h"
#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

struct SimulatorOptions {
  double physics_step_s = 0.01;
  double max_linear_speed_mps = 1.0;
  double max_angular_speed_rps = 2.0;
  std::uint64_t seed = 1;
};

class Simulator {
 public:
  // Takes a copy of the world (with its sensor settings).
  Simulator(World world, const SimulatorOptions& options);

  // Sets the commanded velocity (base_link frame), clamped to the options' limits.
  void SetCommand(double linear_mps, double angular_rps);
  // Advances the physics by one step. A step that would take the robot into a wall or clutter is not
  // made and bumped() is true until a step moves it again. People (World::people) never block the robot:
  // they are taken to step round it.
  void Step();
  // Moves the robot instantly (kidnapping); odometry does not see it.
  void Teleport(const Pose2D& pose);
  // A lift ride to another floor: the robot is at `pose` in `floor_world` (a world of the same building:
  // its surfaces and signs replace the current ones; the laser and odometry keep their settings, the camera
  // takes the new world's), stopped; odometry, time, the random streams and the distance travelled carry
  // on (odometry does not see the ride).
  void ChangeWorld(World floor_world, const Pose2D& pose);

  double time_s() const { return time_s_; }
  const Pose2D& true_pose() const { return true_pose_; }
  const Pose2D& odom_pose() const { return odometry_.pose(); }
  double linear_velocity_mps() const { return linear_mps_; }
  double angular_velocity_rps() const { return angular_rps_; }
  bool bumped() const { return bumped_; }
  double distance_travelled_m() const { return distance_travelled_m_; }

  // The sensors see the world's people where they are at time_s() (PlacePeople).
  LaserScan Scan();
  cv::Mat CameraImage();

  // The world, with its people placed at the time of the last Scan/CameraImage (at 0 before any).
  const World& world() const { return world_; }
  const LaserSimulator& laser() const { return laser_; }
  const CameraRenderer& camera() const { return *camera_; }

 private:
  // Distance from the robot centre to the nearest surface low enough to hit (people aside), metres.
  double Clearance(const Pose2D& pose) const;
  // Moves the people's surfaces to time_s_ if they are elsewhere.
  void UpdatePeople();

  World world_;
  const SimulatorOptions options_;
  std::mt19937_64 odom_rng_, laser_rng_, camera_rng_;
  LaserSimulator laser_;
  OdometrySimulator odometry_;
  std::unique_ptr<CameraRenderer> camera_;
  Pose2D true_pose_;
  double time_s_ = 0.0;
  double linear_mps_ = 0.0, angular_rps_ = 0.0;
  bool bumped_ = false;
  double distance_travelled_m_ = 0.0;
  double people_time_s_ = 0.0;  // time the people's surfaces in world_ show
};

}  // namespace doorplate_localization

// CorridorSimNodelet: runs the ROS-free corridor Simulator in sim time and publishes its sensors.
// Topics (relative to the nodelet's namespace): publishes /clock, scan, odom, base_pose_ground_truth,
// camera/image_raw + camera/camera_info (rendered only while subscribed), tf odom -> base_link (and
// map -> odom from the true pose if ~publish_ground_truth_tf), static tf base_link -> laser and
// base_link -> camera_link -> camera_optical; subscribes cmd_vel and ~teleport (geometry_msgs/Pose2D: moves
// the robot there at once, in the world frame, metres and radians — a kidnapping; odometry does not see it).
// It also subscribes ride_lift (std_msgs/String "<lift id> <floor id>", e.g. "A 3", ros/lift_ride.h): with
// ~building (several floors' worlds and their lifts, docs/building-format.md) a robot within 1.5 m of that
// lift's stop on its floor leaves the lift at its stop on that floor, facing away from the door
// (Simulator::ChangeWorld; odometry does not see the ride); else a warning says why and nothing moves.
// Publishes ~floor (std_msgs/String, latched: the floor the robot is truly on; with ~world, the world's name).
// With ~wait_for_recorder_s it holds sim time at 0 until a recorder subscribes base_pose_ground_truth.
// Parameters: corridor_sim_options.h.
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <geometry_msgs/Pose2D.h>
#include <geometry_msgs/Twist.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <std_msgs/String.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

#include "corridor_sim_options.h"
#include "doorplate_localization/ros/lift_ride.h"
#include "doorplate_localization/ros/sim_conversions.h"
#include "doorplate_localization/sim/simulator.h"

namespace doorplate_localization {
namespace {

// Fires once per period of `rate_hz` in sim time: at the first step of every tick floor(t * rate_hz).
class RateGate {
 public:
  explicit RateGate(double rate_hz) : rate_hz_(rate_hz) {}
  bool Due(double time_s) {
    const long tick = static_cast<long>(std::floor(time_s * rate_hz_ + 1e-9));
    if (tick == last_tick_) return false;
    last_tick_ = tick;
    return true;
  }

 private:
  double rate_hz_;
  long last_tick_ = -1;
};

// What one physics step produced, copied out under the lock and published after it.
struct StepOutput {
  double time_s = 0.0;
  std::optional<LaserScan> scan;
  bool odometry_due = false;
  Pose2D odom_pose, true_pose;
  double linear_mps = 0.0, angular_rps = 0.0;
  PlanarVariance odom_variance;
  std::optional<cv::Mat> image;
  bool camera_due = false;
};

}  // namespace

class CorridorSimNodelet : public nodelet::Nodelet {
 public:
  ~CorridorSimNodelet() override {
    stop_ = true;
    if (worker_.joinable()) worker_.join();
  }

 private:
  void onInit() override {
    try {
      options_ = LoadCorridorSimOptions(getPrivateNodeHandle());
      sim_ = std::make_unique<Simulator>(options_.world, options_.simulator);
      floor_ = options_.start_floor;
    } catch (const std::exception& e) {
      NODELET_FATAL("%s", e.what());
      throw;
    }
    ros::NodeHandle& nh = getNodeHandle();
    if (options_.publish_clock) clock_pub_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
    scan_pub_ = nh.advertise<sensor_msgs::LaserScan>("scan", 10);
    odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", 50);
    truth_pub_ = nh.advertise<nav_msgs::Odometry>("base_pose_ground_truth", 50);
    image_pub_ = nh.advertise<sensor_msgs::Image>("camera/image_raw", 2);
    info_pub_ = nh.advertise<sensor_msgs::CameraInfo>("camera/camera_info", 2);
    cmd_sub_ = nh.subscribe("cmd_vel", 10, &CorridorSimNodelet::OnCmdVel, this);
    teleport_sub_ = getPrivateNodeHandle().subscribe("teleport", 1, &CorridorSimNodelet::OnTeleport, this);
    ride_sub_ = nh.subscribe("ride_lift", 5, &CorridorSimNodelet::OnRideLift, this);
    floor_pub_ = getPrivateNodeHandle().advertise<std_msgs::String>("floor", 1, /*latch=*/true);
    PublishFloor();
    tf_ = std::make_unique<tf2_ros::TransformBroadcaster>();
    static_tf_ = std::make_unique<tf2_ros::StaticTransformBroadcaster>();
    PublishStaticTransforms();
    NODELET_INFO("corridor sim: world '%s' (%s; floor '%s' of %zu), seed %lu, real_time_factor %.2f, "
                 "physics step %.3f s", options_.world.name.c_str(), options_.world_file.c_str(),
                 options_.floor.c_str(), options_.building.floors.size(),
                 static_cast<unsigned long>(options_.simulator.seed), options_.real_time_factor,
                 options_.simulator.physics_step_s);
    worker_ = std::thread(&CorridorSimNodelet::Run, this);
  }

  void OnCmdVel(const geometry_msgs::Twist::ConstPtr& msg) {
    if (!std::isfinite(msg->linear.x) || !std::isfinite(msg->angular.z)) {
      NODELET_ERROR_THROTTLE(1.0, "%s: ignoring non-finite command linear.x=%f angular.z=%f",
                             cmd_sub_.getTopic().c_str(), msg->linear.x, msg->angular.z);
      return;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    sim_->SetCommand(msg->linear.x, msg->angular.z);
    last_cmd_time_s_ = sim_->time_s();
  }

  void OnTeleport(const geometry_msgs::Pose2D::ConstPtr& msg) {
    if (!std::isfinite(msg->x) || !std::isfinite(msg->y) || !std::isfinite(msg->theta)) {
      NODELET_ERROR("%s: ignoring a non-finite pose x=%f y=%f theta=%f", teleport_sub_.getTopic().c_str(), msg->x,
                    msg->y, msg->theta);
      return;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    sim_->Teleport({msg->x, msg->y, msg->theta});
    NODELET_WARN("%s: robot teleported to (%.2f, %.2f, %.1f deg)", teleport_sub_.getTopic().c_str(), msg->x, msg->y,
                 msg->theta * 180.0 / M_PI);
  }

  // A lift ride: validate -> plan where it ends (lift_ride.h) -> move the robot to that floor's world.
  void OnRideLift(const std_msgs::String::ConstPtr& msg) {
    const std::string& topic = ride_sub_.getTopic();
    LiftRideRequest ride;
    std::string problem = ParseLiftRide(msg->data, &ride);
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string& from = options_.building.floors[static_cast<size_t>(floor_)].id;
    int to = -1;
    Pose2D pose;
    if (problem.empty()) {
      problem = PlanLiftRide(options_.building, ride, from, sim_->true_pose(), kLiftRideDistanceM, &to, &pose);
    }
    if (!problem.empty()) {
      NODELET_WARN("%s: '%s': %s; the robot stays where it is", topic.c_str(), msg->data.c_str(), problem.c_str());
      return;
    }
    sim_->ChangeWorld(options_.floor_worlds[static_cast<size_t>(to)], pose);
    floor_ = to;
    NODELET_INFO("%s: rode lift %s from floor %s to floor %s: at (%.2f, %.2f, %.0f deg)", topic.c_str(),
                 ride.lift.c_str(), from.c_str(), ride.floor.c_str(), pose.x_m, pose.y_m, pose.theta_rad * 180 / M_PI);
    PublishFloor();
  }

  void PublishFloor() {  // requires mutex_ once the worker runs
    std_msgs::String msg;
    msg.data = options_.building.floors[static_cast<size_t>(floor_)].id;
    floor_pub_.publish(msg);
  }

  void PublishStaticTransforms() {
    const ros::Time stamp = SimTime(0.0);
    const SensorOptions& sensors = options_.world.sensors;
    double x, y, z, yaw, pitch;
    sim_->camera().MountPose(&x, &y, &z, &yaw, &pitch);
    static_tf_->sendTransform(std::vector<geometry_msgs::TransformStamped>{
        ToTransformStampedMsg(sim_->laser().MountPose(), options_.base_frame_id, options_.laser_frame_id, stamp,
                              sensors.laser.mount_height_m),
        CameraBodyTransformMsg(x, y, z, yaw, pitch, options_.base_frame_id, options_.camera_body_frame_id, stamp),
        OpticalFromBodyTransformMsg(options_.camera_body_frame_id, options_.camera_frame_id, stamp)});
  }

  // One physics step and whatever sensor output falls due, all under the lock.
  StepOutput StepOnce() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (sim_->time_s() - last_cmd_time_s_ > options_.cmd_vel_timeout_s) sim_->SetCommand(0.0, 0.0);
    const double theta_before = sim_->true_pose().theta_rad;
    sim_->Step();
    turned_rad_ += std::fabs(NormalizeAngle(sim_->true_pose().theta_rad - theta_before));
    StepOutput out;
    out.time_s = sim_->time_s();
    if (scan_gate_->Due(out.time_s)) out.scan = sim_->Scan();
    out.odometry_due = odom_gate_->Due(out.time_s);
    out.odom_pose = sim_->odom_pose();
    out.true_pose = sim_->true_pose();
    out.linear_mps = sim_->linear_velocity_mps();
    out.angular_rps = sim_->angular_velocity_rps();
    out.odom_variance =
        OdometryPoseVariance(options_.world.sensors.odometry, sim_->distance_travelled_m(), turned_rad_);
    out.camera_due = camera_gate_->Due(out.time_s) &&
                     (image_pub_.getNumSubscribers() > 0 || info_pub_.getNumSubscribers() > 0);
    if (out.camera_due && image_pub_.getNumSubscribers() > 0) out.image = sim_->CameraImage();
    return out;
  }

  void Publish(const StepOutput& out) {
    const ros::Time stamp = SimTime(out.time_s);
    if (options_.publish_clock) {
      rosgraph_msgs::Clock clock;
      clock.clock = stamp;
      clock_pub_.publish(clock);
    }
    if (out.scan) {
      scan_pub_.publish(ToLaserScanMsg(*out.scan, options_.world.sensors.laser.rate_hz, options_.laser_frame_id,
                                       stamp));
    }
    if (out.odometry_due) {
      odom_pub_.publish(ToOdometryMsg(out.odom_pose, out.linear_mps, out.angular_rps, options_.odom_frame_id,
                                      options_.base_frame_id, stamp, out.odom_variance));
      truth_pub_.publish(ToOdometryMsg(out.true_pose, out.linear_mps, out.angular_rps,
                                       options_.ground_truth_frame_id, options_.base_frame_id, stamp));
      std::vector<geometry_msgs::TransformStamped> transforms{
          ToTransformStampedMsg(out.odom_pose, options_.odom_frame_id, options_.base_frame_id, stamp)};
      if (options_.publish_ground_truth_tf) {
        transforms.push_back(ToTransformStampedMsg(out.true_pose.Compose(out.odom_pose.Inverse()),
                                                   options_.ground_truth_frame_id, options_.odom_frame_id, stamp));
      }
      tf_->sendTransform(transforms);
    }
    if (out.camera_due) {
      info_pub_.publish(ToCameraInfoMsg(sim_->camera().intrinsics(), options_.camera_frame_id, stamp));
      if (out.image) image_pub_.publish(ToImageMsg(*out.image, options_.camera_frame_id, stamp));
    }
  }

  // Before the first step (with ~wait_for_recorder_s > 0): waits, in wall time, until base_pose_ground_truth
  // has a subscriber — the recorder of a run — so the recording starts at sim time 0, not wherever a slow
  // recorder happened to connect (a bag that misses the start measures from the wrong moment).
  void WaitForRecorder() {
    if (options_.wait_for_recorder_s <= 0.0) return;
    const std::string topic = truth_pub_.getTopic();
    NODELET_INFO("corridor sim: waiting up to %.1f s for a subscriber of %s (~wait_for_recorder_s)",
                 options_.wait_for_recorder_s, topic.c_str());
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(options_.wait_for_recorder_s);
    while (!stop_ && ros::ok() && truth_pub_.getNumSubscribers() == 0) {
      if (ros::WallTime::now() > deadline) {
        NODELET_WARN("corridor sim: no subscriber of %s after %.1f s (~wait_for_recorder_s): starting anyway; "
                     "a recording will miss the start", topic.c_str(), options_.wait_for_recorder_s);
        return;
      }
      ros::WallDuration(0.01).sleep();
    }
    // A recorder subscribes to all its topics at once; give the other connections a moment to complete.
    ros::WallDuration(kRecorderSettleS).sleep();
    NODELET_INFO("corridor sim: %s has a subscriber; starting", topic.c_str());
  }

  // Worker thread: step, publish, then wait until wall time catches up with sim time / real_time_factor.
  void Run() {
    WaitForRecorder();
    const SensorOptions& sensors = options_.world.sensors;
    scan_gate_.emplace(sensors.laser.rate_hz);
    odom_gate_.emplace(sensors.odometry.rate_hz);
    camera_gate_.emplace(sensors.camera.rate_hz);
    ros::WallTime anchor_wall = ros::WallTime::now();
    double anchor_sim_s = 0.0;
    while (!stop_ && ros::ok()) {
      const StepOutput out = StepOnce();
      Publish(out);
      if (options_.real_time_factor <= 0.0) continue;
      const ros::WallTime due = anchor_wall + ros::WallDuration((out.time_s - anchor_sim_s) / options_.real_time_factor);
      const ros::WallTime now = ros::WallTime::now();
      if (now < due) {
        (due - now).sleep();
      } else if ((now - due).toSec() > kMaxLagS) {  // too slow for the factor: do not burst to catch up
        NODELET_WARN_THROTTLE(10.0, "corridor sim: %.2f s behind real_time_factor %.2f",
                              (now - due).toSec(), options_.real_time_factor);
        anchor_wall = now;
        anchor_sim_s = out.time_s;
      }
    }
  }

  static constexpr double kMaxLagS = 0.5;
  static constexpr double kRecorderSettleS = 0.5;  // wall seconds after the recorder's first connection
  static constexpr double kLiftRideDistanceM = 1.5;  // a ride needs the robot this close to the lift's stop

  CorridorSimOptions options_;
  std::mutex mutex_;  // guards sim_, floor_, last_cmd_time_s_ and turned_rad_
  std::unique_ptr<Simulator> sim_;
  double last_cmd_time_s_ = -std::numeric_limits<double>::infinity();
  double turned_rad_ = 0.0;  // sum of |yaw change| of the true pose, for the odometry variance
  int floor_ = 0;            // index into options_.building.floors: where the robot truly is
  std::optional<RateGate> scan_gate_, odom_gate_, camera_gate_;
  ros::Publisher clock_pub_, scan_pub_, odom_pub_, truth_pub_, image_pub_, info_pub_, floor_pub_;
  ros::Subscriber cmd_sub_, teleport_sub_, ride_sub_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> tf_;
  std::unique_ptr<tf2_ros::StaticTransformBroadcaster> static_tf_;
  std::atomic<bool> stop_{false};
  std::thread worker_;
};

}  // namespace doorplate_localization

PLUGINLIB_EXPORT_CLASS(doorplate_localization::CorridorSimNodelet, nodelet::Nodelet)

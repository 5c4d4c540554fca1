// WallFollowerNodelet: corridor following with the laser (paper Sec. 3.2-3.4) as a thin nodelet over
// WallFollower (~mode follow), CorridorSweep (~mode sweep / patrol), FloorExplorer (~mode explore: a
// whole floor) or ContourSteering (~mode roam: one wall of a floor, for ever); sweep, patrol and explore
// also need tf odom→base_link to measure turns and distance.
// Subscribes scan (sensor_msgs/LaserScan, any frame with a tf to base_link) and, in explore mode,
// text_detections (TextDetectionArray: its plate reports end the passes); publishes cmd_vel
// (geometry_msgs/Twist), ~state (std_msgs/String, latched: follow mode following | no_wall |
// end_reached; sweep modes follow_out | turn_around | follow_back | done; explore pass_<n> |
// turn_around | done; roam roaming | no_wall; any mode disabled | no_valid_scan) and ~corridor_width (std_msgs/Float32, metres,
// when both walls are seen; follow and sweep modes).
// Service ~enable (std_srvs/SetBool) starts and stops driving. Parameters: wall_follower_options.h.
#include <mutex>

#include <geometry_msgs/Twist.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Float32.h>
#include <std_msgs/String.h>
#include <std_srvs/SetBool.h>
#include <tf2/utils.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "doorplate_localization/TextDetectionArray.h"
#include "doorplate_localization/ros/scan_conversions.h"
#include "doorplate_localization/ros/text_detection_conversions.h"
#include "doorplate_localization/ros/tf_lookup.h"
#include "wall_follower_options.h"

namespace doorplate_localization {

class WallFollowerNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    try {
      options_ = LoadWallFollowerOptions(pnh);
      follower_ = std::make_unique<WallFollower>(options_.follower);
      if (options_.mode == CorridorDriveMode::kSweep || options_.mode == CorridorDriveMode::kPatrol) {
        sweep_ = std::make_unique<CorridorSweep>(options_.sweep);
      }
      if (options_.mode == CorridorDriveMode::kExplore) explorer_ = std::make_unique<FloorExplorer>(options_.explore);
      if (options_.mode == CorridorDriveMode::kRoam) roamer_ = std::make_unique<ContourSteering>(options_.explore.steering);
    } catch (const std::exception& e) {
      NODELET_FATAL("%s", e.what());
      throw;
    }
    enabled_ = options_.enabled;
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(tf_buffer_);
    cmd_pub_ = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
    state_pub_ = pnh.advertise<std_msgs::String>("state", 1, /*latch=*/true);
    width_pub_ = pnh.advertise<std_msgs::Float32>("corridor_width", 1);
    enable_srv_ = pnh.advertiseService("enable", &WallFollowerNodelet::OnEnable, this);
    scan_sub_ = nh.subscribe("scan", 1, &WallFollowerNodelet::OnScan, this);
    if (explorer_) detections_sub_ = nh.subscribe("text_detections", kTextDetectionsQueueSize, &WallFollowerNodelet::OnDetections, this);
    watchdog_ = nh.createTimer(ros::Duration(options_.scan_timeout_s), &WallFollowerNodelet::OnWatchdog, this);
    PublishState(enabled_ ? "waiting_for_scan" : "disabled");
  }

  bool OnEnable(std_srvs::SetBool::Request& req, std_srvs::SetBool::Response& res) {
    std::lock_guard<std::mutex> lock(mutex_);
    enabled_ = req.data;
    if (!enabled_) Stop("disabled");
    res.success = true;
    res.message = enabled_ ? "driving" : "stopped";
    return true;
  }

  void OnDetections(const TextDetectionArray::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    const int ended = explorer_->passes_ended();
    // Judged where the robot was when the camera saw the plate (the report comes later on a loaded machine).
    for (const std::string& text : CrossedPlateTexts(*msg)) explorer_->OnPlateRead(text, msg->header.stamp.toSec());
    if (explorer_->passes_ended() != ended) {
      NODELET_INFO("floor exploration: pass %d ended (%s) after %.1f m; %d plates known", explorer_->pass(),
                   PassEndName(explorer_->last_pass_end()), explorer_->pass_distance_m(), explorer_->plates_known());
    }
  }

  void OnScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
    std::lock_guard<std::mutex> lock(mutex_);
    // validate → convert → core → publish
    std::string problem = ValidateScan(*scan);
    double yaw_in_base = 0.0;
    Pose2D odom_pose;
    if (problem.empty()) {
      const std::optional<Pose2D> laser_in_base =
          LookupPlanarPose(tf_buffer_, options_.base_frame_id, scan->header.frame_id, scan->header.stamp, 0.1, &problem);
      if (laser_in_base) yaw_in_base = laser_in_base->theta_rad;
    }
    if (problem.empty() && (sweep_ || explorer_)) {
      // The latest odometry, not the one at the scan's stamp: the turn is measured by the yaw change, which
      // a few tens of milliseconds of latency do not disturb, while waiting for the stamp can time out. But not
      // odometry that stood still while the robot moved on: a turn steered with it overshot (~max_odom_lag_s).
      const std::optional<Pose2D> base_in_odom = LookupLatestPlanarPose(
          tf_buffer_, options_.odom_frame_id, options_.base_frame_id, scan->header.stamp, options_.max_odom_lag_s,
          0.1, &problem);
      if (base_in_odom) odom_pose = *base_in_odom;
    }
    if (!problem.empty()) {
      NODELET_ERROR_THROTTLE(2.0, "%s: %s; stopping", scan_sub_.getTopic().c_str(), problem.c_str());
      Stop("no_valid_scan");
      return;
    }
    last_valid_scan_ = ros::Time::now();
    if (!enabled_) return;
    CorridorObservation obs;
    VelocityCommand cmd;
    std::string state;
    if (roamer_) {
      const ContourSteeringResult steer = roamer_->Step(scan->ranges, scan->angle_min + yaw_in_base, scan->angle_increment);
      cmd = steer.command;
      state = steer.wall_found ? "roaming" : "no_wall";
    } else if (explorer_) {
      cmd = explorer_->Step(scan->ranges, scan->angle_min + yaw_in_base, scan->angle_increment, odom_pose,
                            scan->header.stamp.toSec());
      state = explorer_->phase() == ExplorePhase::kFollow ? "pass_" + std::to_string(explorer_->pass())
                                                          : ExplorePhaseName(explorer_->phase());
    } else if (sweep_) {
      if (sweep_->phase() == SweepPhase::kDone && options_.mode == CorridorDriveMode::kPatrol) sweep_->Reset();
      cmd = sweep_->Step(scan->ranges, scan->angle_min + yaw_in_base, scan->angle_increment, odom_pose,
                         scan->header.stamp.toSec());
      obs = sweep_->last_observation();
      state = SweepPhaseName(sweep_->phase());
    } else {
      obs = follower_->Observe(scan->ranges, scan->angle_min + yaw_in_base, scan->angle_increment);
      WallFollowState follow_state;
      cmd = follower_->Command(obs, &follow_state);
      state = follow_state == WallFollowState::kFollowing ? "following"
              : follow_state == WallFollowState::kNoWall  ? "no_wall"
                                                          : "end_reached";
    }
    geometry_msgs::Twist twist;
    twist.linear.x = cmd.linear_mps;
    twist.angular.z = cmd.angular_rps;
    cmd_pub_.publish(twist);
    if (obs.width_m > 0.0) {
      std_msgs::Float32 width;
      width.data = static_cast<float>(obs.width_m);
      width_pub_.publish(width);
    }
    PublishState(state);
  }

  void OnWatchdog(const ros::TimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (enabled_ && !last_valid_scan_.isZero() &&
        (ros::Time::now() - last_valid_scan_).toSec() > options_.scan_timeout_s) {
      NODELET_WARN_THROTTLE(5.0, "%s: no valid scan for %.1f s; stopping", scan_sub_.getTopic().c_str(),
                            options_.scan_timeout_s);
      Stop("no_valid_scan");
    }
  }

  void Stop(const std::string& state) {
    cmd_pub_.publish(geometry_msgs::Twist());
    PublishState(state);
  }

  void PublishState(const std::string& state) {
    if (state == last_state_) return;
    last_state_ = state;
    std_msgs::String msg;
    msg.data = state;
    state_pub_.publish(msg);
    NODELET_INFO("corridor following: %s", state.c_str());
  }

  WallFollowerNodeOptions options_;
  std::unique_ptr<WallFollower> follower_;
  std::unique_ptr<CorridorSweep> sweep_;  // sweep and patrol modes
  std::unique_ptr<FloorExplorer> explorer_;  // explore mode
  std::unique_ptr<ContourSteering> roamer_;  // roam mode
  tf2_ros::Buffer tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  ros::Publisher cmd_pub_, state_pub_, width_pub_;
  ros::Subscriber scan_sub_, detections_sub_;
  ros::ServiceServer enable_srv_;
  ros::Timer watchdog_;
  std::mutex mutex_;
  bool enabled_ = true;
  ros::Time last_valid_scan_;
  std::string last_state_;
};

}  // namespace doorplate_localization

PLUGINLIB_EXPORT_CLASS(doorplate_localization::WallFollowerNodelet, nodelet::Nodelet)

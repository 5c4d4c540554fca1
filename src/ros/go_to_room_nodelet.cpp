// GoToRoomNodelet: go to a room by number (paper Sec. 3.4, Fig. 8, eq. 15) as a thin nodelet over
// RoomGoalPlanner, PlanFromReading and GoToRoom (include/doorplate_localization/behaviour/).
// Subscribes go_to_room (std_msgs/String: "105", or "220@north" for one plate of a repeated number; every
// request replaces the current goal), scan (sensor_msgs/LaserScan, for the wall following) and, with
// ~text_fallback, text_detections (TextDetectionArray). Pose: tf map -> base_link (a localizer's, amcl
// style); while that tf is missing a request waits (a warning names the frames) and nothing drives, unless
// a plate was read recently: then eq. 15 gives the goal in odom and the robot drives by odometry.
// Publishes cmd_vel (geometry_msgs/Twist) ONLY while a goal is active (and one zero when it ends), so it
// idles beside another driver until asked; ~status (std_msgs/String, latched: "idle", "waiting_for_pose: ...",
// "turning: ...", "driving: room 105, 3.20 m to go", "facing: ...", "arrived: ...", "refused: <reason>",
// "failed: <reason>"), ~goal (geometry_msgs/PoseStamped, latched, for rviz). Parameters: go_to_room_options.h.
// With ~route grid (a whole floor) it also subscribes map (nav_msgs/OccupancyGrid, latched by the localizer)
// and drives FloorGoToRoom instead: a path over the grid round corners ("following: ..." statuses), published
// on ~path (nav_msgs/Path, latched, for rviz); a request waits for both the map and the map pose.
#include <memory>
#include <mutex>
#include <optional>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>
#include <tf2/utils.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "doorplate_localization/behaviour/plate_route.h"
#include "doorplate_localization/ros/map_conversions.h"
#include "doorplate_localization/ros/pose_conversions.h"
#include "doorplate_localization/ros/scan_conversions.h"
#include "doorplate_localization/ros/text_detection_conversions.h"
#include "go_to_room_conversions.h"
#include "go_to_room_options.h"

namespace doorplate_localization {

class GoToRoomNodelet : public nodelet::Nodelet {
 private:
  struct Reading {
    PlateReading plate;
    ros::Time stamp;
  };

  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    try {
      options_ = LoadGoToRoomOptions(pnh);
      planner_ = std::make_unique<RoomGoalPlanner>(options_.planner, options_.text_map, options_.text_map_file);
      controller_ = std::make_unique<GoToRoom>(options_.controller);
    } catch (const std::exception& e) {
      NODELET_FATAL("%s", e.what());
      throw;
    }
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(tf_buffer_);
    cmd_pub_ = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
    status_pub_ = pnh.advertise<std_msgs::String>("status", 1, /*latch=*/true);
    goal_pub_ = pnh.advertise<geometry_msgs::PoseStamped>("goal", 1, /*latch=*/true);
    request_sub_ = nh.subscribe("go_to_room", 5, &GoToRoomNodelet::OnRequest, this);
    scan_sub_ = nh.subscribe("scan", 1, &GoToRoomNodelet::OnScan, this);
    if (options_.route == "grid") {
      path_pub_ = pnh.advertise<nav_msgs::Path>("path", 1, /*latch=*/true);
      map_sub_ = nh.subscribe("map", 1, &GoToRoomNodelet::OnMap, this);
    } else if (options_.text_fallback) {
      detections_sub_ = nh.subscribe("text_detections", 10, &GoToRoomNodelet::OnDetections, this);
    }
    watchdog_ = nh.createTimer(ros::Duration(options_.scan_timeout_s), &GoToRoomNodelet::OnWatchdog, this);
    NODELET_INFO("go to room: %zu plates from %s (rooms: %zu)", options_.text_map.landmarks.size(),
                 options_.text_map_file.c_str(), options_.text_map.Texts().size());
    PublishStatus(controller_->Status());
  }

  void OnRequest(const std_msgs::String::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    const bool was_active = Active();
    controller_->Cancel();
    if (floor_) floor_->Cancel();
    pending_.reset();
    const RoomCandidates candidates = planner_->Candidates(msg->data);
    if (candidates.landmarks.empty()) {
      Refuse(candidates.refusal, was_active);
      return;
    }
    if (was_active) cmd_pub_.publish(geometry_msgs::Twist());
    pending_ = msg->data;
    TryPlan(ros::Time(0));
  }

  // Plans the pending request with the map pose at `stamp` (0: latest), else eq. 15 from a recent reading.
  void TryPlan(const ros::Time& stamp) {
    std::string problem;
    const std::optional<Pose2D> map_pose = LookupPose(options_.global_frame_id, stamp, &problem);
    if (options_.route == "grid") {
      TryPlanOnGrid(map_pose, problem);
      return;
    }
    RoomGoalResult result;
    if (map_pose) {
      result = planner_->Plan(*pending_, map_pose);
      goal_frame_ = options_.global_frame_id;
    } else if (reading_ && (ros::Time::now() - reading_->stamp).toSec() <= options_.reading_max_age_s) {
      result = PlanFromReading(*planner_, *pending_, reading_->plate);
      goal_frame_ = options_.odom_frame_id;
    } else {
      const std::string waiting = "waiting_for_pose: room " + *pending_ + ": no tf " + options_.global_frame_id +
                                  " -> " + options_.base_frame_id + " (" + problem + ")" +
                                  (options_.text_fallback ? " and no plate read recently" : "") + "; not driving";
      NODELET_WARN_THROTTLE(5.0, "%s", waiting.c_str());
      PublishStatus(waiting);
      return;
    }
    const std::string request = *pending_;
    pending_.reset();
    if (!result.goal) {
      Refuse(result.refusal, false);
      return;
    }
    controller_->Start(*result.goal);
    const Pose2D& g = result.goal->pose;
    NODELET_INFO("going to room %s: goal (%.2f, %.2f, %.2f rad) in %s%s%s", result.goal->room.c_str(), g.x_m, g.y_m,
                 g.theta_rad, goal_frame_.c_str(), result.goal->note.empty() ? "" : "; ", result.goal->note.c_str());
    goal_pub_.publish(ToGoalPoseMsg(g, goal_frame_, ros::Time::now()));
    PublishStatus(controller_->Status());
  }

  // TryPlan for ~route grid: the goal from the text map, the path from the map pose over the latest map.
  void TryPlanOnGrid(const std::optional<Pose2D>& map_pose, const std::string& problem) {
    if (!floor_ || !map_pose) {
      const std::string waiting = "waiting_for_pose: room " + *pending_ + ": " +
                                  (!floor_ ? "no map on " + map_sub_.getTopic() + " yet"
                                           : "no tf " + options_.global_frame_id + " -> " + options_.base_frame_id +
                                                 " (" + problem + ")") +
                                  "; not driving";
      NODELET_WARN_THROTTLE(5.0, "%s", waiting.c_str());
      PublishStatus(waiting);
      return;
    }
    const RoomGoalResult result = planner_->Plan(*pending_, map_pose);
    pending_.reset();
    if (!result.goal) {
      Refuse(result.refusal, false);
      return;
    }
    goal_frame_ = options_.global_frame_id;
    if (!floor_->Start(*result.goal, *map_pose)) {
      NODELET_ERROR("go to room %s", floor_->Status().c_str());
      PublishStatus(floor_->Status());
      return;
    }
    const Pose2D& g = result.goal->pose;
    NODELET_INFO("going to room %s: goal (%.2f, %.2f, %.2f rad) in %s, path %.1f m%s%s", result.goal->room.c_str(),
                 g.x_m, g.y_m, g.theta_rad, goal_frame_.c_str(), floor_->first_plan_length_m(),
                 result.goal->note.empty() ? "" : "; ", result.goal->note.c_str());
    goal_pub_.publish(ToGoalPoseMsg(g, goal_frame_, ros::Time::now()));
    PublishPath();
    PublishStatus(floor_->Status());
  }

  void OnMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    OccupancyGrid grid;
    const std::string problem = FromOccupancyGridMsg(*msg, &grid);
    if (!problem.empty()) {
      NODELET_ERROR("%s: %s; keeping the previous map", map_sub_.getTopic().c_str(), problem.c_str());
      return;
    }
    if (floor_ && floor_->active()) {
      cmd_pub_.publish(geometry_msgs::Twist());
      NODELET_WARN("%s: a new map while going to room %s: stopped, ask again", map_sub_.getTopic().c_str(),
                   floor_->goal().room.c_str());
    }
    floor_ = std::make_unique<FloorGoToRoom>(options_.floor, grid);
    NODELET_INFO("go to room: map %u x %u cells at %.3f m for the grid route", msg->info.width, msg->info.height,
                 msg->info.resolution);
    if (pending_) TryPlan(ros::Time(0));
  }

  void PublishPath() {
    nav_msgs::Path path;
    path.header.frame_id = goal_frame_;
    path.header.stamp = ros::Time::now();
    for (const Vec2& p : floor_->path().waypoints) {
      geometry_msgs::PoseStamped pose;
      pose.header = path.header;
      pose.pose.position.x = p.x;
      pose.pose.position.y = p.y;
      pose.pose.orientation.w = 1.0;
      path.poses.push_back(pose);
    }
    path_pub_.publish(path);
  }

  bool Active() const { return controller_->active() || (floor_ && floor_->active()); }

  void Refuse(const std::string& reason, bool was_active) {
    controller_->Refuse(reason);
    if (was_active) cmd_pub_.publish(geometry_msgs::Twist());
    NODELET_ERROR("%s: %s", request_sub_.getTopic().c_str(), reason.c_str());
    PublishStatus(controller_->Status());
  }

  void OnScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::string problem = ValidateScan(*scan);
    double yaw_in_base = 0.0;
    if (problem.empty()) {
      try {
        yaw_in_base = tf2::getYaw(tf_buffer_
                                      .lookupTransform(options_.base_frame_id, scan->header.frame_id,
                                                       scan->header.stamp, ros::Duration(options_.tf_timeout_s))
                                      .transform.rotation);
      } catch (const tf2::TransformException& e) {
        problem = "no tf " + options_.base_frame_id + " -> " + scan->header.frame_id + ": " + e.what();
      }
    }
    if (!problem.empty()) {
      NODELET_ERROR_THROTTLE(2.0, "%s: %s; not driving", scan_sub_.getTopic().c_str(), problem.c_str());
      if (Active()) cmd_pub_.publish(geometry_msgs::Twist());
      return;
    }
    last_valid_scan_ = ros::Time::now();
    if (pending_) TryPlan(scan->header.stamp);
    if (floor_ && floor_->active()) {
      StepOnGrid(*scan, yaw_in_base);
      return;
    }
    if (!controller_->active()) return;
    const std::optional<Pose2D> pose = LookupPose(goal_frame_, scan->header.stamp, &problem);
    if (!pose) {
      const std::string waiting = "waiting_for_pose: room " + controller_->goal().room + ": no tf " + goal_frame_ +
                                  " -> " + options_.base_frame_id + " (" + problem + "); not driving";
      NODELET_WARN_THROTTLE(5.0, "%s", waiting.c_str());
      cmd_pub_.publish(geometry_msgs::Twist());
      PublishStatus(waiting);
      return;
    }
    const VelocityCommand cmd =
        controller_->Step(scan->ranges, scan->angle_min + yaw_in_base, scan->angle_increment, *pose);
    cmd_pub_.publish(ToTwistMsg(cmd));  // a zero command once the goal ends
    const std::string status = controller_->Status();
    if (controller_->state() == GoToRoomState::kFailed) NODELET_ERROR("go to room %s", status.c_str());
    if (controller_->state() == GoToRoomState::kArrived) NODELET_INFO("go to room %s", status.c_str());
    PublishStatus(status);
  }

  void StepOnGrid(const sensor_msgs::LaserScan& scan, double yaw_in_base) {
    std::string problem;
    const std::optional<Pose2D> pose = LookupPose(goal_frame_, scan.header.stamp, &problem);
    if (!pose) {
      const std::string waiting = "waiting_for_pose: room " + floor_->goal().room + ": no tf " + goal_frame_ +
                                  " -> " + options_.base_frame_id + " (" + problem + "); not driving";
      NODELET_WARN_THROTTLE(5.0, "%s", waiting.c_str());
      cmd_pub_.publish(geometry_msgs::Twist());
      PublishStatus(waiting);
      return;
    }
    const int replans = floor_->replans();
    const VelocityCommand cmd = floor_->Step(scan.ranges, scan.angle_min + yaw_in_base, scan.angle_increment, *pose,
                                             scan.header.stamp.toSec());
    cmd_pub_.publish(ToTwistMsg(cmd));  // a zero command once the goal ends
    if (floor_->replans() != replans) PublishPath();
    const std::string status = floor_->Status();
    if (floor_->state() == FloorGoToRoomState::kFailed) NODELET_ERROR("go to room %s", status.c_str());
    if (floor_->state() == FloorGoToRoomState::kArrived) NODELET_INFO("go to room %s", status.c_str());
    PublishStatus(status);
  }

  void OnDetections(const TextDetectionArray::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const std::string& text : CrossedPlateTexts(*msg)) {
      const std::vector<int> plates = options_.text_map.Find(text);
      if (plates.size() != 1) {
        NODELET_DEBUG("read '%s': %zu plates of that number in the text map, not used for eq. 15", text.c_str(),
                      plates.size());
        continue;
      }
      std::string problem;
      const std::optional<Pose2D> odom = LookupPose(options_.odom_frame_id, msg->header.stamp, &problem);
      std::optional<bool> left;
      try {
        left = CameraLooksLeft(tf_buffer_
                                   .lookupTransform(options_.base_frame_id, msg->header.frame_id, msg->header.stamp,
                                                    ros::Duration(options_.tf_timeout_s))
                                   .transform);
        if (!left) problem = "camera frame '" + msg->header.frame_id + "' does not look sideways";
      } catch (const tf2::TransformException& e) {
        problem = std::string("no tf ") + options_.base_frame_id + " -> " + msg->header.frame_id + ": " + e.what();
      }
      if (!odom || !left) {
        NODELET_WARN_THROTTLE(5.0, "%s: read '%s' but cannot use it for eq. 15: %s", detections_sub_.getTopic().c_str(),
                              text.c_str(), problem.c_str());
        continue;
      }
      reading_ = Reading{PlateReading{plates.front(), *odom, *left}, msg->header.stamp};
    }
    if (pending_ && reading_) TryPlan(ros::Time(0));
  }

  void OnWatchdog(const ros::TimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (Active() && !last_valid_scan_.isZero() &&
        (ros::Time::now() - last_valid_scan_).toSec() > options_.scan_timeout_s) {
      NODELET_WARN_THROTTLE(5.0, "%s: no valid scan for %.1f s; stopping", scan_sub_.getTopic().c_str(),
                            options_.scan_timeout_s);
      cmd_pub_.publish(geometry_msgs::Twist());
    }
  }

  // base_link in `frame` at `stamp` (0: the latest); nullopt with `*problem` set when tf has none.
  std::optional<Pose2D> LookupPose(const std::string& frame, const ros::Time& stamp, std::string* problem) {
    try {
      const ros::Duration wait(stamp.isZero() ? 0.0 : options_.tf_timeout_s);
      return ToPose2D(tf_buffer_.lookupTransform(frame, options_.base_frame_id, stamp, wait).transform);
    } catch (const std::exception& e) {  // tf2::TransformException, or a non-finite transform
      *problem = e.what();
      return std::nullopt;
    }
  }

  // Publishes on a change of state, and at most once a second while the text only changes its numbers.
  void PublishStatus(const std::string& status) {
    const std::string state = status.substr(0, status.find(':'));
    const ros::Time now = ros::Time::now();
    if (status == last_status_) return;
    if (state == last_state_ && (now - last_status_time_).toSec() < 1.0) return;
    last_status_ = status;
    last_state_ = state;
    last_status_time_ = now;
    std_msgs::String msg;
    msg.data = status;
    status_pub_.publish(msg);
  }

  GoToRoomNodeOptions options_;
  std::unique_ptr<RoomGoalPlanner> planner_;
  std::unique_ptr<GoToRoom> controller_;
  std::unique_ptr<FloorGoToRoom> floor_;  // ~route grid, once a map arrived
  tf2_ros::Buffer tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  ros::Publisher cmd_pub_, status_pub_, goal_pub_, path_pub_;
  ros::Subscriber request_sub_, scan_sub_, detections_sub_, map_sub_;
  ros::Timer watchdog_;
  std::mutex mutex_;
  std::optional<std::string> pending_;  // a request waiting for a pose
  std::string goal_frame_;              // frame of the active goal: global_frame_id or odom_frame_id
  std::optional<Reading> reading_;      // the last plate read (for eq. 15)
  ros::Time last_valid_scan_;
  std::string last_status_, last_state_;
  ros::Time last_status_time_;
};

}  // namespace doorplate_localization

PLUGINLIB_EXPORT_CLASS(doorplate_localization::GoToRoomNodelet, nodelet::Nodelet)

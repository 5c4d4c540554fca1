// GoToRoomNodelet: go to a room by number (paper Sec. 3.4, Fig. 8, eq. 15) as a thin nodelet over
// RoomGoalPlanner, PlanFromReading and GoToRoom (include/doorplate_localization/behaviour/). Subscribes
// go_to_room (std_msgs/String: "105", or "220@north" for one plate of a repeated number; a request replaces
// the current goal), scan and, with ~text_fallback, text_detections. Pose: tf map -> base_link (a localizer's);
// while it is missing a request waits (a warning names the frames) and nothing drives, unless a plate was read
// recently: then eq. 15 gives the goal in odom and the robot drives by odometry. Publishes cmd_vel ONLY while a
// goal is active (and one zero when it ends), so it idles beside another driver; ~status (latched: "idle",
// "waiting_for_pose: ...", "turning: ...", "driving: room 105, 3.20 m to go", "facing: ...", "arrived: ...",
// "refused: <reason>", "failed: <reason>"), ~goal (latched PoseStamped). Parameters: go_to_room_options.h.
// ~route grid (a whole floor): it subscribes map (latched by the localizer) and drives FloorGoToRoom, a path
// round corners ("following: ..."), latched on ~path; a request waits for the map and the map pose.
// ~building_file (several floors): the grids come from that file; a request waits until the localizer
// (amcl/floor, amcl/state) has converged, the search drive on meanwhile (~search_enable_service), then goes to
// the room, or to a lift's stop ("to_lift: ... take lift A from floor 2 to floor 3 ..."), waits for ride_lift
// ("waiting_for_lift: ..."), calls the localizer's global_localization and searches until it has converged on
// the room's floor ("localizing: ..."), then drives to the room (building_goal.h).
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>
#include <std_srvs/Empty.h>
#include <std_srvs/SetBool.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include "doorplate_localization/behaviour/plate_route.h"
#include "doorplate_localization/ros/map_conversions.h"
#include "doorplate_localization/ros/pose_conversions.h"
#include "doorplate_localization/ros/scan_conversions.h"
#include "doorplate_localization/ros/text_detection_conversions.h"
#include "doorplate_localization/ros/tf_lookup.h"
#include "background_calls.h"
#include "building_goal.h"
#include "go_to_room_conversions.h"
#include "go_to_room_options.h"

namespace doorplate_localization {

class GoToRoomNodelet : public nodelet::Nodelet {
 private:
  struct Reading {
    MatchedPlateReading plate;
    ros::Time stamp;
  };

  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    try {
      options_ = LoadGoToRoomOptions(pnh);
      planner_ = std::make_unique<RoomGoalPlanner>(options_.planner, options_.text_map, options_.text_map_file);
      controller_ = std::make_unique<GoToRoom>(options_.controller);
      if (options_.building) {
        building_ = std::make_unique<BuildingGoal>(BuildingRouteOptions{options_.floor.planner, options_.planner},
                                                   options_.building);
      }
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
    if (building_) {  // the localizer's floor and state (latched), and the lift rides
      for (const bool floor : {true, false}) {
        localizer_subs_.push_back(nh.subscribe<std_msgs::String>(
            floor ? "amcl/floor" : "amcl/state", 1,
            [this, floor](const std_msgs::String::ConstPtr& m) { OnLocalizer(floor, m->data); }));
      }
      ride_sub_ = nh.subscribe("ride_lift", 5, &GoToRoomNodelet::OnRide, this);
    }
    if (options_.route == "grid") {
      path_pub_ = pnh.advertise<nav_msgs::Path>("path", 1, /*latch=*/true);
      if (!building_) map_sub_ = nh.subscribe("map", 1, &GoToRoomNodelet::OnMap, this);
    } else if (options_.text_fallback) {
      detections_sub_ = nh.subscribe("text_detections", kTextDetectionsQueueSize, &GoToRoomNodelet::OnDetections, this);
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
    const std::string refusal = building_ ? building_->Start(msg->data) : planner_->Candidates(msg->data).refusal;
    if (!refusal.empty()) {
      Refuse(refusal, was_active);
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
    if (building_) return TryPlanInBuilding(map_pose);
    if (options_.route == "grid") return TryPlanOnGrid(map_pose, problem);
    RoomGoalResult result;
    if (map_pose) {
      result = planner_->Plan(*pending_, map_pose);
      goal_frame_ = options_.global_frame_id;
    } else if (reading_ && (ros::Time::now() - reading_->stamp).toSec() <= options_.reading_max_age_s) {
      result = PlanFromReading(*planner_, *pending_, reading_->plate);
      goal_frame_ = options_.odom_frame_id;
    } else {
      WaitForPose(*pending_, NoPose(options_.global_frame_id, problem) +
                                 (options_.text_fallback ? " and no plate read recently" : ""), false);
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
      WaitForPose(*pending_,
                  !floor_ ? "no map on " + map_sub_.getTopic() + " yet" : NoPose(options_.global_frame_id, problem),
                  false);
      return;
    }
    const RoomGoalResult result = planner_->Plan(*pending_, map_pose);
    pending_.reset();
    if (!result.goal) {
      Refuse(result.refusal, false);
      return;
    }
    StartOnGrid(*result.goal, *map_pose);
  }

  // floor_ on `goal` from `pose` (map frame), the goal and path published; false (status published) if refused.
  bool StartOnGrid(const RoomGoal& goal, const Pose2D& pose) {
    goal_frame_ = options_.global_frame_id;
    if (!floor_->Start(goal, pose)) {
      NODELET_ERROR("go to room %s", floor_->Status().c_str());
      PublishStatus(floor_->Status());
      return false;
    }
    const Pose2D& g = goal.pose;
    NODELET_INFO("going to room %s: goal (%.2f, %.2f, %.2f rad) in %s, path %.1f m%s%s", goal.room.c_str(), g.x_m,
                 g.y_m, g.theta_rad, goal_frame_.c_str(), floor_->first_plan_length_m(), goal.note.empty() ? "" : "; ",
                 goal.note.c_str());
    goal_pub_.publish(ToGoalPoseMsg(g, goal_frame_, ros::Time::now()));
    path_pub_.publish(ToPathMsg(floor_->path().waypoints, goal_frame_, ros::Time::now()));
    PublishStatus(floor_->Status());
    return true;
  }

  // TryPlan with ~building_file: search until the localizer has converged, then plan and drive the next leg.
  void TryPlanInBuilding(const std::optional<Pose2D>& map_pose) {
    if (!building_->TryStartLeg(map_pose)) {
      SetSearch(building_->searching());
      if (!building_->searching()) pending_.reset();  // refused or failed
      PublishStatus(building_->Status());
      return;
    }
    pending_.reset();
    SetSearch(false);
    NODELET_INFO("go to room %s", building_->Status().c_str());
    PublishStatus(building_->Status());  // the route: "to_lift: ... take lift A ..." or "to_room: ..."
    floor_ = std::make_unique<FloorGoToRoom>(options_.floor, options_.building->floors[building_->leg_floor()].grid);
    if (!StartOnGrid(building_->leg(), *map_pose)) building_->OnLegEnded(false, floor_->Status());
  }

  void OnLocalizer(bool floor, const std::string& value) {  // amcl/floor or amcl/state
    std::lock_guard<std::mutex> lock(mutex_);
    floor ? building_->SetLocalizerFloor(value) : building_->SetLocalizerState(value);
    if (pending_) TryPlan(ros::Time(0));
  }

  // ride_lift: the route's ride ends the wait; the localizer starts over (global_localization: the floor is
  // unknown again) and the robot searches until it has converged on the room's floor.
  void OnRide(const std_msgs::String::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::string problem;
    if (!building_->OnRide(msg->data, &problem)) {
      NODELET_INFO("%s: '%s': %s; ignored", ride_sub_.getTopic().c_str(), msg->data.c_str(), problem.c_str());
      return;
    }
    calls_.Post([this, service = getNodeHandle().resolveName("global_localization")] {
      std_srvs::Empty empty;
      if (!ros::service::call(service, empty)) NODELET_WARN("go to room: %s did not answer", service.c_str());
    });
    pending_ = building_->request();
    NODELET_INFO("go to room %s", building_->Status().c_str());
    TryPlan(ros::Time(0));
  }

  void SetSearch(bool on) {  // the search drive (~search_enable_service), called on a change only
    if (options_.search_enable_service.empty() || search_on_ == on) return;
    search_on_ = on;
    calls_.Post([this, on, service = getNodeHandle().resolveName(options_.search_enable_service)] {
      std_srvs::SetBool srv;
      srv.request.data = on;
      if (!ros::service::call(service, srv)) NODELET_WARN("go to room: %s did not answer", service.c_str());
    });
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
    std::optional<Pose2D> laser_in_base;
    if (problem.empty()) {
      laser_in_base = LookupPlanarPose(tf_buffer_, options_.base_frame_id, scan->header.frame_id, scan->header.stamp,
                                       options_.tf_timeout_s, &problem);
    }
    if (!problem.empty()) {
      NODELET_ERROR_THROTTLE(2.0, "%s: %s; not driving", scan_sub_.getTopic().c_str(), problem.c_str());
      if (Active()) cmd_pub_.publish(geometry_msgs::Twist());
      return;
    }
    const double yaw_in_base = laser_in_base->theta_rad;
    last_valid_scan_ = ros::Time::now();
    if (pending_) TryPlan(scan->header.stamp);
    const bool on_grid = floor_ && floor_->active();
    if (!on_grid && !controller_->active()) return;
    const std::optional<Pose2D> pose = LookupPose(goal_frame_, scan->header.stamp, &problem);
    if (!pose) {
      WaitForPose(on_grid ? floor_->goal().room : controller_->goal().room, NoPose(goal_frame_, problem), true);
      return;
    }
    if (on_grid) return StepOnGrid(*scan, yaw_in_base, *pose);
    const VelocityCommand cmd =
        controller_->Step(scan->ranges, scan->angle_min + yaw_in_base, scan->angle_increment, *pose,
                          scan->header.stamp.toSec());
    cmd_pub_.publish(ToTwistMsg(cmd));  // a zero command once the goal ends
    const std::string status = controller_->Status();
    if (controller_->state() == GoToRoomState::kFailed) NODELET_ERROR("go to room %s", status.c_str());
    if (controller_->state() == GoToRoomState::kArrived) NODELET_INFO("go to room %s", status.c_str());
    PublishStatus(status);
  }

  void StepOnGrid(const sensor_msgs::LaserScan& scan, double yaw_in_base, const Pose2D& pose) {
    const int replans = floor_->replans();
    const ros::Time& stamp = scan.header.stamp;
    const VelocityCommand cmd =
        floor_->Step(scan.ranges, scan.angle_min + yaw_in_base, scan.angle_increment, pose, stamp.toSec());
    cmd_pub_.publish(ToTwistMsg(cmd));  // a zero command once the goal ends
    if (floor_->replans() != replans) path_pub_.publish(ToPathMsg(floor_->path().waypoints, goal_frame_, stamp));
    const std::string status = floor_->Status();
    if (floor_->state() == FloorGoToRoomState::kFailed) NODELET_ERROR("go to room %s", status.c_str());
    if (floor_->state() == FloorGoToRoomState::kArrived) NODELET_INFO("go to room %s", status.c_str());
    if (building_ && !floor_->active()) {  // a building leg ended: wait for the lift, or the goal's end
      building_->OnLegEnded(floor_->state() == FloorGoToRoomState::kArrived, status);
      if (building_->Status() != status) NODELET_INFO("go to room %s", building_->Status().c_str());
      PublishStatus(building_->Status());
      return;
    }
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
      if (const auto camera = LookupTransform(tf_buffer_, options_.base_frame_id, msg->header.frame_id,
                                              msg->header.stamp, options_.tf_timeout_s, &problem)) {
        left = CameraLooksLeft(*camera);
        if (!left) problem = "camera frame '" + msg->header.frame_id + "' does not look sideways";
      }
      if (!odom || !left) {
        NODELET_WARN_THROTTLE(5.0, "%s: read '%s' but cannot use it for eq. 15: %s", detections_sub_.getTopic().c_str(),
                              text.c_str(), problem.c_str());
        continue;
      }
      reading_ = Reading{MatchedPlateReading{plates.front(), *odom, *left}, msg->header.stamp};
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

  // base_link in `frame` at `stamp` (0: the latest, without waiting); nullopt with `*problem` set when tf has none.
  std::optional<Pose2D> LookupPose(const std::string& frame, const ros::Time& stamp, std::string* problem) {
    const double wait_s = stamp.isZero() ? 0.0 : options_.tf_timeout_s;
    return LookupPlanarPose(tf_buffer_, frame, options_.base_frame_id, stamp, wait_s, problem);
  }

  std::string NoPose(const std::string& frame, const std::string& problem) const {
    return "no pose in '" + frame + "' (" + problem + ")";
  }

  // "waiting_for_pose: room R: <why>; not driving" on ~status and (throttled) the log; `stop`: a zero command.
  void WaitForPose(const std::string& room, const std::string& why, bool stop) {
    const std::string waiting = "waiting_for_pose: room " + room + ": " + why + "; not driving";
    NODELET_WARN_THROTTLE(5.0, "%s", waiting.c_str());
    if (stop) cmd_pub_.publish(geometry_msgs::Twist());
    PublishStatus(waiting);
  }

  void PublishStatus(const std::string& status) {  // on a change of state, else at most once a second
    if (!status_throttle_.Due(status, ros::Time::now().toSec())) return;
    std_msgs::String msg;
    msg.data = status;
    status_pub_.publish(msg);
  }

  GoToRoomNodeOptions options_;
  std::unique_ptr<RoomGoalPlanner> planner_;
  std::unique_ptr<GoToRoom> controller_;
  std::unique_ptr<FloorGoToRoom> floor_;  // ~route grid, once a map arrived (~building_file: the current leg)
  std::unique_ptr<BuildingGoal> building_;  // ~building_file
  tf2_ros::Buffer tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  ros::Publisher cmd_pub_, status_pub_, goal_pub_, path_pub_;
  ros::Subscriber request_sub_, scan_sub_, detections_sub_, map_sub_, ride_sub_;
  std::vector<ros::Subscriber> localizer_subs_;
  ros::Timer watchdog_;
  std::mutex mutex_;
  std::optional<std::string> pending_;  // a request waiting for a pose
  std::string goal_frame_;              // frame of the active goal: global_frame_id or odom_frame_id
  std::optional<Reading> reading_;      // the last plate read (for eq. 15)
  std::optional<bool> search_on_;       // the search drive as last set
  ros::Time last_valid_scan_;
  StatusThrottle status_throttle_;
  BackgroundCalls calls_;  // service calls to other nodelets (never from a callback); destroyed first
};

}  // namespace doorplate_localization

PLUGINLIB_EXPORT_CLASS(doorplate_localization::GoToRoomNodelet, nodelet::Nodelet)

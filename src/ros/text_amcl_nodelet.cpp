// TextAmclNodelet: Text AMCL behind amcl's ROS interface, so an amcl launch file works by changing the node
// type. Every callback is validate -> convert -> TextAmclSession (mcl/text_amcl_session.h: the one loop,
// also run by `doorplate_eval localize` and the soak) -> publish. Subscribes scan (sensor_msgs/LaserScan),
// initialpose (geometry_msgs/PoseWithCovarianceStamped), text_detections (TextDetectionArray) and, with
// ~use_map_topic, map (nav_msgs/OccupancyGrid); else it loads ~map_file (and republishes it latched on map)
// or calls the static_map service. Publishes amcl_pose (latched), particlecloud (latched, at most
// ~gui_publish_rate), ~state (latched std_msgs/String: waiting_for_map | tracking | converged |
// lost: <reason>), text_landmarks (latched MarkerArray) and tf global_frame -> odom_frame stamped scan stamp
// + ~transform_tolerance. Services: global_localization, request_nomotion_update (std_srvs/Empty),
// set_map (nav_msgs/SetMap). Odometry is the tf odom_frame -> base_frame at each scan's and each
// detection array's stamp (as amcl); the session orders, ranges and weighs the plate readings.
// Parameters: text_amcl_options.h, docs/parameters.md. Callbacks run on the nodelet's single-threaded
// queue; mutex_ guards the session against the services and timers all the same.
// Size: 411 lines, down from 446 when the loop moved into TextAmclSession; most of the rest is the tf and
// map-source plumbing (file, topic, static_map service), which the shared planar-tf helper of issue 16
// (item 2) is to take over.
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include <nav_msgs/GetMap.h>
#include <nav_msgs/SetMap.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <std_srvs/Empty.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/mcl/text_amcl_session.h"
#include "doorplate_localization/ros/amcl_conversions.h"
#include "doorplate_localization/ros/map_conversions.h"
#include "doorplate_localization/ros/pose_conversions.h"
#include "doorplate_localization/ros/scan_conversions.h"
#include "doorplate_localization/ros/text_detection_conversions.h"
#include "text_amcl_options.h"

namespace doorplate_localization {

class TextAmclNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    OccupancyGrid file_map;
    try {
      options_ = LoadTextAmclOptions(pnh);
      if (!options_.map_file.empty()) file_map = LoadOccupancyMap(options_.map_file);
    } catch (const MapFileError& e) {
      NODELET_FATAL("%s = '%s' cannot be used: %s", pnh.resolveName("map_file").c_str(), options_.map_file.c_str(),
                    e.what());
      throw;
    } catch (const std::exception& e) {
      NODELET_FATAL("%s", e.what());
      throw;
    }
    LoadTextMapFile();
    tf_broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>();
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(tf_buffer_);
    pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("amcl_pose", 2, /*latch=*/true);
    cloud_pub_ = nh.advertise<geometry_msgs::PoseArray>("particlecloud", 2, /*latch=*/true);
    markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("text_landmarks", 1, /*latch=*/true);
    state_pub_ = pnh.advertise<std_msgs::String>("state", 1, /*latch=*/true);
    PublishState("waiting_for_map");
    if (text_map_) markers_pub_.publish(ToTextLandmarkMarkers(*text_map_, options_.global_frame_id, ros::Time::now()));
    global_srv_ = nh.advertiseService("global_localization", &TextAmclNodelet::OnGlobalLocalization, this);
    nomotion_srv_ = nh.advertiseService("request_nomotion_update", &TextAmclNodelet::OnNoMotionUpdate, this);
    set_map_srv_ = nh.advertiseService("set_map", &TextAmclNodelet::OnSetMap, this);
    if (!options_.map_file.empty()) {
      map_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, /*latch=*/true);
      map_pub_.publish(ToOccupancyGridMsg(file_map, options_.global_frame_id, ros::Time::now()));
      std::lock_guard<std::mutex> lock(mutex_);
      if (!UseMap(file_map, options_.map_file)) {
        NODELET_FATAL("%s = '%s' cannot be used (see above)", pnh.resolveName("map_file").c_str(),
                      options_.map_file.c_str());
        throw std::runtime_error("unusable ~map_file " + options_.map_file);
      }
    } else if (options_.use_map_topic) {
      map_sub_ = nh.subscribe("map", 1, &TextAmclNodelet::OnMap, this);
    } else {
      map_timer_ = nh.createWallTimer(ros::WallDuration(1.0), &TextAmclNodelet::RequestStaticMap, this);
    }
    initial_pose_sub_ = nh.subscribe("initialpose", 2, &TextAmclNodelet::OnInitialPose, this);
    scan_sub_ = nh.subscribe("scan", 1, &TextAmclNodelet::OnScan, this);
    detections_sub_ = nh.subscribe("text_detections", 10, &TextAmclNodelet::OnDetections, this);
    if (options_.save_pose_rate_hz > 0.0) {
      save_timer_ = nh.createTimer(ros::Duration(1.0 / options_.save_pose_rate_hz), &TextAmclNodelet::SavePose, this);
    }
  }

  // ~text_map_file: missing or broken -> an error naming the file; the filter runs on the laser alone.
  void LoadTextMapFile() {
    if (!options_.session.setup.use_text) return;
    if (options_.text_map_file.empty()) {
      NODELET_WARN("%s is not set: localizing with the laser alone",
                   getPrivateNodeHandle().resolveName("text_map_file").c_str());
      return;
    }
    try {
      text_map_ = std::make_shared<const TextMap>(doorplate_localization::LoadTextMap(options_.text_map_file));
      NODELET_INFO("text amcl: %zu doorplates from %s", text_map_->landmarks.size(), options_.text_map_file.c_str());
      if (text_map_->frame_id != options_.global_frame_id) {
        NODELET_WARN("text amcl: %s: frame_id '%s' differs from global_frame_id '%s'; using it as %s",
                     options_.text_map_file.c_str(), text_map_->frame_id.c_str(), options_.global_frame_id.c_str(),
                     options_.global_frame_id.c_str());
      }
    } catch (const std::exception& e) {
      NODELET_ERROR("%s: %s; localizing with the laser alone",
                    getPrivateNodeHandle().resolveName("text_map_file").c_str(), e.what());
      text_map_.reset();
    }
  }

  // Starts a session on a new map at the initial pose (amcl: ~initial_pose_*, updated by initialpose and
  // ~save_pose_rate) or over the free space. Requires mutex_.
  bool UseMap(const OccupancyGrid& grid, const std::string& source) {
    std::unique_ptr<TextAmclSession> session;  // the running session stays if the new map cannot be used
    try {
      session = std::make_unique<TextAmclSession>(options_.session, grid, text_map_);
    } catch (const std::invalid_argument& e) {
      std::string problem = e.what();
      if (text_map_) {  // the map, or the text map with it? Without the text map:
        try {
          session = std::make_unique<TextAmclSession>(options_.session, grid, nullptr);
          NODELET_ERROR("%s cannot be used with the map from %s: %s; localizing with the laser alone",
                        options_.text_map_file.c_str(), source.c_str(), problem.c_str());
          text_map_.reset();
          markers_pub_.publish(ToTextLandmarkMarkers(TextMap(), options_.global_frame_id, ros::Time::now()));
        } catch (const std::invalid_argument& laser_only) {
          problem = laser_only.what();
        }
      }
      if (!session) {
        NODELET_ERROR("text amcl: the map from %s cannot be used: %s", source.c_str(), problem.c_str());
        return false;
      }
    }
    session_ = std::move(session);
    NODELET_INFO("text amcl: map %dx%d at %.3f m from %s, %s laser model, %s; %d particles %s", grid.width,
                 grid.height, grid.resolution_m, source.c_str(), ToString(options_.session.setup.laser_model_type),
                 text_map_ ? "with doorplates" : "laser only", options_.session.setup.filter.max_particles,
                 options_.session.start_with_global_localization ? "over the free space" : "at ~initial_pose_*");
    PublishFilter(ros::Time::now(), /*force_cloud=*/true);
    return true;
  }

  void OnMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (options_.first_map_only && session_) return;
    OccupancyGrid grid;
    const std::string problem = FromOccupancyGridMsg(*msg, &grid);
    if (!problem.empty()) {
      NODELET_ERROR_THROTTLE(5.0, "%s: %s; ignoring this map", map_sub_.getTopic().c_str(), problem.c_str());
      return;
    }
    UseMap(grid, map_sub_.getTopic());
  }

  // amcl's default map source: the static_map service, retried every second until it answers.
  void RequestStaticMap(const ros::WallTimerEvent&) {
    const std::string service = getNodeHandle().resolveName("static_map");
    nav_msgs::GetMap srv;
    if (!ros::service::exists(service, false) || !ros::service::call(service, srv)) {
      NODELET_WARN_THROTTLE(10.0, "text amcl: waiting for the %s service (or set ~map_file / ~use_map_topic)",
                            service.c_str());
      return;
    }
    OccupancyGrid grid;
    const std::string problem = FromOccupancyGridMsg(srv.response.map, &grid);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!problem.empty()) {
      NODELET_ERROR_THROTTLE(10.0, "%s: %s; asking again", service.c_str(), problem.c_str());
      return;
    }
    if (UseMap(grid, service)) map_timer_.stop();
  }

  bool OnSetMap(nav_msgs::SetMap::Request& req, nav_msgs::SetMap::Response& res) {
    std::lock_guard<std::mutex> lock(mutex_);
    OccupancyGrid grid;
    Pose2D mean;
    Eigen::Matrix3d covariance;
    std::string problem = FromOccupancyGridMsg(req.map, &grid);
    if (problem.empty()) problem = FromInitialPoseMsg(req.initial_pose, options_.global_frame_id, &mean, &covariance);
    if (!problem.empty()) {
      NODELET_ERROR("%s: %s; map not changed", set_map_srv_.getService().c_str(), problem.c_str());
      res.success = false;
      return true;
    }
    options_.session.initial_pose = mean;
    options_.session.initial_covariance = covariance;
    res.success = UseMap(grid, set_map_srv_.getService());
    return true;
  }

  bool OnGlobalLocalization(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!session_) {
      NODELET_WARN("%s: no map yet; ignored", global_srv_.getService().c_str());
      return true;
    }
    session_->GlobalLocalization();
    NODELET_INFO("text amcl: global localization: %zu particles over the free space", session_->particles().size());
    PublishFilter(ros::Time::now(), /*force_cloud=*/true);
    return true;
  }

  bool OnNoMotionUpdate(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (session_) session_->RequestNoMotionUpdate();
    return true;
  }

  void OnInitialPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    Pose2D mean;
    Eigen::Matrix3d covariance;
    const std::string problem = FromInitialPoseMsg(*msg, options_.global_frame_id, &mean, &covariance);
    if (!problem.empty()) {
      NODELET_WARN_THROTTLE(2.0, "%s: %s; ignored", initial_pose_sub_.getTopic().c_str(), problem.c_str());
      return;
    }
    options_.session.initial_pose = mean;  // also the start pose on the next map
    options_.session.initial_covariance = covariance;
    if (!session_) return;
    session_->Initialize(mean, covariance);
    NODELET_INFO("text amcl: initial pose (%.3f, %.3f, %.3f)", mean.x_m, mean.y_m, mean.theta_rad);
    PublishFilter(ros::Time::now(), /*force_cloud=*/true);
  }

  // validate -> tf (laser mount, odometry) -> convert -> session -> publish.
  void OnScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string& topic = scan_sub_.getTopic();
    const std::string problem = ValidateScan(*msg);
    if (!problem.empty()) {
      NODELET_WARN_THROTTLE(2.0, "%s: %s; scan ignored", topic.c_str(), problem.c_str());
      return;
    }
    if (!session_) {
      NODELET_WARN_THROTTLE(10.0, "%s: no map yet; scan ignored", topic.c_str());
      return;
    }
    Pose2D laser_in_base, base_in_odom;
    std::string tf_problem;
    if (!LookupPlanar(options_.base_frame_id, msg->header.frame_id, ros::Time(0), &laser_in_base, &tf_problem) ||
        !LookupPlanar(options_.odom_frame_id, options_.base_frame_id, msg->header.stamp, &base_in_odom,
                      &tf_problem)) {
      NODELET_WARN_THROTTLE(2.0, "%s: %s; scan ignored", topic.c_str(), tf_problem.c_str());
      return;
    }
    SessionUpdate update;
    try {
      update = session_->AddScan(msg->header.stamp.toSec(), base_in_odom, ToLocalizationScan(*msg, laser_in_base));
    } catch (const std::invalid_argument& e) {
      NODELET_WARN_THROTTLE(2.0, "%s: %s; scan ignored", topic.c_str(), e.what());
      return;
    }
    if (!update.scan_ignored_reason.empty()) {
      NODELET_WARN_THROTTLE(2.0, "%s: %s; scan ignored, continuing from it", topic.c_str(),
                            update.scan_ignored_reason.c_str());
    }
    ReportPlates(update, detections_sub_.getTopic());
    if (update.estimate_changed) PublishFilter(msg->header.stamp, /*force_cloud=*/!update.plates.empty());
    const std::optional<Pose2D>& map_to_odom = session_->MapToOdom();
    if (options_.tf_broadcast && map_to_odom) {
      tf_broadcaster_->sendTransform(ToTransformStampedMsg(*map_to_odom, options_.global_frame_id,
                                                           options_.odom_frame_id,
                                                           msg->header.stamp +
                                                               ros::Duration(options_.transform_tolerance_s)));
    }
  }

  // validate -> tf (camera yaw, odometry at the stamp) -> readings -> session -> publish.
  void OnDetections(const TextDetectionArray::ConstPtr& msg) {
    bool any = false;
    for (const TextDetection& d : msg->detections) any = any || IsPlateReport(d);
    if (!any) return;  // most images report no plate
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string& topic = detections_sub_.getTopic();
    if (!session_) return;
    if (!session_->has_text_map()) {
      NODELET_WARN_ONCE("%s: doorplate readings are ignored: no usable text map (~text_map_file, ~use_text)",
                        topic.c_str());
      return;
    }
    geometry_msgs::TransformStamped camera;
    try {
      camera = tf_buffer_.lookupTransform(options_.base_frame_id, msg->header.frame_id, msg->header.stamp,
                                          ros::Duration(options_.tf_timeout_s));
    } catch (const tf2::TransformException& e) {
      NODELET_WARN_THROTTLE(2.0, "%s: no tf from '%s' to %s: %s; detections ignored", topic.c_str(),
                            msg->header.frame_id.c_str(), options_.base_frame_id.c_str(), e.what());
      return;
    }
    CameraAxis axis;
    const std::string axis_problem = ToCameraAxis(camera.transform, &axis);
    if (!axis_problem.empty()) {
      NODELET_WARN_THROTTLE(2.0, "%s: camera frame '%s' in %s: %s; detections ignored", topic.c_str(),
                            msg->header.frame_id.c_str(), options_.base_frame_id.c_str(), axis_problem.c_str());
      return;
    }
    std::vector<std::string> problems;
    const std::vector<PlateReading> readings = ToPlateReadings(*msg, axis, &problems);
    for (const std::string& p : problems) NODELET_WARN_THROTTLE(2.0, "%s: %s; ignored", topic.c_str(), p.c_str());
    // The odometry at the readings' stamp (0: now), if tf has it yet; else the session keeps them until a
    // scan's odometry reaches it.
    const ros::Time stamp = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
    const double stamp_s = stamp.toSec();
    Pose2D base_in_odom;
    std::string odom_problem;
    if (LookupPlanar(options_.odom_frame_id, options_.base_frame_id, stamp, &base_in_odom, &odom_problem)) {
      ReportPlates(session_->AddOdometry(stamp_s, base_in_odom), topic);
    } else {
      NODELET_DEBUG("%s: %s; the readings wait for the next scan's odometry", topic.c_str(), odom_problem.c_str());
    }
    const SessionUpdate update = session_->AddPlates(stamp_s, readings);
    ReportPlates(update, topic);
    if (update.estimate_changed) PublishFilter(stamp, /*force_cloud=*/true);
  }

  // Logs what became of the plate readings one session call resolved (unknown rooms once each).
  void ReportPlates(const SessionUpdate& update, const std::string& topic) {
    for (const PlateReadingOutcome& p : update.plates) {
      if (p.disposition == PlateDisposition::kWeighed) {
        NODELET_INFO("text amcl: %s", DescribePlateOutcome(p).c_str());
      } else if (p.disposition == PlateDisposition::kUnknownRoomFirst) {
        NODELET_WARN("%s: %s (text map %s); its readings are ignored", topic.c_str(), DescribePlateOutcome(p).c_str(),
                     options_.text_map_file.c_str());
      } else if (p.disposition == PlateDisposition::kStale || p.disposition == PlateDisposition::kInvalid) {
        NODELET_WARN_THROTTLE(2.0, "%s: %s", topic.c_str(), DescribePlateOutcome(p).c_str());
      }
    }
  }

  // target_T_source at `stamp` as a planar pose. False (and *problem) if tf has none within tf_timeout.
  bool LookupPlanar(const std::string& target, const std::string& source, const ros::Time& stamp, Pose2D* pose,
                    std::string* problem) {
    try {
      *pose = ToPose2D(
          tf_buffer_.lookupTransform(target, source, stamp, ros::Duration(options_.tf_timeout_s)).transform);
      return true;
    } catch (const tf2::TransformException& e) {
      *problem = "no tf from '" + source + "' to '" + target + "': " + e.what();
      return false;
    } catch (const std::invalid_argument& e) {  // a non-finite transform
      *problem = "tf from '" + source + "' to '" + target + "': " + e.what();
      return false;
    }
  }

  // amcl_pose and ~state; particlecloud when forced or due by ~gui_publish_rate. Requires mutex_.
  void PublishFilter(const ros::Time& stamp, bool force_cloud) {
    if (!session_) return;
    const PoseEstimate& estimate = session_->Estimate();
    pose_pub_.publish(ToAmclPoseMsg(estimate, options_.global_frame_id, stamp));
    const ros::WallTime now = ros::WallTime::now();
    const double rate = options_.gui_publish_rate_hz;
    if (force_cloud || rate <= 0.0 || (now - last_cloud_time_).toSec() >= 1.0 / rate) {
      cloud_pub_.publish(ToParticleCloudMsg(session_->particles(), options_.global_frame_id, stamp));
      last_cloud_time_ = now;
    }
    const TextAmclStatus& status = session_->Status();
    PublishState(StateText(status.state, status.lost_reason));
  }

  void PublishState(const std::string& state) {
    if (state == last_state_) return;
    last_state_ = state;
    std_msgs::String msg;
    msg.data = state;
    state_pub_.publish(msg);
    NODELET_INFO("text amcl: %s", state.c_str());
  }

  // amcl's save_pose_rate: the last estimate becomes ~initial_pose_* / ~initial_cov_* on the server.
  void SavePose(const ros::TimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!session_) return;
    const PoseEstimate& e = session_->Estimate();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    pnh.setParam("initial_pose_x", e.pose.x_m);
    pnh.setParam("initial_pose_y", e.pose.y_m);
    pnh.setParam("initial_pose_a", e.pose.theta_rad);
    pnh.setParam("initial_cov_xx", e.covariance(0, 0));
    pnh.setParam("initial_cov_yy", e.covariance(1, 1));
    pnh.setParam("initial_cov_aa", e.covariance(2, 2));
  }

  TextAmclNodeOptions options_;
  std::shared_ptr<const TextMap> text_map_;  // null: laser only
  std::mutex mutex_;                         // guards everything below
  std::unique_ptr<TextAmclSession> session_; // null until a map arrives
  ros::WallTime last_cloud_time_;
  std::string last_state_;
  tf2_ros::Buffer tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> tf_broadcaster_;
  ros::Publisher pose_pub_, cloud_pub_, markers_pub_, state_pub_, map_pub_;
  ros::Subscriber scan_sub_, initial_pose_sub_, detections_sub_, map_sub_;
  ros::ServiceServer global_srv_, nomotion_srv_, set_map_srv_;
  ros::WallTimer map_timer_;
  ros::Timer save_timer_;
};

}  // namespace doorplate_localization

PLUGINLIB_EXPORT_CLASS(doorplate_localization::TextAmclNodelet, nodelet::Nodelet)

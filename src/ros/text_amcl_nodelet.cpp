// TextAmclNodelet: Text AMCL behind amcl's ROS interface (an amcl launch file works by changing the node type).
// Each callback: validate -> convert -> BuildingSession (mcl/building_session.h: a TextAmclSession per floor,
// the loop `doorplate_eval localize` and the soak run) -> publish. Subscribes scan, initialpose (on the current
// floor, which becomes certain), text_detections and, with ~use_map_topic, map; else it loads ~map_file
// (latched on map) or calls static_map. With ~building_file the floors' maps come from it (text_amcl_building.h);
// without, the map is a one-floor building. Publishes amcl_pose, particlecloud (at most ~gui_publish_rate),
// ~state (waiting_for_map | tracking | converged | lost: <reason>; converged only on a floor the plates made
// certain), ~floor (the current floor's id; a switch also latches that floor's grid on map when the nodelet
// owns the map, and its plates on text_landmarks), text_landmarks, all latched, and tf global_frame -> odom_frame
// stamped scan stamp + ~transform_tolerance. Services: global_localization (the floor becomes unknown too),
// request_nomotion_update, set_map (refused with ~building_file). Odometry: tf odom_frame -> base_frame at each
// scan's and detection array's stamp. Parameters: text_amcl_options.h. mutex_ guards the session.
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

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

#include "doorplate_localization/mcl/building_session.h"
#include "doorplate_localization/ros/amcl_conversions.h"
#include "doorplate_localization/ros/map_conversions.h"
#include "doorplate_localization/ros/pose_conversions.h"
#include "doorplate_localization/ros/scan_conversions.h"
#include "doorplate_localization/ros/text_detection_conversions.h"
#include "doorplate_localization/ros/tf_lookup.h"
#include "text_amcl_building.h"
#include "text_amcl_options.h"

namespace doorplate_localization {

class TextAmclNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    std::shared_ptr<const BuildingMaps> start_maps;
    try {
      options_ = LoadTextAmclOptions(pnh);  // loads ~building_file
      if (!options_.building) {             // one floor: ~text_map_file with the map the nodelet gets
        const LocalizerTextMap loaded = LoadLocalizerTextMap(options_, pnh.resolveName("text_map_file"));
        text_map_ = loaded.text_map;
        if (!loaded.problem.empty()) NODELET_ERROR("%s; localizing with the laser alone", loaded.problem.c_str());
        if (!loaded.warning.empty()) NODELET_WARN("text amcl: %s", loaded.warning.c_str());
      }
      start_maps = LocalizerStartMaps(options_, text_map_, pnh.resolveName("map_file"));
    } catch (const std::exception& e) {
      NODELET_FATAL("%s", e.what());
      throw;
    }
    tf_broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>();
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(tf_buffer_);
    pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("amcl_pose", 2, /*latch=*/true);
    cloud_pub_ = nh.advertise<geometry_msgs::PoseArray>("particlecloud", 2, /*latch=*/true);
    markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("text_landmarks", 1, /*latch=*/true);
    state_pub_ = pnh.advertise<std_msgs::String>("state", 1, /*latch=*/true);
    floor_pub_ = pnh.advertise<std_msgs::String>("floor", 1, /*latch=*/true);
    PublishState("waiting_for_map");
    if (text_map_) markers_pub_.publish(ToTextLandmarkMarkers(*text_map_, options_.global_frame_id, ros::Time::now()));
    global_srv_ = nh.advertiseService("global_localization", &TextAmclNodelet::OnGlobalLocalization, this);
    nomotion_srv_ = nh.advertiseService("request_nomotion_update", &TextAmclNodelet::OnNoMotionUpdate, this);
    set_map_srv_ = nh.advertiseService("set_map", &TextAmclNodelet::OnSetMap, this);
    if (start_maps) {  // ~building_file or ~map_file: the nodelet owns the map and latches it on map
      map_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, /*latch=*/true);
      const std::string param = pnh.resolveName(options_.building ? "building_file" : "map_file");
      const std::string& file = options_.building ? options_.building_file : options_.map_file;
      std::lock_guard<std::mutex> lock(mutex_);
      if (!UseMaps(start_maps, file)) {
        NODELET_FATAL("%s = '%s' cannot be used (see above)", param.c_str(), file.c_str());
        throw std::runtime_error("unusable " + param + " " + file);
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

  // A session on new maps (the building's, or a map the nodelet got with text_map_) at ~initial_pose_* or over
  // the free space; the running session stays if the maps cannot be used. Requires mutex_.
  bool UseMaps(const std::shared_ptr<const BuildingMaps>& maps, const std::string& source) {
    std::unique_ptr<BuildingSession> session;
    std::string text_problem;
    try {
      session = StartBuildingSession(ToBuildingSessionOptions(options_), maps, &text_problem);
    } catch (const std::invalid_argument& e) {
      NODELET_ERROR("text amcl: the map from %s cannot be used: %s", source.c_str(), e.what());
      return false;
    }
    if (!text_problem.empty()) {
      NODELET_ERROR("%s cannot be used with the map from %s: %s; localizing with the laser alone",
                    options_.text_map_file.c_str(), source.c_str(), text_problem.c_str());
      text_map_.reset();
    }
    session_ = std::move(session);
    const BuildingSession& b = *session_;
    const OccupancyGrid& grid = b.maps().floors[static_cast<size_t>(b.floor())].grid;
    const TextAmclSessionOptions& o = options_.session;
    NODELET_INFO("text amcl: map %dx%d at %.3f m from %s (floor '%s' of %zu%s), %s laser model, %s; %d particles %s",
                 grid.width, grid.height, grid.resolution_m, source.c_str(), b.floor_id().c_str(),
                 b.maps().floors.size(), b.floor_certain() ? "" : ", until the plates decide",
                 ToString(o.setup.laser_model_type), b.session().has_text_map() ? "with doorplates" : "laser only",
                 o.setup.filter.max_particles, o.start_with_global_localization ? "globally" : "at ~initial_pose_*");
    PublishFloor(/*new_maps=*/true);
    PublishFilter(ros::Time::now(), /*force_cloud=*/true);
    return true;
  }

  // ~floor, and the floor's grid on map (when the nodelet owns the map) and its plates on text_landmarks: for
  // new maps, and when the session has switched floors (logged). Requires mutex_ and a session.
  void PublishFloor(bool new_maps) {
    const std::string& id = session_->floor_id();
    if (!new_maps && id == floor_id_) return;
    if (!new_maps) {
      NODELET_INFO("text amcl: floor '%s' -> '%s' (the plates read; belief %.3f)", floor_id_.c_str(), id.c_str(),
                   session_->belief().probabilities()[static_cast<size_t>(session_->floor())]);
    }
    floor_id_ = id;
    const FloorMaps& floor = session_->maps().floors[static_cast<size_t>(session_->floor())];
    const ros::Time now = ros::Time::now();
    if (map_pub_) map_pub_.publish(ToOccupancyGridMsg(floor.grid, options_.global_frame_id, now));
    markers_pub_.publish(
        ToTextLandmarkMarkers(floor.text_map ? *floor.text_map : TextMap(), options_.global_frame_id, now));
    std_msgs::String msg;
    msg.data = id;
    floor_pub_.publish(msg);
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
    UseMaps(OneFloorBuilding(grid, text_map_, options_.start_floor), map_sub_.getTopic());
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
    if (UseMaps(OneFloorBuilding(grid, text_map_, options_.start_floor), service)) map_timer_.stop();
  }

  bool OnSetMap(nav_msgs::SetMap::Request& req, nav_msgs::SetMap::Response& res) {
    std::lock_guard<std::mutex> lock(mutex_);
    OccupancyGrid grid;
    Pose2D mean;
    Eigen::Matrix3d covariance;
    std::string problem = options_.building ? "the floors' maps come from " + options_.building_file : "";
    if (problem.empty()) problem = FromOccupancyGridMsg(req.map, &grid);
    if (problem.empty()) problem = FromInitialPoseMsg(req.initial_pose, options_.global_frame_id, &mean, &covariance);
    if (!problem.empty()) {
      NODELET_ERROR("%s: %s; map not changed", set_map_srv_.getService().c_str(), problem.c_str());
      res.success = false;
      return true;
    }
    options_.session.initial_pose = mean;
    options_.session.initial_covariance = covariance;
    res.success = UseMaps(OneFloorBuilding(grid, text_map_, options_.start_floor), set_map_srv_.getService());
    return true;
  }

  bool OnGlobalLocalization(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!session_) {
      NODELET_WARN("%s: no map yet; ignored", global_srv_.getService().c_str());
      return true;
    }
    session_->GlobalLocalization();
    NODELET_INFO("text amcl: global localization on floor '%s'%s", session_->floor_id().c_str(),
                 session_->floor_certain() ? "" : "; the floor is unknown until the plates decide");
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
    session_->Initialize(session_->floor(), mean, covariance);
    NODELET_INFO("text amcl: initial pose (%.3f, %.3f, %.3f) on floor '%s'", mean.x_m, mean.y_m, mean.theta_rad,
                 session_->floor_id().c_str());
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
    std::string tf_problem;
    const std::optional<Pose2D> laser_in_base = LookupPlanarPose(tf_buffer_, options_.base_frame_id,
                                                                 msg->header.frame_id, ros::Time(0),
                                                                 options_.tf_timeout_s, &tf_problem);
    const std::optional<Pose2D> base_in_odom =
        laser_in_base ? LookupPlanarPose(tf_buffer_, options_.odom_frame_id, options_.base_frame_id,
                                         msg->header.stamp, options_.tf_timeout_s, &tf_problem)
                      : std::nullopt;
    if (!base_in_odom) {
      NODELET_WARN_THROTTLE(2.0, "%s: %s; scan ignored", topic.c_str(), tf_problem.c_str());
      return;
    }
    SessionUpdate update;
    try {
      update = session_->AddScan(msg->header.stamp.toSec(), *base_in_odom, ToLocalizationScan(*msg, *laser_in_base));
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
      const ros::Time stamp = msg->header.stamp + ros::Duration(options_.transform_tolerance_s);
      tf_broadcaster_->sendTransform(
          ToTransformStampedMsg(*map_to_odom, options_.global_frame_id, options_.odom_frame_id, stamp));
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
    if (!session_->session().has_text_map()) {
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
    std::string odom_problem;
    const std::optional<Pose2D> base_in_odom = LookupPlanarPose(tf_buffer_, options_.odom_frame_id,
                                                                options_.base_frame_id, stamp,
                                                                options_.tf_timeout_s, &odom_problem);
    if (base_in_odom) {
      ReportPlates(session_->AddOdometry(stamp_s, *base_in_odom), topic);
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
        NODELET_WARN("%s: %s (text map of floor '%s': %s); its readings are ignored", topic.c_str(),
                     DescribePlateOutcome(p).c_str(), session_->floor_id().c_str(),
                     (options_.building ? options_.building_file : options_.text_map_file).c_str());
      } else if (p.disposition == PlateDisposition::kStale || p.disposition == PlateDisposition::kInvalid) {
        NODELET_WARN_THROTTLE(2.0, "%s: %s", topic.c_str(), DescribePlateOutcome(p).c_str());
      }
    }
  }

  // amcl_pose and ~state (and the floor, if it changed); particlecloud when forced or due by
  // ~gui_publish_rate. Requires mutex_.
  void PublishFilter(const ros::Time& stamp, bool force_cloud) {
    if (!session_) return;
    PublishFloor(/*new_maps=*/false);
    const PoseEstimate& estimate = session_->Estimate();
    pose_pub_.publish(ToAmclPoseMsg(estimate, options_.global_frame_id, stamp));
    const ros::WallTime now = ros::WallTime::now();
    const double rate = options_.gui_publish_rate_hz;
    if (force_cloud || rate <= 0.0 || (now - last_cloud_time_).toSec() >= 1.0 / rate) {
      cloud_pub_.publish(ToParticleCloudMsg(session_->session().particles(), options_.global_frame_id, stamp));
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
    const std::pair<const char*, double> saved[] = {
        {"initial_pose_x", e.pose.x_m},         {"initial_pose_y", e.pose.y_m},
        {"initial_pose_a", e.pose.theta_rad},   {"initial_cov_xx", e.covariance(0, 0)},
        {"initial_cov_yy", e.covariance(1, 1)}, {"initial_cov_aa", e.covariance(2, 2)}};
    for (const auto& [name, value] : saved) getPrivateNodeHandle().setParam(name, value);
  }

  TextAmclNodeOptions options_;
  std::shared_ptr<const TextMap> text_map_;   // one floor: ~text_map_file (null: laser only)
  std::mutex mutex_;                          // guards everything below
  std::unique_ptr<BuildingSession> session_;  // null until a map arrives
  ros::WallTime last_cloud_time_;
  std::string last_state_, floor_id_;         // as last published
  tf2_ros::Buffer tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> tf_broadcaster_;
  ros::Publisher pose_pub_, cloud_pub_, markers_pub_, state_pub_, floor_pub_, map_pub_;
  ros::Subscriber scan_sub_, initial_pose_sub_, detections_sub_, map_sub_;
  ros::ServiceServer global_srv_, nomotion_srv_, set_map_srv_;
  ros::WallTimer map_timer_;
  ros::Timer save_timer_;
};

}  // namespace doorplate_localization

PLUGINLIB_EXPORT_CLASS(doorplate_localization::TextAmclNodelet, nodelet::Nodelet)

// TextAmclNodelet: Text AMCL behind amcl's ROS interface (an amcl launch file works by changing the node type).
// Each callback: validate -> convert -> BuildingSession (mcl/building_session.h: a TextAmclSession per floor,
// the loop `doorplate_eval localize` and the soak run) -> publish. Subscribes scan, initialpose (on the current
// floor, which becomes certain), text_detections and, with ~use_map_topic, map; else it loads ~map_file
// (latched on map) or calls static_map. With ~building_file the floors' maps come from it (text_amcl_building.h);
// without, the map is a one-floor building. Publishes amcl_pose, particlecloud (at most ~gui_publish_rate),
// ~state (below; converged only on a floor the plates made certain), ~floor (the current floor's id; a switch
// also latches that floor's grid on map when the nodelet owns the map, and its plates on text_landmarks),
// text_landmarks, all latched, and tf global_frame -> odom_frame stamped scan stamp + ~transform_tolerance. Services: global_localization (the floor becomes unknown too;
// queued until a map is in force), request_nomotion_update, set_map (refused with ~building_file; always
// starts at its initial_pose). Odometry: tf odom_frame -> base_frame at each scan's stamp (scans wait for it in
// a tf2 message filter, scan_tf_filter.h, as amcl's) and detection array's. Parameters: text_amcl_options.h.
//
// Requests go through LocalizerCore (text_amcl_building.h): a refused map (set_map, the map topic,
// static_map) leaves the session, the latched map and ~state as they were, and set_map answers success
// false with the reason logged. ~state is LocalizerCore's (waiting_for_map | waiting_for_scan | tracking |
// converged | lost: <reason> | error: <what>): converged only while scans are being taken and estimates
// published. /diagnostics (diagnostic_msgs/DiagnosticArray, 1 Hz ROS time): state, map in force, scan rate,
// scans dropped, odometry tf age, plates used, the last error (amcl_conversions.h's ToDiagnosticStatus). amcl_pose is
// published after filter updates (scans, plates), not at a (re)start, as amcl; its covariance is the whole
// particle set's (amcl's). mutex_ guards the core.
// Over 400 lines: one callback per amcl interface (3 services, 4 subscriptions, 3 timers) and their logging;
// the rules live in LocalizerCore and the message conversions, which have their own tests.
#include <algorithm>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
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

#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/mcl/building_session.h"
#include "doorplate_localization/ros/amcl_conversions.h"
#include "doorplate_localization/ros/map_conversions.h"
#include "doorplate_localization/ros/pose_conversions.h"
#include "doorplate_localization/ros/text_detection_conversions.h"
#include "doorplate_localization/ros/tf_lookup.h"
#include "scan_tf_filter.h"
#include "text_amcl_building.h"
#include "text_amcl_options.h"

namespace doorplate_localization {

class TextAmclNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    std::shared_ptr<const BuildingMaps> start_maps;
    std::shared_ptr<const TextMap> text_map;  // one floor: ~text_map_file (null: laser only)
    try {
      options_ = LoadTextAmclOptions(pnh);  // loads ~building_file
      if (!options_.building) {             // one floor: ~text_map_file with the map the nodelet gets
        const LocalizerTextMap loaded = LoadLocalizerTextMap(options_, pnh.resolveName("text_map_file"));
        text_map = loaded.text_map;
        if (!loaded.problem.empty()) NODELET_ERROR("%s; localizing with the laser alone", loaded.problem.c_str());
        if (!loaded.warning.empty()) NODELET_WARN("text amcl: %s", loaded.warning.c_str());
      }
      start_maps = LocalizerStartMaps(options_, text_map, pnh.resolveName("map_file"));
    } catch (const std::exception& e) {
      NODELET_FATAL("%s", e.what());
      throw;
    }
    core_ = std::make_unique<LocalizerCore>(options_, text_map);
    tf_broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>();
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(tf_buffer_);
    pose_pub_ = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("amcl_pose", 2, /*latch=*/true);
    cloud_pub_ = nh.advertise<geometry_msgs::PoseArray>("particlecloud", 2, /*latch=*/true);
    markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("text_landmarks", 1, /*latch=*/true);
    state_pub_ = pnh.advertise<std_msgs::String>("state", 1, /*latch=*/true);
    floor_pub_ = pnh.advertise<std_msgs::String>("floor", 1, /*latch=*/true);
    diagnostics_pub_ = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 1);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      PublishState();
    }
    if (text_map) markers_pub_.publish(ToTextLandmarkMarkers(*text_map, options_.global_frame_id, ros::Time::now()));
    global_srv_ = nh.advertiseService("global_localization", &TextAmclNodelet::OnGlobalLocalization, this);
    nomotion_srv_ = nh.advertiseService("request_nomotion_update", &TextAmclNodelet::OnNoMotionUpdate, this);
    set_map_srv_ = nh.advertiseService("set_map", &TextAmclNodelet::OnSetMap, this);
    if (start_maps) {  // ~building_file or ~map_file: the nodelet owns the map and latches it on map
      map_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, /*latch=*/true);
      const std::string param = pnh.resolveName(options_.building ? "building_file" : "map_file");
      const std::string& file = options_.building ? options_.building_file : options_.map_file;
      std::lock_guard<std::mutex> lock(mutex_);
      if (!UseMaps([&] { return core_->UseMaps(start_maps, file); }, file)) {
        NODELET_FATAL("%s = '%s' cannot be used (see above)", param.c_str(), file.c_str());
        throw std::runtime_error("unusable " + param + " " + file);
      }
    } else if (options_.use_map_topic) {
      map_sub_ = nh.subscribe("map", 1, &TextAmclNodelet::OnMap, this);
    } else {
      map_timer_ = nh.createWallTimer(ros::WallDuration(1.0), &TextAmclNodelet::RequestStaticMap, this);
    }
    initial_pose_sub_ = nh.subscribe("initialpose", 2, &TextAmclNodelet::OnInitialPose, this);
    scan_filter_ = std::make_unique<ScanTfFilter>(tf_buffer_, options_.odom_frame_id, kScanTfQueueSize,
        nh.getCallbackQueue(), [this](const auto& m) { OnScan(m); }, [this](const auto&, const auto& why, bool broken) {
          std::lock_guard<std::mutex> lock(mutex_);
          ScanDropped(why, broken);
        });
    scan_filter_->Subscribe(nh, "scan");
    detections_sub_ = nh.subscribe("text_detections", kTextDetectionsQueueSize, &TextAmclNodelet::OnDetections, this);
    if (options_.save_pose_rate_hz > 0.0) {
      save_timer_ = nh.createTimer(ros::Duration(1.0 / options_.save_pose_rate_hz), &TextAmclNodelet::SavePose, this);
    }
    health_timer_ = nh.createTimer(ros::Duration(1.0), &TextAmclNodelet::OnHealthTimer, this);
  }

  // Applies a new map through `use` (a LocalizerCore::UseMaps / UseGrid call) and, if it was taken, publishes
  // what changed; if refused, logs why: the session, the latched map and ~state stay as they were. Returns
  // whether the map is now in force. Requires mutex_.
  template <typename Use>
  bool UseMaps(const Use& use, const std::string& source) {
    const LocalizerCore::MapChange change = use();
    if (!change.used) {
      NODELET_ERROR("text amcl: the map from %s is refused: %s; %s", source.c_str(), change.problem.c_str(),
                    core_->has_session() ? ("the map in force (" + core_->map_in_force() + ") is kept").c_str()
                                         : "still waiting for a usable map");
      return false;
    }
    if (!change.text_problem.empty()) {
      NODELET_ERROR("%s cannot be used with the map from %s: %s; localizing with the laser alone on it",
                    options_.text_map_file.c_str(), source.c_str(), change.text_problem.c_str());
    }
    const BuildingSession& b = core_->session();
    const OccupancyGrid& grid = b.maps().floors[static_cast<size_t>(b.floor())].grid;
    const TextAmclSessionOptions& o = options_.session;
    NODELET_INFO("text amcl: map %dx%d at %.3f m from %s (floor '%s' of %zu%s), %s laser model, %s; %d particles %s",
                 grid.width, grid.height, grid.resolution_m, source.c_str(), b.floor_id().c_str(),
                 b.maps().floors.size(), b.floor_certain() ? "" : ", until the plates decide",
                 ToString(o.setup.laser_model_type), b.session().has_text_map() ? "with doorplates" : "laser only",
                 o.setup.filter.max_particles,
                 change.ran_queued_global_localization ? "globally (the queued global_localization request)"
                 : o.start_with_global_localization    ? "globally"
                                                       : "at the start pose");
    PublishFloor(/*new_maps=*/true);
    PublishRestart();
    return true;
  }

  // ~floor, and the floor's grid on map (when the nodelet owns the map) and its plates on text_landmarks: for
  // new maps, and when the session has switched floors (logged). Requires mutex_ and a session.
  void PublishFloor(bool new_maps) {
    const BuildingSession& session = core_->session();
    const std::string& id = session.floor_id();
    if (!new_maps && id == floor_id_) return;
    if (!new_maps) {
      NODELET_INFO("text amcl: floor '%s' -> '%s' (the plates read; belief %.3f)", floor_id_.c_str(), id.c_str(),
                   session.belief().probabilities()[static_cast<size_t>(session.floor())]);
    }
    floor_id_ = id;
    const FloorMaps& floor = session.maps().floors[static_cast<size_t>(session.floor())];
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
    if (options_.first_map_only && core_->has_session()) return;
    const std::string& topic = map_sub_.getTopic();
    OccupancyGrid grid;
    const std::string problem = FromOccupancyGridMsg(*msg, &grid);
    if (!problem.empty()) {
      NODELET_ERROR_THROTTLE(5.0, "%s: %s; ignoring this map%s", topic.c_str(), problem.c_str(),
                             core_->has_session() ? ", the map in force is kept" : "");
      return;
    }
    UseMaps([&] { return core_->UseGrid(grid, topic); }, topic);
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
    if (UseMaps([&] { return core_->UseGrid(grid, service); }, service)) map_timer_.stop();
  }

  // amcl's set_map: the map and the pose to start at. Validated whole before anything changes; refused: success
  // false, the reason logged, the map in force kept.
  bool OnSetMap(nav_msgs::SetMap::Request& req, nav_msgs::SetMap::Response& res) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string& service = set_map_srv_.getService();
    OccupancyGrid grid;
    StartPose start;
    std::string problem = options_.building ? "the floors' maps come from " + options_.building_file : "";
    if (problem.empty()) problem = FromOccupancyGridMsg(req.map, &grid);
    if (problem.empty()) {
      problem = FromInitialPoseMsg(req.initial_pose, options_.global_frame_id, &start.mean, &start.covariance);
      if (!problem.empty()) problem = "initial_pose: " + problem;
    }
    if (!problem.empty()) {
      NODELET_ERROR("%s: %s; map not changed%s", service.c_str(), problem.c_str(),
                    core_->has_session() ? ", the map in force is kept" : "");
      res.success = false;
      return true;
    }
    const bool was_queued = core_->global_localization_queued();
    res.success = UseMaps([&] { return core_->UseGrid(grid, service, start); }, service);
    if (res.success && was_queued) {
      NODELET_INFO("%s: the queued global_localization request is cancelled: set_map gave a start pose",
                   service.c_str());
    }
    return true;
  }

  bool OnGlobalLocalization(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!core_->GlobalLocalization()) {
      NODELET_WARN("%s: no map in force yet: queued; the first map used will start with global localization",
                   global_srv_.getService().c_str());
      PublishState();
      return true;
    }
    const BuildingSession& session = core_->session();
    NODELET_INFO("text amcl: global localization on floor '%s'%s", session.floor_id().c_str(),
                 session.floor_certain() ? "" : "; the floor is unknown until the plates decide");
    PublishRestart();
    return true;
  }

  bool OnNoMotionUpdate(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (core_->has_session()) core_->session().RequestNoMotionUpdate();
    return true;
  }

  void OnInitialPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string& topic = initial_pose_sub_.getTopic();
    StartPose pose;
    std::string problem = FromInitialPoseMsg(*msg, options_.global_frame_id, &pose.mean, &pose.covariance);
    const bool was_queued = core_->global_localization_queued();
    if (problem.empty()) {
      try {
        core_->InitialPose(pose);  // restarts the session there, or is the start pose on the next map
      } catch (const std::exception& e) {
        problem = e.what();
      }
    }
    if (!problem.empty()) {
      NODELET_WARN_THROTTLE(2.0, "%s: %s; ignored", topic.c_str(), problem.c_str());
      return;
    }
    if (was_queued) NODELET_INFO("%s: the queued global_localization request is cancelled", topic.c_str());
    if (!core_->has_session()) return;
    NODELET_INFO("text amcl: initial pose (%.3f, %.3f, %.3f) on floor '%s'", pose.mean.x_m, pose.mean.y_m,
                 pose.mean.theta_rad, core_->session().floor_id().c_str());
    PublishRestart();
  }

  // A scan not taken: a throttled error (broken) or warning naming the topic, counted. Requires mutex_.
  void ScanDropped(const std::string& why, bool broken) {
    core_->ScanDropped(why);
    if (broken) NODELET_ERROR_THROTTLE(2.0, "%s: %s; scan ignored", scan_filter_->topic().c_str(), why.c_str());
    else NODELET_WARN_THROTTLE(2.0, "%s: %s; scan ignored", scan_filter_->topic().c_str(), why.c_str());
  }

  // A valid scan whose odometry tf has (scan_filter_) -> tf (laser mount, odometry) -> convert -> session -> publish.
  void OnScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string& topic = scan_filter_->topic();
    if (!core_->has_session()) {
      NODELET_WARN_THROTTLE(10.0, "%s: no map yet; scan ignored", topic.c_str());
      return;
    }
    std::string tf_problem;
    const std::optional<ScanPoses> tf =
        LookupScanPoses(tf_buffer_, options_.odom_frame_id, options_.base_frame_id, *msg, &tf_problem);
    if (!tf) return ScanDropped(tf_problem, /*broken=*/false);
    BuildingSession& session = core_->session();
    SessionUpdate update;
    try {
      update = session.AddScan(msg->header.stamp.toSec(), tf->base_in_odom,
                               ToLocalizationScan(*msg, tf->laser_in_base));
    } catch (const std::invalid_argument& e) {  // the scan (nothing changed)
      return ScanDropped(e.what(), /*broken=*/true);
    } catch (const std::exception& e) {  // the session: no estimate until it takes a scan again
      return Failed(topic, e.what());
    }
    core_->ScanTaken(ros::Time::now().toSec());
    ++scans_since_health_;
    if (!update.scan_ignored_reason.empty()) {
      NODELET_WARN_THROTTLE(2.0, "%s: %s; scan ignored, continuing from it", topic.c_str(),
                            update.scan_ignored_reason.c_str());
    }
    ReportPlates(update, detections_sub_.getTopic());
    if (update.estimate_changed) {
      PublishFilter(msg->header.stamp, /*force_cloud=*/!update.plates.empty());
    } else {
      PublishState();  // e.g. waiting_for_scan -> the filter's state
    }
    const std::optional<Pose2D>& map_to_odom = session.MapToOdom();
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
    if (!core_->has_session()) return;
    BuildingSession& session = core_->session();
    if (!session.session().has_text_map()) {
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
                            limits::TruncateForLog(msg->header.frame_id).c_str(), options_.base_frame_id.c_str(),
                            e.what());
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
    try {
      if (base_in_odom) {
        ReportPlates(session.AddOdometry(stamp_s, *base_in_odom), topic);
      } else {
        NODELET_DEBUG("%s: %s; the readings wait for the next scan's odometry", topic.c_str(), odom_problem.c_str());
      }
      const SessionUpdate update = session.AddPlates(stamp_s, readings);
      ReportPlates(update, topic);
      if (update.estimate_changed) PublishFilter(stamp, /*force_cloud=*/true);
    } catch (const std::exception& e) {
      Failed(topic, e.what());
    }
  }

  // The session threw while handling `topic`: logged, ~state says error until it takes a scan again.
  // Requires mutex_.
  void Failed(const std::string& topic, const std::string& what) {
    NODELET_ERROR_THROTTLE(2.0, "%s: the localizer failed: %s; no estimate until it takes a scan again",
                           topic.c_str(), what.c_str());
    core_->Failed(what);
    PublishState();
  }

  // Logs what became of the plate readings one session call resolved (unknown rooms once each).
  void ReportPlates(const SessionUpdate& update, const std::string& topic) {
    for (const PlateReadingOutcome& p : update.plates) {
      if (p.disposition == PlateDisposition::kWeighed) {
        NODELET_INFO("text amcl: %s", DescribePlateOutcome(p).c_str());
      } else if (p.disposition == PlateDisposition::kUnknownRoomFirst) {
        NODELET_WARN("%s: %s (text map of floor '%s': %s); its readings are ignored", topic.c_str(),
                     DescribePlateOutcome(p).c_str(), core_->session().floor_id().c_str(),
                     (options_.building ? options_.building_file : options_.text_map_file).c_str());
      } else if (p.disposition == PlateDisposition::kStale || p.disposition == PlateDisposition::kInvalid) {
        NODELET_WARN_THROTTLE(2.0, "%s: %s", topic.c_str(), DescribePlateOutcome(p).c_str());
      }
    }
  }

  // After a (re)start (a new map, initialpose, global_localization): the new particle cloud and ~state (now
  // waiting_for_scan); amcl_pose waits for the first update, as amcl's. Requires mutex_ and a session.
  void PublishRestart() {
    PublishFloor(/*new_maps=*/false);
    cloud_pub_.publish(ToParticleCloudMsg(core_->session().session().particles(), options_.global_frame_id,
                                          ros::Time::now()));
    last_cloud_time_ = ros::WallTime::now();
    PublishState();
  }

  // amcl_pose and ~state (and the floor, if it changed); particlecloud when forced or due by
  // ~gui_publish_rate. Requires mutex_ and a session.
  void PublishFilter(const ros::Time& stamp, bool force_cloud) {
    PublishFloor(/*new_maps=*/false);
    const BuildingSession& session = core_->session();
    pose_pub_.publish(ToAmclPoseMsg(session.Estimate(), options_.global_frame_id, stamp));
    const ros::WallTime now = ros::WallTime::now();
    const double rate = options_.gui_publish_rate_hz;
    if (force_cloud || rate <= 0.0 || (now - last_cloud_time_).toSec() >= 1.0 / rate) {
      cloud_pub_.publish(ToParticleCloudMsg(session.session().particles(), options_.global_frame_id, stamp));
      last_cloud_time_ = now;
    }
    PublishState();
  }

  // ~state as LocalizerCore says it now (published and logged when it changed). Requires mutex_.
  void PublishState() {
    const std::string state = core_->State(ros::Time::now().toSec());
    if (state == last_state_) return;
    last_state_ = state;
    std_msgs::String msg;
    msg.data = state;
    state_pub_.publish(msg);
    NODELET_INFO("text amcl: %s", state.c_str());
  }

  // 1 Hz: ~state (a scan timeout shows here) and /diagnostics.
  void OnHealthTimer(const ros::TimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    const ros::Time now = ros::Time::now();
    PublishState();
    LocalizerHealth health = core_->Health(now.toSec());
    const double elapsed_s = last_health_time_.isZero() ? 0.0 : (now - last_health_time_).toSec();
    health.scan_rate_hz = elapsed_s > 0.0 ? scans_since_health_ / elapsed_s : 0.0;
    scans_since_health_ = 0;
    last_health_time_ = now;
    try {
      const ros::Time latest =
          tf_buffer_.lookupTransform(options_.odom_frame_id, options_.base_frame_id, ros::Time(0)).header.stamp;
      health.tf_age_s = std::max(0.0, (now - latest).toSec());
    } catch (const tf2::TransformException&) {
      health.tf_age_s = -1.0;
    }
    diagnostic_msgs::DiagnosticArray array;
    array.header.stamp = now;
    array.status.push_back(ToDiagnosticStatus(health, getName() + ": localization", getName()));
    diagnostics_pub_.publish(array);
  }

  // amcl's save_pose_rate: the last estimate becomes ~initial_pose_* / ~initial_cov_* on the server (while
  // estimates are being published only).
  void SavePose(const ros::TimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!core_->has_session()) return;
    const std::string state = core_->State(ros::Time::now().toSec());
    if (state != "tracking" && state != "converged") return;
    const PoseEstimate& e = core_->session().Estimate();
    const std::pair<const char*, double> saved[] = {
        {"initial_pose_x", e.pose.x_m},         {"initial_pose_y", e.pose.y_m},
        {"initial_pose_a", e.pose.theta_rad},   {"initial_cov_xx", e.covariance(0, 0)},
        {"initial_cov_yy", e.covariance(1, 1)}, {"initial_cov_aa", e.covariance(2, 2)}};
    for (const auto& [name, value] : saved) getPrivateNodeHandle().setParam(name, value);
  }

  TextAmclNodeOptions options_;
  std::mutex mutex_;                     // guards everything below
  std::unique_ptr<LocalizerCore> core_;  // the session (none until a map is in force) and its state
  ros::WallTime last_cloud_time_;
  ros::Time last_health_time_;
  int scans_since_health_ = 0;
  std::string last_state_, floor_id_;  // as last published
  tf2_ros::Buffer tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> tf_broadcaster_;
  ros::Publisher pose_pub_, cloud_pub_, markers_pub_, state_pub_, floor_pub_, map_pub_, diagnostics_pub_;
  std::unique_ptr<ScanTfFilter> scan_filter_;  // after tf_buffer_: destroyed before it
  ros::Subscriber initial_pose_sub_, detections_sub_, map_sub_;
  ros::ServiceServer global_srv_, nomotion_srv_, set_map_srv_;
  ros::WallTimer map_timer_;
  ros::Timer save_timer_, health_timer_;
};

}  // namespace doorplate_localization

PLUGINLIB_EXPORT_CLASS(doorplate_localization::TextAmclNodelet, nodelet::Nodelet)

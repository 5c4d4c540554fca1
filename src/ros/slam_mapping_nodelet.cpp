// SlamMappingNodelet: RBPF SLAM with doorplate text landmarks as a thin, gmapping-compatible nodelet
// around the mapping session (slam/mapping_session.h: throttling, stamps, plate ranges, when the back end
// is solved, map -> odom), the loop `doorplate_eval map` and the offline tools run too. Each callback is
// validate -> convert (slam_conversions.h) -> session -> publish.
// Subscribes scan (sensor_msgs/LaserScan; a broken scan is refused at once, the others held back by a
// ScanTfFilter (scan_tf_filter.h, the localizer's too) until odom -> scan frame is known at its stamp; the
// laser's mounting comes from tf base_frame -> scan frame) and, with ~use_text,
// text_detections (doorplate_localization/TextDetectionArray; detections at the image-centre crossing with
// a text; bearing composed with the camera's optical axis in base_frame from tf). Every array, empty ones
// too, says how far the camera got: with ~camera_wait_s > 0 a scan waits in the session until the arrays
// reached its stamp (at most that long), so scans and plates reach the filter in stamp order whatever
// order the callbacks run in (a replayed bag maps as doorplate_map_bag maps it).
// Publishes map (nav_msgs/OccupancyGrid, latched) and map_metadata (latched) whenever the session solved
// (every map_update_interval of scan time), ~entropy (std_msgs/Float64, gmapping's pose entropy) per
// processed scan, text_landmarks (visualization_msgs/MarkerArray, latched) when the landmarks change, and
// tf map -> odom (the session's) every transform_publish_period (future-dated by one period, like
// gmapping's tf_delay).
// /diagnostics (diagnostic_msgs/DiagnosticArray, 1 Hz ROS time): "mapping" while the session takes scans,
// "waiting_for_scan" before the first and after 2 s without one, "error: <what>" after an unexpected
// exception until it takes a scan again; scans dropped and why, particles, landmarks, plates, the map
// (slam_conversions.h's ToMapperDiagnosticStatus).
// Services: dynamic_map (nav_msgs/GetMap, the last published map) and ~save_maps (std_srvs/Trigger:
// <map_output_dir>/<map_name>.pgm + .yaml (map_server), .text_map.yaml and .trajectory.txt (`scan_index x y
// theta` per processed scan, the posterior mean path, as doorplate_map_bag writes it), atomically); the
// maps are also saved when the nodelet shuts down, after the scans and plates still waiting for the camera.
// Parameters: slam_mapping_options.h, docs/parameters.md.
// Bad input (broken scans, missing tf, stamps going backwards, unusable detections) is dropped with a
// throttled warning naming the topic; the nodelet keeps running.
// Threading: callbacks run on the nodelet's single-threaded queue (tf filter included); mutex_ also
// guards against the destructor's final save.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/GetMap.h>
#include <nav_msgs/MapMetaData.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Float64.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include "doorplate_localization/TextDetectionArray.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/ros/map_conversions.h"
#include "doorplate_localization/ros/pose_conversions.h"
#include "doorplate_localization/ros/slam_conversions.h"
#include "doorplate_localization/ros/text_detection_conversions.h"
#include "doorplate_localization/ros/tf_lookup.h"
#include "doorplate_localization/slam/mapping_session.h"
#include "map_tool_output.h"  // src/tools: the map pair and trajectory file, as the offline tools write them
#include "scan_tf_filter.h"
#include "slam_mapping_options.h"

namespace doorplate_localization {

class SlamMappingNodelet : public nodelet::Nodelet {
 public:
  ~SlamMappingNodelet() override {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!session_ || !options_.save_on_shutdown || !session_->started()) return;
    std::string message;
    session_->Flush();  // the scans and plates still waiting for the camera: the input has ended
    SaveMaps(&message);  // the message says whether it worked; printed without ROS (it may be shutting down)
    std::fprintf(stderr, "[slam_mapping] at shutdown: %s\n", message.c_str());
  }

 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    try {
      options_ = LoadSlamMappingOptions(pnh);
      session_ = std::make_unique<MappingSession>(ToMappingSessionOptions(options_));
    } catch (const std::exception& e) {
      NODELET_FATAL("%s", e.what());
      throw;
    }
    for (const std::string& p : options_.ignored_parameters) {
      NODELET_WARN("%s is a gmapping parameter without a counterpart here; ignored (docs/parameters.md)", p.c_str());
    }
    frames_.odom_frame = options_.odom_frame;
    frames_.base_frame = options_.base_frame;
    frames_.max_range_m = options_.max_range_m;
    frames_.min_valid_beams = options_.min_valid_beams;
    lookup_ = [this](const std::string& target, const std::string& source, const ros::Time& stamp,
                     std::string* problem) { return Lookup(target, source, stamp, problem); };
    tf_buffer_ = std::make_unique<tf2_ros::Buffer>();
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_);
    map_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, /*latch=*/true);
    metadata_pub_ = nh.advertise<nav_msgs::MapMetaData>("map_metadata", 1, /*latch=*/true);
    markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("text_landmarks", 1, /*latch=*/true);
    entropy_pub_ = pnh.advertise<std_msgs::Float64>("entropy", 1, /*latch=*/true);
    map_srv_ = nh.advertiseService("dynamic_map", &SlamMappingNodelet::OnGetMap, this);
    save_srv_ = pnh.advertiseService("save_maps", &SlamMappingNodelet::OnSaveMaps, this);
    diagnostics_pub_ = nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 1);
    health_timer_ = nh.createTimer(ros::Duration(1.0), &SlamMappingNodelet::OnHealthTimer, this);

    // Scans wait in a ScanTfFilter (scan_tf_filter.h, as the localizer's) until tf has the odometry at their
    // stamp. Its queue of kScanTfQueueSize: a back-end solve holds this nodelet for ~1 s (more on a loaded
    // machine, 5x that in sim time at 5x real time); the scans received meanwhile must not be dropped.
    scan_filter_ = std::make_unique<ScanTfFilter>(*tf_buffer_, options_.odom_frame, kScanTfQueueSize,
        nh.getCallbackQueue(), [this](const auto& m) { OnScan(m); }, [this](const auto&, const auto& why, bool) {
          std::lock_guard<std::mutex> lock(mutex_);
          DropScan(why);
        });
    scan_filter_->Subscribe(nh, "scan");
    scan_topic_ = scan_filter_->topic();
    if (options_.use_text) {
      detections_topic_ = nh.resolveName("text_detections");
      detections_sub_ = nh.subscribe("text_detections", kTextDetectionsQueueSize, &SlamMappingNodelet::OnDetections, this);
    }
    if (options_.transform_publish_period_s > 0.0) {
      tf_timer_ = nh.createTimer(ros::Duration(options_.transform_publish_period_s), &SlamMappingNodelet::OnTfTimer,
                                 this);
    }
    NODELET_INFO("slam mapping: %d particles, linear update %.2f m, angular update %.2f rad, temporal update %.1f s, "
                 "text %s; maps to %s/%s.*",
                 options_.slam.slam.num_particles, options_.slam.slam.linear_update_m,
                 options_.slam.slam.angular_update_rad, options_.temporal_update_s, options_.use_text ? "on" : "off",
                 options_.map_output_dir.c_str(), options_.map_name.c_str());
  }

  // A transform target <- source at `stamp`, or nullopt with *problem set (waits up to tf_timeout_s).
  std::optional<geometry_msgs::Transform> Lookup(const std::string& target, const std::string& source,
                                                 const ros::Time& stamp, std::string* problem) const {
    return LookupTransform(*tf_buffer_, target, source, stamp, options_.tf_timeout_s, problem);
  }

  // A scan not taken: a throttled warning naming the topic, counted for /diagnostics. Call with mutex_ held.
  void DropScan(const std::string& why) {
    ++scans_dropped_;
    last_drop_ = scan_topic_ + ": " + why;
    NODELET_WARN_THROTTLE(5.0, "%s; dropping it", last_drop_.c_str());
  }

  // validate -> convert -> session -> publish. Throttling and stamp order are the session's.
  void OnScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    const ros::Time stamp = msg->header.stamp;
    LaserScan scan;
    Pose2D odom_pose;
    const std::string problem = PrepareSlamScan(*msg, lookup_, frames_, &scan, &odom_pose);
    if (!problem.empty()) return DropScan(problem);
    MappingUpdate update;
    try {
      update = session_->AddScan(stamp.toSec(), odom_pose, scan);
    } catch (const std::invalid_argument& e) {
      return DropScan(e.what());
    } catch (const std::exception& e) {  // not bad input: the session failed; said on /diagnostics until a scan is taken
      error_ = std::string("scan at ") + std::to_string(stamp.toSec()) + " s: " + e.what();
      NODELET_ERROR_THROTTLE(5.0, "slam mapping: %s", error_.c_str());
      return;
    }
    if (!update.scan_refused_reason.empty()) return DropScan(update.scan_refused_reason);
    last_scan_taken_ = ros::Time::now();
    ++scans_since_health_;
    error_.clear();
    last_drop_.clear();
    if (NotePlates(update.plates)) PublishLandmarks(stamp);  // sightings that waited for a scan after them
    if (update.scan_processed) PublishAfterScans(update, stamp);
  }

  // After the filter processed a scan (this call's, or ones that waited for the camera): entropy, the map.
  void PublishAfterScans(const MappingUpdate& update, const ros::Time& stamp) {
    std_msgs::Float64 entropy;
    entropy.data = PoseEntropy(session_->slam().slam().particles());
    entropy_pub_.publish(entropy);
    if (update.solved) PublishMap(stamp);
  }

  // Every array, empty or not, tells the session how far the camera got (it orders scans and plates by stamp).
  void OnDetections(const TextDetectionArray::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    const ros::Time stamp = msg->header.stamp;
    bool changed = false;
    try {  // the camera's progress first (the sightings of this stamp wait for a later scan either way)
      const MappingUpdate update = session_->AddPlates(stamp.toSec(), Pose2D{}, {});
      changed = NotePlates(update.plates);
      if (update.scan_processed) PublishAfterScans(update, stamp);
    } catch (const std::invalid_argument& e) {  // a non-finite stamp
      NODELET_WARN_THROTTLE(5.0, "%s: %s; dropping it", detections_topic_.c_str(), e.what());
      return;
    }
    if (!msg->detections.empty()) changed = AddDetections(*msg) || changed;
    if (changed) PublishLandmarks(stamp);
  }

  // The array's sightings to the session; true when one was used (the landmarks changed).
  bool AddDetections(const TextDetectionArray& msg) {
    const ros::Time stamp = msg.header.stamp;
    std::vector<PlateReading> sightings;
    std::vector<std::string> rejected;
    Pose2D odom_pose;
    const std::string problem = PrepareSlamSightings(msg, lookup_, frames_, &sightings, &odom_pose, &rejected);
    if (!problem.empty()) {
      NODELET_WARN_THROTTLE(5.0, "%s: %s; dropping %zu detections", detections_topic_.c_str(), problem.c_str(),
                            msg.detections.size());
      return false;
    }
    for (const std::string& r : rejected) {
      NODELET_WARN_THROTTLE(5.0, "%s: detection %s; dropping it", detections_topic_.c_str(), r.c_str());
    }
    bool changed = false;
    for (const PlateReading& sighting : sightings) {  // one by one: a malformed one does not drop the others
      try {
        const MappingUpdate update = session_->AddPlates(stamp.toSec(), odom_pose, {sighting});
        changed = NotePlates(update.plates) || changed;
        if (update.plates_held > 0) {
          NODELET_DEBUG("slam mapping: plate '%s' waits for the scans near its stamp %.2f s", sighting.text.c_str(),
                        stamp.toSec());
        }
      } catch (const std::invalid_argument& e) {
        NODELET_WARN_THROTTLE(5.0, "%s: detection '%s': %s; dropping it", detections_topic_.c_str(),
                              sighting.text.c_str(), e.what());
      }
    }
    return changed;
  }

  // Logs and counts the session's plate outcomes; true when one was used (the landmarks changed).
  bool NotePlates(const std::vector<MappingPlateOutcome>& outcomes) {
    bool used = false;
    for (const MappingPlateOutcome& o : outcomes) {
      ++(o.result.used() ? plates_used_ : plates_ignored_);
      if (o.result.used()) {
        used = true;
        NODELET_INFO("slam mapping: plate '%s' %s (landmark %d, range %.2f m)", o.sighting.text.c_str(),
                     o.result.outcome == PlateOutcome::kNewLandmark ? "mapped" : "re-observed",
                     o.result.landmark_index, o.result.range_m);
      } else {
        NODELET_INFO("slam mapping: plate '%s' not used: %s", o.sighting.text.c_str(), o.result.reason.c_str());
      }
    }
    return used;
  }

  // The landmarks as they stand (the last solve's positions, the best particle's for plates read since).
  void PublishLandmarks(const ros::Time& stamp) {
    markers_pub_.publish(ToTextLandmarkMarkers(MapFrame(session_->slam().BuildTextMap()), options_.map_frame, stamp));
  }

  // 1 Hz: /diagnostics.
  void OnHealthTimer(const ros::TimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    const ros::Time now = ros::Time::now();
    MapperHealth h;
    h.scan_age_s = last_scan_taken_.isZero() ? -1.0 : std::max(0.0, (now - last_scan_taken_).toSec());
    const double elapsed_s = last_health_time_.isZero() ? 0.0 : (now - last_health_time_).toSec();
    h.scan_rate_hz = elapsed_s > 0.0 ? scans_since_health_ / elapsed_s : 0.0;
    scans_since_health_ = 0;
    last_health_time_ = now;
    h.scans_dropped = scans_dropped_;
    h.last_drop = last_drop_;
    const RbpfSlam& filter = session_->slam().slam();
    h.scans_processed = filter.stats().scans_processed;
    h.particles = static_cast<int>(filter.particles().size());
    h.neff = filter.stats().last_neff;
    h.landmarks = session_->slam().num_landmarks();
    h.plates_used = plates_used_;
    h.plates_ignored = plates_ignored_;
    if (session_->options().camera_wait_s > 0) h.scans_waiting_for_camera = static_cast<int>(session_->waiting_scans());
    h.camera_waits_expired = session_->counters().scans_camera_wait_expired;
    h.plates_late = session_->counters().plates_late;
    h.solves = session_->counters().solves;
    h.last_solve_s = session_->counters().last_solve_wall_s;
    h.solves_deferred = session_->counters().solves_deferred;
    h.back_end_nodes = session_->slam().back_end().num_nodes();
    h.nodes_on_mapped_ground = session_->slam().back_end().nodes_on_mapped_ground();
    if (latest_map_) {
      std::ostringstream map;
      map << latest_map_->info.width << " x " << latest_map_->info.height << " at " << latest_map_->info.resolution
          << " m";
      h.map = map.str();
    }
    h.error = error_;
    diagnostic_msgs::DiagnosticArray array;
    array.header.stamp = now;
    array.status.push_back(ToMapperDiagnosticStatus(h, getName() + ": mapping", getName()));
    diagnostics_pub_.publish(array);
  }

  void OnTfTimer(const ros::TimerEvent&) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!session_->MapToOdom()) return;
    geometry_msgs::TransformStamped t;
    t.header.frame_id = options_.map_frame;
    t.child_frame_id = options_.odom_frame;
    t.header.stamp = ros::Time::now() + ros::Duration(options_.transform_publish_period_s);
    if (t.header.stamp <= last_tf_stamp_) return;  // sim time did not advance: tf2 would drop a repeat
    last_tf_stamp_ = t.header.stamp;
    t.transform = ToTransformMsg(*session_->MapToOdom());
    tf_broadcaster_.sendTransform(t);
  }

  TextMap MapFrame(TextMap map) const {
    map.frame_id = options_.map_frame;
    return map;
  }

  // The maps of the session's last solve.
  void PublishMap(const ros::Time& stamp) {
    latest_map_ = ToOccupancyGridMsg(*session_->Map(), options_.map_frame, stamp);
    map_pub_.publish(*latest_map_);
    metadata_pub_.publish(latest_map_->info);
    markers_pub_.publish(ToTextLandmarkMarkers(MapFrame(session_->GetTextMap()), options_.map_frame, stamp));
  }

  bool OnGetMap(nav_msgs::GetMap::Request&, nav_msgs::GetMap::Response& res) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!latest_map_) return false;  // as gmapping: no map yet
    res.map = *latest_map_;
    return true;
  }

  bool OnSaveMaps(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    std::lock_guard<std::mutex> lock(mutex_);
    res.success = SaveMaps(&res.message);
    if (res.success) NODELET_INFO("slam mapping: %s", res.message.c_str());
    else NODELET_ERROR("slam mapping: ~save_maps: %s", res.message.c_str());
    return true;
  }

  // Solves, then writes the occupancy map and the text map atomically; never replaces saved maps with an
  // empty one.
  bool SaveMaps(std::string* message) {
    if (!session_->started()) {
      *message = "no scan processed yet: nothing to save (files in " + options_.map_output_dir + " left alone)";
      return false;
    }
    const std::string base = options_.map_output_dir + "/" + options_.map_name;
    try {
      std::filesystem::create_directories(options_.map_output_dir);
      session_->Solve();
      const TextMap text_map = MapFrame(session_->GetTextMap());
      tools::SaveMapPair(*session_->Map(), text_map, base);  // as the offline tools: occupancy_map = <name>.yaml
      tools::WriteTrajectory(session_->slam().slam().MeanTrajectory(), base + ".trajectory.txt");
      *message = "saved " + base + ".pgm, " + base + ".yaml, " + base + ".text_map.yaml (" +
                 std::to_string(text_map.landmarks.size()) + " plates) and " + base + ".trajectory.txt";
      return true;
    } catch (const std::exception& e) {
      *message = std::string("cannot save the maps: ") + e.what();
      return false;
    }
  }

  SlamMappingNodeOptions options_;
  SlamInputFrames frames_;
  TransformLookup lookup_;
  std::unique_ptr<MappingSession> session_;
  std::mutex mutex_;  // guards everything below
  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  std::unique_ptr<ScanTfFilter> scan_filter_;  // after tf_buffer_: destroyed before it
  ros::Subscriber detections_sub_;
  ros::Publisher map_pub_, metadata_pub_, markers_pub_, entropy_pub_, diagnostics_pub_;
  ros::ServiceServer map_srv_, save_srv_;
  ros::Timer tf_timer_, health_timer_;
  // For /diagnostics.
  ros::Time last_scan_taken_, last_health_time_;
  int scans_since_health_ = 0;
  long long scans_dropped_ = 0, plates_used_ = 0, plates_ignored_ = 0;
  std::string last_drop_, error_;
  std::string scan_topic_, detections_topic_;
  ros::Time last_tf_stamp_;
  std::optional<nav_msgs::OccupancyGrid> latest_map_;
};

}  // namespace doorplate_localization

PLUGINLIB_EXPORT_CLASS(doorplate_localization::SlamMappingNodelet, nodelet::Nodelet)

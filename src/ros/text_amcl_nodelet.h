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
// At run time: ~set_parameters (dynamic_reconfigure, cfg/TextAmcl.cfg; text_amcl_reconfigure.h), keeping the
// particles.
//
// Requests go through LocalizerCore (text_amcl_building.h): a refused map (set_map, the map topic,
// static_map) leaves the session, the latched map and ~state as they were, and set_map answers success
// false with the reason logged. ~state is LocalizerCore's (waiting_for_map | waiting_for_scan | tracking |
// converged | lost: <reason> | error: <what>): converged only while scans are being taken and estimates
// published. /diagnostics (diagnostic_msgs/DiagnosticArray, 1 Hz ROS time): state, map in force, scan rate,
// scans dropped, odometry tf age, plates used, the last error (amcl_conversions.h's ToDiagnosticStatus). amcl_pose is
// published after filter updates (scans, plates), not at a (re)start, as amcl; its covariance is the whole
// particle set's (amcl's). mutex_ guards the core.
// The class; its definitions: text_amcl_nodelet.cpp (start, maps, services, publishing, health) and
// text_amcl_nodelet_inputs.cpp (scans and doorplate readings).
#pragma once

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
#include "text_amcl_reconfigure.h"

namespace doorplate_localization {

class TextAmclNodelet : public nodelet::Nodelet {
 private:
  void onInit() override;
  // An accepted dynamic_reconfigure request (text_amcl_reconfigure.h; checked as the startup parameters): the
  // filter and its models, keeping the particles, then the options read at use (transform_tolerance,
  // gui_publish_rate: cfg/TextAmcl.cfg holds no other kind). Returns "" or why the core refused it.
  std::string Reconfigure(const TextAmclNodeOptions& o);
  // Applies a new map through `use` (a LocalizerCore::UseMaps / UseGrid call) and, if it was taken, publishes
  // what changed; if refused, logs why: the session, the latched map and ~state stay as they were. Returns
  // whether the map is now in force. Requires mutex_.
  template <typename Use>
  bool UseMaps(const Use& use, const std::string& source);
  // ~floor, and the floor's grid on map (when the nodelet owns the map) and its plates on text_landmarks: for
  // new maps, and when the session has switched floors (logged). Requires mutex_ and a session.
  void PublishFloor(bool new_maps);
  void OnMap(const nav_msgs::OccupancyGrid::ConstPtr& msg);
  // amcl's default map source: the static_map service, retried every second until it answers.
  void RequestStaticMap(const ros::WallTimerEvent&);
  // amcl's set_map: the map and the pose to start at. Validated whole before anything changes; refused: success
  // false, the reason logged, the map in force kept.
  bool OnSetMap(nav_msgs::SetMap::Request& req, nav_msgs::SetMap::Response& res);
  bool OnGlobalLocalization(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool OnNoMotionUpdate(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  void OnInitialPose(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg);
  // A scan not taken: a throttled error (broken) or warning naming the topic, counted. Requires mutex_.
  void ScanDropped(const std::string& why, bool broken);
  // A valid scan whose odometry tf has (scan_filter_) -> tf (laser mount, odometry) -> convert -> session -> publish.
  void OnScan(const sensor_msgs::LaserScan::ConstPtr& msg);
  // validate -> tf (camera yaw, odometry at the stamp) -> readings -> session -> publish.
  void OnDetections(const TextDetectionArray::ConstPtr& msg);
  // The session threw while handling `topic`: logged, ~state says error until it takes a scan again.
  // Requires mutex_.
  void Failed(const std::string& topic, const std::string& what);
  // Logs what became of the plate readings one session call resolved (unknown rooms once each).
  void ReportPlates(const SessionUpdate& update, const std::string& topic);
  // After a (re)start (a new map, initialpose, global_localization): the new particle cloud and ~state (now
  // waiting_for_scan); amcl_pose waits for the first update, as amcl's. Requires mutex_ and a session.
  void PublishRestart();
  // amcl_pose and ~state (and the floor, if it changed); particlecloud when forced or due by
  // ~gui_publish_rate. Requires mutex_ and a session.
  void PublishFilter(const ros::Time& stamp, bool force_cloud);
  // ~state as LocalizerCore says it now (published and logged when it changed). Requires mutex_.
  void PublishState();
  // 1 Hz: ~state (a scan timeout shows here) and /diagnostics.
  void OnHealthTimer(const ros::TimerEvent&);
  // amcl's save_pose_rate: the last estimate becomes ~initial_pose_* / ~initial_cov_* on the server (while
  // estimates are being published only).
  void SavePose(const ros::TimerEvent&);

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
  std::unique_ptr<TextAmclReconfigureServer> reconfigure_;  // last: its callbacks stop first
};

}  // namespace doorplate_localization

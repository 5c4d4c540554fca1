// Conversions between the Text AMCL core (include/doorplate_localization/mcl/) and amcl's ROS interface,
// used by TextAmclNodelet; poses, map -> odom, grids, landmark markers and camera axes are shared with the
// other nodelets (pose_conversions.h, map_conversions.h). Pure functions: no node handle, no clock, no tf;
// every stamp, frame and mounting pose is passed in. Units follow the messages: metres, radians, seconds.
// Planar poses are x, y and the yaw about z (REP-103); z, roll and pitch of incoming poses are ignored.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <diagnostic_msgs/DiagnosticStatus.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <ros/time.h>
#include <sensor_msgs/LaserScan.h>

#include "doorplate_localization/TextDetectionArray.h"
#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/mcl/localization_scan.h"
#include "doorplate_localization/mcl/particle.h"
#include "doorplate_localization/sensors/plate_reading.h"
#include "doorplate_localization/mcl/text_amcl.h"
#include "doorplate_localization/mcl/text_amcl_session.h"
#include "doorplate_localization/ros/pose_conversions.h"

namespace doorplate_localization {

// --- scans ---
// A sensor_msgs/LaserScan (validated with ValidateScan) as the filter's scan: ranges copied as they are
// (REP-117 ±inf / NaN stay), range_min/range_max as the device's interval, `laser_in_base` (the laser
// frame in base_link, from tf) as the mounting pose.
LaserScan ToLocalizationScan(const sensor_msgs::LaserScan& msg, const Pose2D& laser_in_base);

// --- doorplate readings ---
// The plate readings of one TextDetectionArray: one per plate report (IsPlateReport), bearing_rad in
// base_link = camera.yaw_rad + camera.bearing_sign * detection bearing (pose_conversions.h's ToCameraAxis,
// wrapped to (-pi, pi]; PlateReadingFromCamera), no range (TextAmclSession measures it from its scans), camera side
// unknown. Detections whose reading fails ValidatePlateReading (confidence outside [0, 1], NaN bearing) are
// left out with the problem appended to *problems (may be null).
std::vector<PlateReading> ToPlateReadings(const TextDetectionArray& msg, const CameraAxis& camera,
                                          std::vector<std::string>* problems);

// --- initial pose ---
// Returns "" and fills *mean / *covariance (x_m, y_m, theta_rad) from an initialpose message, else the
// problem: a frame other than `global_frame` ("" is accepted as amcl does), a non-finite pose or
// covariance, an orientation that is not a unit quaternion, or a covariance of x, y, yaw that is not
// symmetric positive semi-definite. Outputs are left alone on error.
std::string FromInitialPoseMsg(const geometry_msgs::PoseWithCovarianceStamped& msg, const std::string& global_frame,
                               Pose2D* mean, Eigen::Matrix3d* covariance);

// --- outputs ---
// amcl_pose: the estimate (the heaviest cluster's mean) with estimate.covariance, the WHOLE particle set's
// (as amcl publishes it, text_amcl.h's PoseEstimate), placed in the 6x6 (x, y, z, roll, pitch, yaw) matrix
// at x/y/yaw (rows/columns 0, 1, 5), everything else 0 (as amcl).
geometry_msgs::PoseWithCovarianceStamped ToAmclPoseMsg(const PoseEstimate& estimate, const std::string& frame_id,
                                                       const ros::Time& stamp);
// particlecloud: every particle's pose (weights are not carried, as amcl).
geometry_msgs::PoseArray ToParticleCloudMsg(const std::vector<Particle>& particles, const std::string& frame_id,
                                            const ros::Time& stamp);
// The filter's state: "tracking", "converged" or "lost: <reason>" (likelihood_collapse | plate_contradiction).
std::string StateText(LocalizationState state, LostReason reason);

// What TextAmclNodelet knows about its own condition: for ~state (NodeStateText) and /diagnostics.
struct LocalizerHealth {
  bool map_in_force = false;
  std::string map;                          // the map in force: "<source>: W x H at R m"
  bool global_localization_queued = false;  // requested before any map was in force
  std::string error;                        // the last unexpected exception of the session ("" none)
  double scan_age_s = -1.0;                 // ROS time since the last scan the session took; < 0: none since the (re)start
  double scan_timeout_s = 0.0;              // ~scan_timeout_s; <= 0: scans are never stale
  double scan_rate_hz = 0.0;                // scans taken per second over the last diagnostics period
  double tf_age_s = -1.0;                   // age of the latest odom -> base transform; < 0: none
  long long scans_dropped = 0;              // scans not taken (broken, no tf, dropped waiting for tf), ever
  std::string last_scan_dropped;            // why the last of them was ("" none)
  TextAmclStatus status;                    // the filter's (BuildingSession::Status)
  long long plates_weighed = 0, plates_used = 0, unknown_room_readings = 0;  // the current floor's session
};

// ~state, honest about what is published: "waiting_for_map" (no map in force), "error: <what>" (the
// session threw; cleared by the next scan it takes), "waiting_for_scan" (no scan taken since the filter
// was (re)started, or none for scan_timeout_s: no estimate is being published), else StateText of the
// filter. So "converged" is only said while estimates are flowing.
std::string NodeStateText(const LocalizerHealth& health);

// /diagnostics entry (diagnostic_msgs, rqt_runtime_monitor): level OK for tracking / converged, WARN for
// waiting_for_map / waiting_for_scan / lost, ERROR for error; message = NodeStateText; values: state, map in
// force, global localization queued, scan rate, last scan age, scans dropped, last scan dropped, odometry tf
// age, particles, best cluster weight, position stddev, plates weighed / used, unknown room readings, last error.
diagnostic_msgs::DiagnosticStatus ToDiagnosticStatus(const LocalizerHealth& health, const std::string& name,
                                                     const std::string& hardware_id);

// One line on what became of a plate reading (TextAmclSession's PlateReadingOutcome), for the log: "plate '214' at
// 1.571 rad, range 1.20 m: explained 3.10 (best cluster 4.00), 0 reseeded", "plate '214' not used: <why>",
// "room '999' is not in the text map", "plate '214' at 12.300 s ignored (stale): <detail>". The text is
// quoted at most limits::kMaxLoggedTextBytes long (a 1 MB detection text must not reach the log whole).
std::string DescribePlateOutcome(const PlateReadingOutcome& outcome);

}  // namespace doorplate_localization

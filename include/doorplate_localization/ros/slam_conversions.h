// Conversions between ROS messages and the SLAM core's types (slam/text_slam.h), shared by the mapping
// nodelet (SlamMappingNodelet) and the offline bag mapper (doorplate_map_bag); poses, map -> odom, grids,
// landmark markers and camera axes are shared with the other nodelets (pose_conversions.h,
// map_conversions.h). Pure functions: no node handle, no clock, no tf buffer. Units: metres, radians,
// REP-103 frames (x forward, y left, z up).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <geometry_msgs/Transform.h>
#include <ros/time.h>
#include <sensor_msgs/LaserScan.h>

#include "doorplate_localization/TextDetection.h"
#include "doorplate_localization/TextDetectionArray.h"
#include "doorplate_localization/ros/pose_conversions.h"
#include "doorplate_localization/sensors/laser_scan.h"
#include "doorplate_localization/slam/rbpf_slam.h"
#include "doorplate_localization/slam/text_slam.h"

namespace doorplate_localization {

// Where a laser sits on the robot: its pose in base_link, and whether it is mounted upside down (its z
// axis points down, so its beam angles turn clockwise seen from above).
struct LaserMounting {
  Pose2D pose;
  bool upside_down = false;
};

// Reads the mounting from the transform base_link → laser frame. Returns "" or the problem: a non-finite
// transform, or a laser whose scan plane is tilted more than ~8° from the floor plane (no 2D map then).
std::string ToLaserMounting(const geometry_msgs::Transform& base_to_laser, LaserMounting* mounting);

// Converts a sensor_msgs/LaserScan into the core's LaserScan for the mapper (beam angles in the laser frame, upside-down mountings
// mirrored, `laser_pose` = the mounting's pose). Readings: +inf, or >= `max_range_m` (<= 0: the scan's
// range_max) or > range_max, mean "no echo" (+inf: free space up to the core's clear range); NaN, -inf
// and readings below range_min are invalid (NaN, skipped). Returns "" and fills *out, or the problem
// (ValidateScan's, ranges that do not fit angle_min..angle_max, or fewer than `min_valid_beams`
// finite returns); *out is left alone on error.
std::string ToMappingScan(const sensor_msgs::LaserScan& msg, const LaserMounting& mounting, double max_range_m,
                          int min_valid_beams, LaserScan* out);

// A detection as a SLAM plate sighting: the bearing composed with the camera axis (base_link, CCW:
// camera.yaw_rad + camera.bearing_sign * bearing_rad, wrapped to (-pi, pi]), the confidence, no range
// (the mapping session takes it from the scan nearest in time). nullopt, with *why_not set, for detections the mapper does not
// use: not at the image-centre crossing, an empty text, a text longer than limits::kMaxPlateTextBytes, a
// detection ValidateTextDetection rejects, or a reading ValidatePlateReading rejects (what the session refuses).
std::optional<PlateReading> ToPlateSighting(const TextDetection& msg, const CameraAxis& camera,
                                            std::string* why_not);

// A tf lookup: the transform `target` <- `source` at `stamp` (i.e. `source` expressed in `target`), or
// nullopt with *problem set. The nodelet wraps its tf2_ros::Buffer, doorplate_map_bag a tf2::BufferCore.
using TransformLookup = std::function<std::optional<geometry_msgs::Transform>(
    const std::string& target, const std::string& source, const ros::Time& stamp, std::string* problem)>;

// Frames and scan handling shared by the nodelet and the bag mapper (SlamMappingNodeOptions' fields).
struct SlamInputFrames {
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  double max_range_m = 0.0;   // see ToMappingScan
  int min_valid_beams = 10;
};

// One LaserScan as the SLAM takes it: the mounting from tf base_frame -> scan frame, the odometry pose
// (base_frame in odom_frame) at the scan's stamp, and the converted scan. Returns "" or the problem.
std::string PrepareSlamScan(const sensor_msgs::LaserScan& msg, const TransformLookup& lookup,
                            const SlamInputFrames& frames, LaserScan* scan, Pose2D* odometry_pose);

// One TextDetectionArray as plate sightings (ToPlateSighting; the camera axis from tf base_frame ->
// header.frame_id) and the odometry pose at its stamp. Returns "" or the problem with the tf; detections
// dropped for a reason other than "not at the crossing" / "text is empty" are listed in *rejected as
// "'<text>': <why>".
std::string PrepareSlamSightings(const TextDetectionArray& msg, const TransformLookup& lookup,
                                 const SlamInputFrames& frames, std::vector<PlateReading>* sightings,
                                 Pose2D* odometry_pose, std::vector<std::string>* rejected);

// What SlamMappingNodelet knows about its own condition, for /diagnostics (issue 18).
struct MapperHealth {
  double scan_age_s = -1.0;        // ROS time since the session last took a scan; < 0: none yet
  double scan_timeout_s = 2.0;     // older than this: waiting_for_scan (laser or tf gone)
  double scan_rate_hz = 0.0;       // scans the session took per second over the last diagnostics period
  long long scans_dropped = 0;     // since the start: broken, without tf, stamp not after the previous one
  std::string last_drop;           // why the last one was dropped ("" none)
  int scans_processed = 0;         // by the filter (after throttling and the update thresholds)
  int particles = 0;
  double neff = 0.0;               // the filter's last effective sample size
  int landmarks = 0;
  long long plates_used = 0, plates_ignored = 0;
  // The stamp order (MappingSession camera_wait_s): scans waiting now for the text extractor's arrays (< 0:
  // scans do not wait), waits that ran out since the start (the camera was off or more than camera_wait_s
  // behind), sightings that came after a newer scan had gone to the filter.
  int scans_waiting_for_camera = -1;
  long long camera_waits_expired = 0, plates_late = 0;
  long long solves = 0;            // back-end solves (MappingSession counters)
  double last_solve_s = 0.0;       // wall-clock seconds of the last one
  long long solves_deferred = 0;   // processed scans at which a due solve waited for the solve share
  int back_end_nodes = 0;          // pose-graph nodes (one per processed scan)
  int nodes_on_mapped_ground = 0;  // ... of them added without their scan (back_end.max_nodes_per_place)
  std::string map;                 // the last published map, "W x H at R m"; "" none yet
  std::string error;               // the last unexpected exception of a callback ("" none)
};

// "error: <what>", "waiting_for_scan" (no scan taken yet, or none for scan_timeout_s) or "mapping".
std::string MapperStateText(const MapperHealth& health);

// /diagnostics entry: level OK for mapping, WARN for waiting_for_scan, ERROR for error; message = the
// state, plus "; last scan dropped: <why>" while scans are dropped; values: state, scan rate, last scan
// age, scans processed, scans dropped, last drop, particles, neff, landmarks, plates used / ignored, the
// stamp order's scans waiting for the camera ("off" when they do not wait), waits run out and late plates,
// solves, the last solve's seconds, solves deferred, back-end nodes and those on mapped ground, map, last
// error.
diagnostic_msgs::DiagnosticStatus ToMapperDiagnosticStatus(const MapperHealth& health, const std::string& name,
                                                           const std::string& hardware_id);

// gmapping's ~entropy: the entropy of the particle poses as one weighted Gaussian (x, y, theta),
// ½ ln((2πe)³ det Σ), nats; weights from the particles' log-weights. Lower = more concentrated.
// Degenerate covariances (all particles on one pose) give a large negative value, never NaN.
double PoseEntropy(const std::vector<SlamParticle>& particles);

}  // namespace doorplate_localization

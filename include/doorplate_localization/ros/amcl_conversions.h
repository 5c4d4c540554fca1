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
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <ros/time.h>
#include <sensor_msgs/LaserScan.h>

#include "doorplate_localization/TextDetectionArray.h"
#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/mcl/localization_scan.h"
#include "doorplate_localization/mcl/particle.h"
#include "doorplate_localization/mcl/plate_reading.h"
#include "doorplate_localization/mcl/text_amcl.h"
#include "doorplate_localization/mcl/text_amcl_session.h"
#include "doorplate_localization/ros/pose_conversions.h"

namespace doorplate_localization {

// --- scans ---
// A sensor_msgs/LaserScan (validated with ValidateScan) as the filter's scan: ranges copied as they are
// (REP-117 ±inf / NaN stay), range_min/range_max as the device's interval, `laser_in_base` (the laser
// frame in base_link, from tf) as the mounting pose.
LocalizationScan ToLocalizationScan(const sensor_msgs::LaserScan& msg, const Pose2D& laser_in_base);

// --- doorplate readings ---
// The plate readings of one TextDetectionArray: one per plate report (IsPlateReport), bearing_rad in
// base_link = camera.yaw_rad + camera.bearing_sign * detection bearing (pose_conversions.h's ToCameraAxis,
// wrapped to (-pi, pi]; PlateReadingAt), no range (TextAmclSession measures it from its scans), camera side
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
// amcl_pose: the estimate with its covariance placed in the 6x6 (x, y, z, roll, pitch, yaw) matrix at
// x/y/yaw (rows/columns 0, 1, 5), everything else 0 (as amcl).
geometry_msgs::PoseWithCovarianceStamped ToAmclPoseMsg(const PoseEstimate& estimate, const std::string& frame_id,
                                                       const ros::Time& stamp);
// particlecloud: every particle's pose (weights are not carried, as amcl).
geometry_msgs::PoseArray ToParticleCloudMsg(const std::vector<Particle>& particles, const std::string& frame_id,
                                            const ros::Time& stamp);
// ~state: "tracking", "converged" or "lost: <reason>" (likelihood_collapse | plate_contradiction).
std::string StateText(LocalizationState state, LostReason reason);

// One line on what became of a plate reading (TextAmclSession's PlateReadingOutcome), for the log: "plate '214' at
// 1.571 rad, range 1.20 m: explained 3.10 (best cluster 4.00), 0 reseeded", "plate '214' not used: <why>",
// "room '999' is not in the text map", "plate '214' at 12.300 s ignored (stale): <detail>".
std::string DescribePlateOutcome(const PlateReadingOutcome& outcome);

}  // namespace doorplate_localization

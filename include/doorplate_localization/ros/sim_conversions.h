// Conversions between the ROS-free simulator types and ROS messages. Pure functions: no node handle, no
// clock; every stamp and frame id is passed in. Units follow the messages (metres, radians, seconds).
#pragma once

#include <string>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <opencv2/core.hpp>
#include <ros/time.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/LaserScan.h>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/ros/pose_conversions.h"  // ToPoseMsg, ToTransformStampedMsg, ...
#include "doorplate_localization/sim/camera_renderer.h"
#include "doorplate_localization/sim/laser_simulator.h"
#include "doorplate_localization/sim/sensor_options.h"

namespace doorplate_localization {

// Simulator seconds -> ros::Time (sim time). Throws std::invalid_argument for negative or non-finite input.
ros::Time SimTime(double time_s);

// A scan in `frame_id` stamped `stamp`. Ranges are copied as they are, so beams without an echo stay +inf
// (REP-117). scan_time = 1 / rate_hz. time_increment = 0: the simulator casts every beam at the same
// instant, and a non-zero value would make deskewing consumers move beams that were never distorted.
// Throws std::invalid_argument if rate_hz <= 0.
sensor_msgs::LaserScan ToLaserScanMsg(const LaserScan& scan, double rate_hz, const std::string& frame_id,
                                      const ros::Time& stamp);

// Diagonal variances of a planar pose or twist; the message's other entries (z, roll, pitch and all
// cross terms) stay 0: a planar robot has exactly zero z, roll and pitch. All zero means "not estimated".
struct PlanarVariance {
  double x = 0.0;    // m² (pose) or (m/s)² (twist)
  double y = 0.0;    // m² or (m/s)²
  double yaw = 0.0;  // rad² or (rad/s)²
};

// nav_msgs/Odometry: `pose` is child_frame in frame_id; the twist (forward speed, yaw rate) is in
// child_frame, as REP-105 and nav_msgs/Odometry require.
nav_msgs::Odometry ToOdometryMsg(const Pose2D& pose, double linear_mps, double angular_rps,
                                 const std::string& frame_id, const std::string& child_frame,
                                 const ros::Time& stamp, const PlanarVariance& pose_variance = {},
                                 const PlanarVariance& twist_variance = {});

// Variance of the random part of the odometry error after driving `distance_m` and turning `turned_rad`
// (absolute sums), from the noise model of OdometrySimulator (every term is a random walk whose variance
// grows linearly with the motion). x and y both get the along-track variance, yaw the heading variance;
// the systematic errors (scale_error, heading drift) are biases, not variance, and are left out.
PlanarVariance OdometryPoseVariance(const OdometryNoiseOptions& noise, double distance_m, double turned_rad);

// A BGR8 image (CV_8UC3, any strides) as sensor_msgs/Image with encoding "bgr8", copied row by row.
// Throws std::invalid_argument for another pixel type or an empty image.
sensor_msgs::Image ToImageMsg(const cv::Mat& bgr8, const std::string& frame_id, const ros::Time& stamp);

// Pinhole intrinsics as CameraInfo: plumb_bob with zero distortion, K from fx/fy/cx/cy, R = identity,
// P = [K | 0] (monocular). `frame_id` must be the optical frame (z forward, x right, y down).
sensor_msgs::CameraInfo ToCameraInfoMsg(const CameraIntrinsics& intrinsics, const std::string& frame_id,
                                        const ros::Time& stamp);

// The camera body frame (x along the optical axis, y left, z up; REP-103) in base_link, from the values of
// CameraRenderer::MountPose: position, yaw about z, then pitch about the body y axis (REP-103: positive
// pitch tilts the optical axis down, so a camera tilted up has a negative pitch_rad).
geometry_msgs::TransformStamped CameraBodyTransformMsg(double x_m, double y_m, double z_m, double yaw_rad,
                                                       double pitch_rad, const std::string& base_frame,
                                                       const std::string& body_frame, const ros::Time& stamp);
// The fixed rotation from a camera body frame (x forward, y left, z up) to its optical frame (z forward,
// x right, y down): optical = body rotated by roll -pi/2, yaw -pi/2.
geometry_msgs::TransformStamped OpticalFromBodyTransformMsg(const std::string& body_frame,
                                                            const std::string& optical_frame,
                                                            const ros::Time& stamp);

}  // namespace doorplate_localization

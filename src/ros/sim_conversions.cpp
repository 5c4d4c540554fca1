#include "doorplate_localization/ros/sim_conversions.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

#include <sensor_msgs/image_encodings.h>
#include <sensor_msgs/distortion_models.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

namespace doorplate_localization {
namespace {

// Row-major 6×6 covariance (x, y, z, roll, pitch, yaw) with only the planar diagonal set.
void FillPlanarCovariance(const PlanarVariance& variance, boost::array<double, 36>* covariance) {
  covariance->fill(0.0);
  (*covariance)[0] = variance.x;
  (*covariance)[7] = variance.y;
  (*covariance)[35] = variance.yaw;
}

}  // namespace

ros::Time SimTime(double time_s) {
  if (!std::isfinite(time_s) || time_s < 0.0) {
    throw std::invalid_argument("SimTime: time_s must be finite and >= 0, got " + std::to_string(time_s));
  }
  return ros::Time().fromSec(time_s);
}

sensor_msgs::LaserScan ToLaserScanMsg(const LaserScan& scan, double rate_hz, const std::string& frame_id,
                                      const ros::Time& stamp) {
  if (!(rate_hz > 0.0)) {
    throw std::invalid_argument("ToLaserScanMsg: rate_hz must be > 0, got " + std::to_string(rate_hz));
  }
  sensor_msgs::LaserScan msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  msg.angle_min = static_cast<float>(scan.angle_min_rad);
  msg.angle_increment = static_cast<float>(scan.angle_increment_rad);
  const double beams = scan.ranges_m.empty() ? 0.0 : static_cast<double>(scan.ranges_m.size() - 1);
  msg.angle_max = static_cast<float>(scan.angle_min_rad + beams * scan.angle_increment_rad);
  msg.scan_time = static_cast<float>(1.0 / rate_hz);
  msg.time_increment = 0.0f;
  msg.range_min = static_cast<float>(scan.min_range_m);
  msg.range_max = static_cast<float>(scan.max_range_m);
  msg.ranges = scan.ranges_m;
  return msg;
}

nav_msgs::Odometry ToOdometryMsg(const Pose2D& pose, double linear_mps, double angular_rps,
                                 const std::string& frame_id, const std::string& child_frame,
                                 const ros::Time& stamp, const PlanarVariance& pose_variance,
                                 const PlanarVariance& twist_variance) {
  nav_msgs::Odometry msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  msg.child_frame_id = child_frame;
  msg.pose.pose = ToPoseMsg(pose);
  FillPlanarCovariance(pose_variance, &msg.pose.covariance);
  msg.twist.twist.linear.x = linear_mps;
  msg.twist.twist.angular.z = angular_rps;
  FillPlanarCovariance(twist_variance, &msg.twist.covariance);
  return msg;
}

PlanarVariance OdometryPoseVariance(const OdometryNoiseOptions& noise, double distance_m, double turned_rad) {
  const double d = std::fabs(distance_m), r = std::fabs(turned_rad);
  const double along_track_m2 = noise.alpha3_m2_per_m * d + noise.alpha4_m2_per_rad * r;
  return {along_track_m2, along_track_m2, noise.alpha1_rad2_per_rad * r + noise.alpha2_rad2_per_m * d};
}

sensor_msgs::Image ToImageMsg(const cv::Mat& bgr8, const std::string& frame_id, const ros::Time& stamp) {
  if (bgr8.empty() || bgr8.type() != CV_8UC3) {
    throw std::invalid_argument("ToImageMsg: expected a non-empty CV_8UC3 (bgr8) image, got type " +
                                std::to_string(bgr8.type()) + " size " + std::to_string(bgr8.cols) + "x" +
                                std::to_string(bgr8.rows));
  }
  sensor_msgs::Image msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  msg.height = static_cast<uint32_t>(bgr8.rows);
  msg.width = static_cast<uint32_t>(bgr8.cols);
  msg.encoding = sensor_msgs::image_encodings::BGR8;
  msg.is_bigendian = 0;
  msg.step = static_cast<uint32_t>(bgr8.cols * 3);
  msg.data.resize(static_cast<size_t>(msg.step) * msg.height);
  for (int row = 0; row < bgr8.rows; ++row) {
    std::memcpy(&msg.data[static_cast<size_t>(row) * msg.step], bgr8.ptr<uint8_t>(row), msg.step);
  }
  return msg;
}

sensor_msgs::CameraInfo ToCameraInfoMsg(const CameraIntrinsics& intrinsics, const std::string& frame_id,
                                        const ros::Time& stamp) {
  sensor_msgs::CameraInfo msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  msg.width = static_cast<uint32_t>(intrinsics.width_px);
  msg.height = static_cast<uint32_t>(intrinsics.height_px);
  msg.distortion_model = sensor_msgs::distortion_models::PLUMB_BOB;
  msg.D.assign(5, 0.0);
  msg.K = {intrinsics.fx_px, 0.0, intrinsics.cx_px, 0.0, intrinsics.fy_px, intrinsics.cy_px, 0.0, 0.0, 1.0};
  msg.R = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  msg.P = {intrinsics.fx_px, 0.0, intrinsics.cx_px, 0.0, 0.0, intrinsics.fy_px, intrinsics.cy_px, 0.0,
           0.0, 0.0, 1.0, 0.0};
  return msg;
}

geometry_msgs::TransformStamped CameraBodyTransformMsg(double x_m, double y_m, double z_m, double yaw_rad,
                                                       double pitch_rad, const std::string& base_frame,
                                                       const std::string& body_frame, const ros::Time& stamp) {
  geometry_msgs::TransformStamped msg;
  msg.header.frame_id = base_frame;
  msg.header.stamp = stamp;
  msg.child_frame_id = body_frame;
  msg.transform.translation.x = x_m;
  msg.transform.translation.y = y_m;
  msg.transform.translation.z = z_m;
  tf2::Quaternion q;
  q.setRPY(0.0, pitch_rad, yaw_rad);  // R = Rz(yaw) * Ry(pitch)
  msg.transform.rotation = tf2::toMsg(q);
  return msg;
}

geometry_msgs::TransformStamped OpticalFromBodyTransformMsg(const std::string& body_frame,
                                                            const std::string& optical_frame,
                                                            const ros::Time& stamp) {
  geometry_msgs::TransformStamped msg;
  msg.header.frame_id = body_frame;
  msg.header.stamp = stamp;
  msg.child_frame_id = optical_frame;
  tf2::Quaternion q;
  q.setRPY(-M_PI / 2.0, 0.0, -M_PI / 2.0);
  msg.transform.rotation = tf2::toMsg(q);
  return msg;
}

}  // namespace doorplate_localization

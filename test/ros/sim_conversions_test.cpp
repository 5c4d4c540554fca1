#include "doorplate_localization/ros/sim_conversions.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>
#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/LinearMath/Vector3.h>

namespace doorplate_localization {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

tf2::Quaternion ToTf(const geometry_msgs::Quaternion& q) { return tf2::Quaternion(q.x, q.y, q.z, q.w); }

double YawOf(const geometry_msgs::Quaternion& q) {
  double roll, pitch, yaw;
  tf2::Matrix3x3(ToTf(q)).getRPY(roll, pitch, yaw);
  return yaw;
}

// A vector given in the child frame, expressed in the parent frame.
tf2::Vector3 Rotate(const geometry_msgs::TransformStamped& t, const tf2::Vector3& v) {
  return tf2::quatRotate(ToTf(t.transform.rotation), v);
}

void ExpectVectorNear(const tf2::Vector3& expected, const tf2::Vector3& actual) {
  EXPECT_NEAR(expected.x(), actual.x(), 1e-9);
  EXPECT_NEAR(expected.y(), actual.y(), 1e-9);
  EXPECT_NEAR(expected.z(), actual.z(), 1e-9);
}

TEST(SimTime, ConvertsSecondsAndRejectsNegativeOrNonFinite) {
  const ros::Time t = SimTime(12.25);
  EXPECT_EQ(12u, t.sec);
  EXPECT_EQ(250000000u, t.nsec);
  EXPECT_THROW(SimTime(-0.5), std::invalid_argument);
  EXPECT_THROW(SimTime(std::nan("")), std::invalid_argument);
}

TEST(ToLaserScanMsg, KeepsInfiniteRangesAndFillsGeometryAndTiming) {
  LaserScan scan;
  scan.angle_min_rad = -M_PI;
  scan.angle_increment_rad = M_PI / 2.0;
  scan.min_range_m = 0.15;
  scan.max_range_m = 16.0;
  scan.ranges_m = {1.0f, static_cast<float>(kInf), 2.5f, 3.0f};
  const sensor_msgs::LaserScan msg = ToLaserScanMsg(scan, 10.0, "laser", ros::Time(5, 0));

  EXPECT_EQ("laser", msg.header.frame_id);
  EXPECT_EQ(ros::Time(5, 0), msg.header.stamp);
  ASSERT_EQ(4u, msg.ranges.size());
  EXPECT_TRUE(std::isinf(msg.ranges[1]) && msg.ranges[1] > 0.0f);  // REP-117: no echo stays +inf
  EXPECT_FLOAT_EQ(2.5f, msg.ranges[2]);
  EXPECT_FLOAT_EQ(static_cast<float>(-M_PI), msg.angle_min);
  EXPECT_FLOAT_EQ(static_cast<float>(M_PI / 2.0), msg.angle_max);  // last beam: -pi + 3 * pi/2
  EXPECT_FLOAT_EQ(0.1f, msg.scan_time);
  EXPECT_FLOAT_EQ(0.0f, msg.time_increment);
  EXPECT_FLOAT_EQ(0.15f, msg.range_min);
  EXPECT_FLOAT_EQ(16.0f, msg.range_max);
  EXPECT_TRUE(msg.intensities.empty());
}

TEST(ToLaserScanMsg, RejectsNonPositiveRate) {
  EXPECT_THROW(ToLaserScanMsg(LaserScan{}, 0.0, "laser", ros::Time(1, 0)), std::invalid_argument);
}

TEST(ToOdometryMsg, PutsPoseInFrameAndTwistInChildFrameWithPlanarCovariance) {
  const nav_msgs::Odometry msg = ToOdometryMsg(Pose2D{4.0, 1.0, M_PI / 2.0}, 0.6, -0.3, "odom", "base_link",
                                               ros::Time(7, 0), PlanarVariance{0.01, 0.02, 0.03},
                                               PlanarVariance{0.001, 0.0, 0.004});
  EXPECT_EQ("odom", msg.header.frame_id);
  EXPECT_EQ("base_link", msg.child_frame_id);
  EXPECT_DOUBLE_EQ(4.0, msg.pose.pose.position.x);
  EXPECT_NEAR(M_PI / 2.0, YawOf(msg.pose.pose.orientation), 1e-12);
  // Forward speed along the child's x even though the robot faces +y in odom.
  EXPECT_DOUBLE_EQ(0.6, msg.twist.twist.linear.x);
  EXPECT_DOUBLE_EQ(0.0, msg.twist.twist.linear.y);
  EXPECT_DOUBLE_EQ(-0.3, msg.twist.twist.angular.z);
  EXPECT_DOUBLE_EQ(0.01, msg.pose.covariance[0]);
  EXPECT_DOUBLE_EQ(0.02, msg.pose.covariance[7]);
  EXPECT_DOUBLE_EQ(0.0, msg.pose.covariance[14]);  // z of a planar robot is exact
  EXPECT_DOUBLE_EQ(0.03, msg.pose.covariance[35]);
  EXPECT_DOUBLE_EQ(0.001, msg.twist.covariance[0]);
  EXPECT_DOUBLE_EQ(0.004, msg.twist.covariance[35]);
  EXPECT_DOUBLE_EQ(0.0, msg.twist.covariance[1]);
}

TEST(OdometryPoseVariance, GrowsLinearlyWithDistanceAndTurnPerNoiseModel) {
  OdometryNoiseOptions noise;
  noise.alpha1_rad2_per_rad = 0.1;
  noise.alpha2_rad2_per_m = 0.01;
  noise.alpha3_m2_per_m = 0.02;
  noise.alpha4_m2_per_rad = 0.005;
  const PlanarVariance v = OdometryPoseVariance(noise, 10.0, -2.0);  // turns count by magnitude
  EXPECT_DOUBLE_EQ(0.02 * 10.0 + 0.005 * 2.0, v.x);
  EXPECT_DOUBLE_EQ(v.x, v.y);
  EXPECT_DOUBLE_EQ(0.1 * 2.0 + 0.01 * 10.0, v.yaw);
  const PlanarVariance zero = OdometryPoseVariance(noise, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(0.0, zero.x);
  EXPECT_DOUBLE_EQ(0.0, zero.yaw);
}

TEST(ToImageMsg, CopiesBgrPixelsRowByRowFromAStridedView) {
  cv::Mat big(6, 8, CV_8UC3, cv::Scalar(0, 0, 0));
  big.at<cv::Vec3b>(2, 3) = cv::Vec3b(10, 20, 30);  // B, G, R
  const cv::Mat view = big(cv::Rect(2, 1, 4, 3));   // not continuous: step 24 bytes, row 12 bytes
  ASSERT_FALSE(view.isContinuous());
  const sensor_msgs::Image msg = ToImageMsg(view, "camera_optical", ros::Time(2, 0));
  EXPECT_EQ("bgr8", msg.encoding);
  EXPECT_EQ("camera_optical", msg.header.frame_id);
  EXPECT_EQ(4u, msg.width);
  EXPECT_EQ(3u, msg.height);
  EXPECT_EQ(12u, msg.step);
  ASSERT_EQ(36u, msg.data.size());
  const size_t i = 1 * msg.step + 1 * 3;  // big(2, 3) is view(1, 1)
  EXPECT_EQ(10, msg.data[i]);
  EXPECT_EQ(20, msg.data[i + 1]);
  EXPECT_EQ(30, msg.data[i + 2]);
  EXPECT_EQ(0, msg.data[0]);
}

TEST(ToImageMsg, RejectsGreyAndEmptyImages) {
  EXPECT_THROW(ToImageMsg(cv::Mat(4, 4, CV_8UC1), "c", ros::Time(1, 0)), std::invalid_argument);
  EXPECT_THROW(ToImageMsg(cv::Mat(), "c", ros::Time(1, 0)), std::invalid_argument);
}

TEST(ToCameraInfoMsg, FillsPlumbBobWithZeroDistortionAndPinholeMatrices) {
  CameraIntrinsics k;
  k.fx_px = 554.3;
  k.fy_px = 554.3;
  k.cx_px = 319.5;
  k.cy_px = 239.5;
  k.width_px = 640;
  k.height_px = 480;
  const sensor_msgs::CameraInfo msg = ToCameraInfoMsg(k, "camera_optical", ros::Time(1, 0));
  EXPECT_EQ("plumb_bob", msg.distortion_model);
  ASSERT_EQ(5u, msg.D.size());
  for (double d : msg.D) EXPECT_EQ(0.0, d);
  EXPECT_EQ(640u, msg.width);
  EXPECT_EQ(480u, msg.height);
  EXPECT_DOUBLE_EQ(554.3, msg.K[0]);
  EXPECT_DOUBLE_EQ(319.5, msg.K[2]);
  EXPECT_DOUBLE_EQ(239.5, msg.K[5]);
  EXPECT_DOUBLE_EQ(1.0, msg.K[8]);
  EXPECT_DOUBLE_EQ(554.3, msg.P[0]);
  EXPECT_DOUBLE_EQ(0.0, msg.P[3]);  // monocular: no baseline
  EXPECT_DOUBLE_EQ(239.5, msg.P[6]);
  EXPECT_DOUBLE_EQ(1.0, msg.P[10]);
  EXPECT_DOUBLE_EQ(1.0, msg.R[0]);
  EXPECT_DOUBLE_EQ(1.0, msg.R[4]);
  EXPECT_DOUBLE_EQ(0.0, msg.R[1]);
}

TEST(CameraBodyTransformMsg, LeftCameraTiltedUpLooksAlongPlusYAndUpwards) {
  const double pitch_up = 10.0 * M_PI / 180.0;
  const geometry_msgs::TransformStamped t =
      CameraBodyTransformMsg(0.1, 0.2, 1.2, M_PI / 2.0, -pitch_up, "base_link", "camera_link", ros::Time(1, 0));
  EXPECT_EQ("base_link", t.header.frame_id);
  EXPECT_EQ("camera_link", t.child_frame_id);
  EXPECT_DOUBLE_EQ(1.2, t.transform.translation.z);
  // The body x axis (optical axis) in base_link: to the left (+y) and up (+z).
  ExpectVectorNear(tf2::Vector3(0.0, std::cos(pitch_up), std::sin(pitch_up)),
                   Rotate(t, tf2::Vector3(1.0, 0.0, 0.0)));
}

// The tf chain built from CameraRenderer::MountPose must put optical-frame points where the renderer
// projects them: on the optical axis -> principal point, +x -> right of it, +y -> below it.
TEST(CameraTransforms, AgreeWithTheRendererProjection) {
  World world;  // empty: Project needs only the camera model
  for (const char* side : {"left", "right"}) {
    CameraOptions options;
    options.side = side;
    options.mount_x_m = 0.1;
    options.mount_y_m = -0.05;
    options.pitch_deg = 12.0;
    const CameraRenderer renderer(world, options);
    double x, y, z, yaw, pitch;
    renderer.MountPose(&x, &y, &z, &yaw, &pitch);
    const geometry_msgs::TransformStamped body =
        CameraBodyTransformMsg(x, y, z, yaw, pitch, "base_link", "camera_link", ros::Time(1, 0));
    const geometry_msgs::TransformStamped optical = OpticalFromBodyTransformMsg("camera_link", "camera_optical", ros::Time(1, 0));
    const Pose2D robot{2.0, 1.0, 0.3};
    const auto to_world = [&](const tf2::Vector3& in_optical) {
      const tf2::Vector3 in_body = Rotate(optical, in_optical);
      const tf2::Vector3 in_base =
          Rotate(body, in_body) + tf2::Vector3(body.transform.translation.x, body.transform.translation.y,
                                               body.transform.translation.z);
      const Vec2 p = robot.TransformPoint({in_base.x(), in_base.y()});
      return Point3{p.x, p.y, in_base.z()};
    };
    const CameraIntrinsics& k = renderer.intrinsics();
    cv::Point2d pixel;
    ASSERT_TRUE(renderer.Project(robot, to_world(tf2::Vector3(0.0, 0.0, 4.0)), &pixel)) << side;
    EXPECT_NEAR(k.cx_px, pixel.x, 1e-6) << side;
    EXPECT_NEAR(k.cy_px, pixel.y, 1e-6) << side;
    ASSERT_TRUE(renderer.Project(robot, to_world(tf2::Vector3(0.5, 0.25, 4.0)), &pixel)) << side;
    EXPECT_NEAR(k.cx_px + k.fx_px * 0.5 / 4.0, pixel.x, 1e-6) << side;
    EXPECT_NEAR(k.cy_px + k.fy_px * 0.25 / 4.0, pixel.y, 1e-6) << side;
  }
}

TEST(OpticalFromBodyTransformMsg, MapsOpticalAxesOntoBodyAxes) {
  const geometry_msgs::TransformStamped t = OpticalFromBodyTransformMsg("camera_link", "camera_optical", ros::Time(1, 0));
  EXPECT_EQ("camera_link", t.header.frame_id);
  EXPECT_EQ("camera_optical", t.child_frame_id);
  ExpectVectorNear(tf2::Vector3(1.0, 0.0, 0.0), Rotate(t, tf2::Vector3(0.0, 0.0, 1.0)));   // z forward
  ExpectVectorNear(tf2::Vector3(0.0, -1.0, 0.0), Rotate(t, tf2::Vector3(1.0, 0.0, 0.0)));  // x right
  ExpectVectorNear(tf2::Vector3(0.0, 0.0, -1.0), Rotate(t, tf2::Vector3(0.0, 1.0, 0.0)));  // y down
}

}  // namespace
}  // namespace doorplate_localization

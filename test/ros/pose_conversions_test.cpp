// Tests of the shared pose, map -> odom and camera-axis conversions (pose_conversions.h) on tiny hand-made
// transforms. Merged from the simulator's, Text AMCL's, the mapping nodelet's and go-to-room's tests.
#include "doorplate_localization/ros/pose_conversions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

namespace doorplate_localization {
namespace {

double YawOf(const geometry_msgs::Quaternion& q) {
  double roll, pitch, yaw;
  tf2::Matrix3x3(tf2::Quaternion(q.x, q.y, q.z, q.w)).getRPY(roll, pitch, yaw);
  return yaw;
}

// Translation (x, y, z) and rotation R = Rz(yaw) Ry(pitch) Rx(roll).
geometry_msgs::Transform Transform(double x, double y, double z, double roll, double pitch, double yaw) {
  geometry_msgs::Transform t;
  t.translation.x = x;
  t.translation.y = y;
  t.translation.z = z;
  tf2::Quaternion q;
  q.setRPY(roll, pitch, yaw);
  t.rotation = tf2::toMsg(q);
  return t;
}

TEST(ToTransformStampedMsg, CarriesFramesPositionHeightAndYaw) {
  const Pose2D pose{1.5, -2.0, 0.75};
  const geometry_msgs::TransformStamped msg = ToTransformStampedMsg(pose, "odom", "base_link", ros::Time(3, 0), 0.25);
  EXPECT_EQ("odom", msg.header.frame_id);
  EXPECT_EQ("base_link", msg.child_frame_id);
  EXPECT_EQ(ros::Time(3, 0), msg.header.stamp);
  EXPECT_DOUBLE_EQ(1.5, msg.transform.translation.x);
  EXPECT_DOUBLE_EQ(-2.0, msg.transform.translation.y);
  EXPECT_DOUBLE_EQ(0.25, msg.transform.translation.z);
  EXPECT_NEAR(0.75, YawOf(msg.transform.rotation), 1e-12);
}

TEST(ToPoseMsg, WrapsYawBeyondPiToTheSameOrientation) {
  const geometry_msgs::Pose msg = ToPoseMsg(Pose2D{0.0, 0.0, 3.0 * M_PI / 2.0});
  EXPECT_NEAR(-M_PI / 2.0, YawOf(msg.orientation), 1e-12);
  const tf2::Quaternion q(msg.orientation.x, msg.orientation.y, msg.orientation.z, msg.orientation.w);
  EXPECT_NEAR(1.0, q.length(), 1e-12);
}

TEST(ToYawQuaternionMsg, EqualsTf2sRotationAboutZ) {
  tf2::Quaternion expected;
  expected.setRPY(0.0, 0.0, -2.3);
  const geometry_msgs::Quaternion q = ToYawQuaternionMsg(-2.3);
  EXPECT_NEAR(q.x, expected.x(), 1e-15);
  EXPECT_NEAR(q.y, expected.y(), 1e-15);
  EXPECT_NEAR(q.z, expected.z(), 1e-15);
  EXPECT_NEAR(q.w, expected.w(), 1e-15);
}

TEST(ToPose2D, RoundTripsThroughAPoseMessage) {
  const Pose2D pose{1.5, -2.0, 2.5};
  const Pose2D back = ToPose2D(ToPoseMsg(pose));
  EXPECT_DOUBLE_EQ(back.x_m, 1.5);
  EXPECT_DOUBLE_EQ(back.y_m, -2.0);
  EXPECT_NEAR(back.theta_rad, 2.5, 1e-12);
}

TEST(ToPose2D, KeepsXYAndYawOfTheSimulatorsTransforms) {
  const Pose2D p = ToPose2D(ToTransformMsg({1.0, -2.0, 2.5}));
  EXPECT_NEAR(p.x_m, 1.0, 1e-12);
  EXPECT_NEAR(p.y_m, -2.0, 1e-12);
  EXPECT_NEAR(p.theta_rad, 2.5, 1e-12);
}

TEST(ToPose2D, APlanarPoseFromATransformKeepsXYAndYawAndRefusesNonFiniteOnes) {
  const Pose2D pose = ToPose2D(Transform(1.5, -2.0, 0.3, 0.0, 0.0, 2.5));
  EXPECT_DOUBLE_EQ(pose.x_m, 1.5);
  EXPECT_DOUBLE_EQ(pose.y_m, -2.0);
  EXPECT_NEAR(pose.theta_rad, 2.5, 1e-9);
  geometry_msgs::Transform broken = Transform(0, 0, 0, 0, 0, 0);
  broken.translation.x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(ToPose2D(broken), std::invalid_argument);
  geometry_msgs::Pose broken_pose = ToPoseMsg({});
  broken_pose.orientation.w = std::numeric_limits<double>::infinity();
  EXPECT_THROW(ToPose2D(broken_pose), std::invalid_argument);
}

TEST(ToPose2D, DropsRollAndPitchAndIgnoresTheQuaternionsScale) {
  const Pose2D tilted = ToPose2D(Transform(0, 0, 0, 0.2, -0.1, 1.0));
  EXPECT_NEAR(tilted.theta_rad, 1.0, 1e-9);
  geometry_msgs::Transform scaled = Transform(0, 0, 0, 0, 0, -0.7);
  scaled.rotation.z *= 3.0;
  scaled.rotation.w *= 3.0;
  EXPECT_NEAR(ToPose2D(scaled).theta_rad, -0.7, 1e-12);
}

// A fuzzing find (issue 18): components near 1e300 (or 1e-300) over- or underflowed in the yaw's products,
// and a map message with such an origin was accepted with a NaN origin yaw.
TEST(ToPose2D, TheYawOfAHugeOrTinyQuaternionIsItsRotations) {
  for (const double scale : {1e300, 1e-300}) {
    geometry_msgs::Transform t = Transform(0, 0, 0, 0, 0, 0.4);
    t.rotation.z *= scale;
    t.rotation.w *= scale;
    EXPECT_NEAR(ToPose2D(t).theta_rad, 0.4, 1e-12) << scale;
  }
}

TEST(MapToOdom, ComposesTheEstimateWithTheInverseOdometry) {
  const Pose2D base_in_odom{2.0, 1.0, 0.3};
  const Pose2D map_to_odom{-0.5, 0.7, -0.2};
  const Pose2D base_in_map = map_to_odom.Compose(base_in_odom);
  const Pose2D got = MapToOdom(base_in_map, base_in_odom);
  EXPECT_NEAR(got.x_m, map_to_odom.x_m, 1e-12);
  EXPECT_NEAR(got.y_m, map_to_odom.y_m, 1e-12);
  EXPECT_NEAR(got.theta_rad, map_to_odom.theta_rad, 1e-12);
}

TEST(MapToOdom, AsATransformMessageComposedWithOdometryGivesTheEstimate) {
  const Pose2D base_in_map{2.0, 1.0, M_PI / 2}, base_in_odom{1.0, 0.5, 0.3};
  const geometry_msgs::TransformStamped t =
      ToTransformStampedMsg(MapToOdom(base_in_map, base_in_odom), "map", "odom", ros::Time(12.5));
  EXPECT_EQ(t.header.frame_id, "map");
  EXPECT_EQ(t.child_frame_id, "odom");
  EXPECT_EQ(t.header.stamp, ros::Time(12.5));
  const Pose2D again = ToPose2D(t.transform).Compose(base_in_odom);
  EXPECT_NEAR(again.x_m, 2.0, 1e-12);
  EXPECT_NEAR(again.y_m, 1.0, 1e-12);
  EXPECT_NEAR(again.theta_rad, M_PI / 2, 1e-12);
}

// The simulator's camera: the body frame yawed by `yaw_rad` and tilted down a little, the optical frame
// = body rotated by roll -pi/2, yaw -pi/2 (z forward, x right, y down).
geometry_msgs::Transform CameraOptical(double yaw_rad) {
  tf2::Quaternion body, optical_from_body;
  body.setRPY(0.0, 0.1, yaw_rad);
  optical_from_body.setRPY(-M_PI / 2, 0.0, -M_PI / 2);
  geometry_msgs::Transform t;
  t.rotation = tf2::toMsg(body * optical_from_body);
  return t;
}

TEST(ToCameraAxis, IsTheYawOfTheCameraBodyAxis) {
  CameraAxis axis;
  ASSERT_EQ(ToCameraAxis(CameraOptical(M_PI / 2), &axis), "");
  EXPECT_NEAR(axis.yaw_rad, M_PI / 2, 1e-9);
  EXPECT_EQ(axis.bearing_sign, 1.0);
  ASSERT_EQ(ToCameraAxis(CameraOptical(-2.0), &axis), "");
  EXPECT_NEAR(axis.yaw_rad, -2.0, 1e-9);
  geometry_msgs::Transform identity;
  identity.rotation.w = 1.0;  // optical z = base z: straight up
  EXPECT_NE(ToCameraAxis(identity, &axis), "");
}

TEST(ToCameraAxis, ALeftLookingUprightOpticalFrameGivesPlusHalfPiAndPositiveSign) {
  // camera_link yawed +90 deg, optical = camera_link rotated (-90 deg roll, then -90 deg yaw): z forward
  // along camera_link x, x right, y down. In base_link: z -> +y, x -> +x, y -> -z.
  CameraAxis axis;
  axis.bearing_sign = 0.0;
  ASSERT_EQ(ToCameraAxis(Transform(0, 0, 0, -M_PI / 2, 0, 0), &axis), "");
  EXPECT_NEAR(axis.yaw_rad, M_PI / 2, 1e-9);
  EXPECT_EQ(axis.bearing_sign, 1.0);
  // Roll +90 instead: looking right (-y) with the image's y up (upside down). The image's left is then
  // base_link's -x, clockwise from the optical axis.
  ASSERT_EQ(ToCameraAxis(Transform(0, 0, 0, M_PI / 2, 0, 0), &axis), "");
  EXPECT_NEAR(axis.yaw_rad, -M_PI / 2, 1e-9);
  EXPECT_EQ(axis.bearing_sign, -1.0);
  EXPECT_NE(ToCameraAxis(Transform(0, 0, 0, 0, 0, 0), &axis), "");  // optical axis straight up
}

TEST(ToCameraAxis, RefusesAnAxisFarOutOfTheFloorPlaneOrANonFiniteRotationAndKeepsTheOutput) {
  CameraAxis axis{0.5, -1.0};
  // Looking left, pitched 40 deg down (body pitch +40 deg: REP-103 positive pitch tilts x down).
  tf2::Quaternion body, optical_from_body;
  body.setRPY(0.0, 40.0 * M_PI / 180.0, M_PI / 2);
  optical_from_body.setRPY(-M_PI / 2, 0.0, -M_PI / 2);
  geometry_msgs::Transform steep;
  steep.rotation = tf2::toMsg(body * optical_from_body);
  EXPECT_NE(ToCameraAxis(steep, &axis).find("out of the floor plane"), std::string::npos);
  geometry_msgs::Transform nan = Transform(0, 0, 0, -M_PI / 2, 0, 0);
  nan.rotation.x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(ToCameraAxis(nan, &axis), "the camera's rotation is not finite");
  EXPECT_EQ(axis.yaw_rad, 0.5);
  EXPECT_EQ(axis.bearing_sign, -1.0);
}

TEST(CameraLooksLeft, TheCameraSideComesFromTheOpticalAxisInBaseLink) {
  // An optical frame (z forward, x right, y down) looking along base_link +y: the simulator's left camera.
  EXPECT_EQ(CameraLooksLeft(Transform(0, 0, 1.2, -M_PI / 2, 0, 0)), std::optional<bool>(true));
  EXPECT_EQ(CameraLooksLeft(Transform(0, 0, 1.2, -M_PI / 2, 0, M_PI)), std::optional<bool>(false));
  // Looking forward: the optical z axis is base_link +x.
  EXPECT_EQ(CameraLooksLeft(Transform(0, 0, 1.2, -M_PI / 2, 0, -M_PI / 2)), std::nullopt);
  // Looking straight up: no side.
  EXPECT_EQ(CameraLooksLeft(Transform(0, 0, 1.2, 0, 0, 0)), std::nullopt);
}

TEST(ChildAxisInParent, RotatesAnAxisAndTreatsAZeroQuaternionAsIdentity) {
  const tf2::Vector3 y = ChildAxisInParent(Transform(0, 0, 0, 0, 0, M_PI / 2).rotation, tf2::Vector3(1, 0, 0));
  EXPECT_NEAR(y.x(), 0.0, 1e-12);
  EXPECT_NEAR(y.y(), 1.0, 1e-12);
  const tf2::Vector3 same = ChildAxisInParent(geometry_msgs::Quaternion(), tf2::Vector3(0, 0, 1));
  EXPECT_EQ(same.z(), 1.0);
}

TEST(IsFinitePose, NeedsEveryPositionAndQuaternionNumberFinite) {
  geometry_msgs::Pose pose = ToPoseMsg({1.0, 2.0, 0.3});
  EXPECT_TRUE(IsFinitePose(pose));
  EXPECT_NEAR(QuaternionNorm(pose.orientation), 1.0, 1e-12);
  pose.position.z = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(IsFinitePose(pose));
  EXPECT_EQ(QuaternionNorm(geometry_msgs::Quaternion()), 0.0);
}

}  // namespace
}  // namespace doorplate_localization

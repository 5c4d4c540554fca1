#include "mission_bags.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <std_msgs/String.h>
#include <tf2/LinearMath/Quaternion.h>

#include "doorplate_localization/TextDetectionArray.h"

namespace doorplate_localization {
namespace {

geometry_msgs::Pose PoseMsg(double x, double y, double yaw) {
  geometry_msgs::Pose p;
  p.position.x = x;
  p.position.y = y;
  tf2::Quaternion q;
  q.setRPY(0, 0, yaw);
  p.orientation.x = q.x();
  p.orientation.y = q.y();
  p.orientation.z = q.z();
  p.orientation.w = q.w();
  return p;
}

std::string TempBag(const std::string& name) { return ::testing::TempDir() + "/" + name + ".bag"; }

// A 2 m drive east in 1 s steps, a plate read at t = 1.5 (crossed) and one not crossing, states.
std::string WriteRun() {
  const std::string path = TempBag("mission_run");
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  for (int i = 0; i <= 2; ++i) {
    const ros::Time t(10.0 + i);
    nav_msgs::Odometry truth, odom;
    truth.header.stamp = odom.header.stamp = t;
    truth.pose.pose = PoseMsg(1.0 + i, 0.5, 0.0);
    odom.pose.pose = PoseMsg(i, 0.0, 0.0);
    bag.write("/base_pose_ground_truth", t, truth);
    bag.write("odom", t, odom);  // rosbag record keeps names as given: with or without the slash
    geometry_msgs::PoseWithCovarianceStamped estimate;
    estimate.header.stamp = t;
    estimate.pose.pose = PoseMsg(i + 0.1, 0.0, 0.0);
    bag.write("/amcl_pose", t, estimate);
  }
  TextDetectionArray detections;
  detections.header.stamp = ros::Time(11.5);
  TextDetection crossed, passing;
  crossed.text = "214";
  crossed.confidence = 0.9f;
  crossed.crossed_center = true;
  passing.text = "216";
  detections.detections = {crossed, passing};
  bag.write("/text_detections", ros::Time(11.5), detections);
  std_msgs::String state;
  state.data = "converged";
  bag.write("/amcl/state", ros::Time(11.8), state);
  state.data = "arrived: room 214";
  bag.write("/go_to_room/status", ros::Time(12.0), state);
  bag.close();
  return path;
}

TEST(ReadRecordedRunTest, ReadsPosesPlatesAndStatesFromTheirTopics) {
  const RecordedRun run = ReadRecordedRun(WriteRun());
  ASSERT_EQ(run.truth.size(), 3u);
  ASSERT_EQ(run.odometry.size(), 3u);
  ASSERT_EQ(run.estimate.size(), 3u);
  EXPECT_DOUBLE_EQ(run.truth[2].pose.x_m, 3.0);
  EXPECT_DOUBLE_EQ(run.truth[2].time_s, 12.0);
  ASSERT_EQ(run.plates.size(), 1u);  // only the detection that crossed the centre line
  EXPECT_EQ(run.plates[0].text, "214");
  ASSERT_EQ(run.localizer_state.size(), 1u);
  EXPECT_EQ(run.localizer_state[0].text, "converged");
  EXPECT_DOUBLE_EQ(run.localizer_state[0].time_s, 11.8);
  ASSERT_EQ(run.go_to_room_status.size(), 1u);
}

TEST(ReadRecordedRunTest, NamesTheBagWhenItCannotBeUsed) {
  try {
    ReadRecordedRun(TempBag("does_not_exist"));
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("does_not_exist.bag"), std::string::npos) << e.what();
  }
  const std::string empty = TempBag("no_poses");
  { rosbag::Bag bag(empty, rosbag::bagmode::Write); }
  try {
    ReadRecordedRun(empty);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("base_pose_ground_truth"), std::string::npos) << e.what();
  }
}

TEST(PoseAtTimeTest, TakesTheNearestSampleAndClampsAtTheEnds) {
  const std::vector<StampedPose> track{{1.0, {0.0, 0.0, 0.0}}, {2.0, {1.0, 0.0, 0.0}}, {3.0, {2.0, 0.0, 0.0}}};
  EXPECT_DOUBLE_EQ(PoseAtTime(track, 0.0).x_m, 0.0);
  EXPECT_DOUBLE_EQ(PoseAtTime(track, 1.6).x_m, 1.0);
  EXPECT_DOUBLE_EQ(PoseAtTime(track, 2.6).x_m, 2.0);
  EXPECT_DOUBLE_EQ(PoseAtTime(track, 9.0).x_m, 2.0);
}

TEST(WorldFromMapAtFirstNodeTest, AlignsWhereOdometryReadTheFirstNodeNotAtTheBagsStart) {
  RecordedRun run;
  // The robot stands at the start, then turns and drives; odometry turns 0.01 rad more than the robot did
  // and keeps that error. The mapper's first processed scan came at t = 3 (odometry (1, 0.01, 0.06)).
  run.truth = {{0.0, {5.0, 2.0, 0.0}}, {1.0, {5.0, 2.0, 0.0}}, {2.0, {5.5, 2.0, 0.05}}, {3.0, {6.0, 2.02, 0.05}}};
  run.odometry = {{0.0, {0.0, 0.0, 0.0}}, {1.0, {0.0, 0.0, 0.0}}, {2.0, {0.5, 0.0, 0.06}}, {3.0, {1.0, 0.01, 0.06}}};
  const Pose2D at_first_node = WorldFromMapAtFirstNode(run, {1.0, 0.01, 0.06});
  const Pose2D expected = run.truth[3].pose.Compose(run.odometry[3].pose.Inverse());
  EXPECT_NEAR(at_first_node.x_m, expected.x_m, 1e-12);
  EXPECT_NEAR(at_first_node.y_m, expected.y_m, 1e-12);
  EXPECT_NEAR(at_first_node.theta_rad, -0.01, 1e-12) << "the odometry's turn error, which the map frame holds";
  // A node read while standing still: the first of the equal messages (truth and odometry constant there).
  const Pose2D at_rest = WorldFromMapAtFirstNode(run, {0.0, 0.0, 0.0});
  EXPECT_DOUBLE_EQ(at_rest.x_m, 5.0);
  EXPECT_DOUBLE_EQ(at_rest.theta_rad, 0.0);
}

TEST(PathLengthTest, SumsTheStepsInsideTheTimeWindow) {
  const std::vector<StampedPose> track{{1.0, {0.0, 0.0, 0.0}}, {2.0, {3.0, 4.0, 0.0}}, {3.0, {3.0, 5.0, 0.0}}};
  EXPECT_DOUBLE_EQ(PathLength(track, 0.0, 10.0), 6.0);
  EXPECT_DOUBLE_EQ(PathLength(track, 1.5, 3.0), 1.0);
}

}  // namespace
}  // namespace doorplate_localization

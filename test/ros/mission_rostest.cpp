// Checker of mission.test: global localization from an unknown pose, then go to a room, through the
// shipped launch file (launch/localization.launch). Waits (wall-clock timeouts, on conditions) for
// /amcl/state "converged", disables the patrol (/corridor_follower/enable), publishes the room on
// /go_to_room, waits for /go_to_room/status "arrived", then checks the true pose against the plate in the
// ground-truth text map (the built-in maps are in the world frame): in front of the plate within 0.3 m along
// the wall, 0.6 ± 0.15 m from it, facing the door within 10°.
#include <cmath>
#include <functional>
#include <string>

#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <std_srvs/SetBool.h>
#include <tf2/utils.h>

#include "doorplate_localization/maps/text_map.h"
#include "rostest_util.h"

namespace doorplate_localization {
namespace {

using rostest_util::StartsWith;
using rostest_util::WaitFor;

TEST(Mission, LocalizesFromAnUnknownPoseAndReachesTheAskedRoom) {
  ros::NodeHandle nh, pnh("~");
  std::string text_map_file, room;
  ASSERT_TRUE(pnh.getParam("text_map_file", text_map_file));
  ASSERT_TRUE(pnh.getParam("room", room));
  const TextMap truth = LoadTextMap(text_map_file);
  const std::vector<int> plates = truth.Find(room);
  ASSERT_EQ(plates.size(), 1u) << "room " << room << " must be on exactly one plate of " << text_map_file;
  const TextLandmark& plate = truth.landmarks[plates.front()];

  std::string state, status;
  bool has_truth = false;
  Pose2D true_pose;
  auto state_sub = nh.subscribe<std_msgs::String>("amcl/state", 10, [&](const auto& m) { state = m->data; });
  auto status_sub = nh.subscribe<std_msgs::String>("go_to_room/status", 10, [&](const auto& m) { status = m->data; });
  auto truth_sub = nh.subscribe<nav_msgs::Odometry>("base_pose_ground_truth", 10, [&](const auto& m) {
    true_pose = {m->pose.pose.position.x, m->pose.pose.position.y, tf2::getYaw(m->pose.pose.orientation)};
    has_truth = true;
  });
  ASSERT_TRUE(WaitFor([&] { return StartsWith(state, "converged"); }, 240.0)) << "amcl/state: " << state;

  std_srvs::SetBool stop;
  stop.request.data = false;
  ASSERT_TRUE(ros::service::waitForService("corridor_follower/enable", ros::Duration(10.0)));
  ASSERT_TRUE(ros::service::call("corridor_follower/enable", stop));
  auto room_pub = nh.advertise<std_msgs::String>("go_to_room", 1, /*latch=*/true);
  std_msgs::String request;
  request.data = room;
  room_pub.publish(request);
  ASSERT_TRUE(WaitFor([&] { return StartsWith(status, "arrived") || StartsWith(status, "failed") ||
                                   StartsWith(status, "refused"); }, 240.0))
      << "go_to_room/status: " << status;
  ASSERT_TRUE(StartsWith(status, "arrived")) << status;
  ASSERT_TRUE(WaitFor([&] { return has_truth; }, 5.0));

  const Pose2D rel = plate.pose.Between(true_pose);  // x: out of the plate's wall, y: along it
  EXPECT_LT(std::fabs(rel.y_m), 0.3) << "along the wall from plate " << room;
  EXPECT_NEAR(rel.x_m, 0.6, 0.15) << "distance from the wall";
  EXPECT_LT(std::fabs(NormalizeAngle(true_pose.theta_rad - (plate.pose.theta_rad + M_PI))), 10.0 * M_PI / 180.0)
      << "facing the door";
}

}  // namespace
}  // namespace doorplate_localization

int main(int argc, char** argv) {
  return doorplate_localization::rostest_util::RunCheckerTests(argc, argv, "mission_rostest");
}

// Checker of building_floors.test: the two-floor hospital through launch/localization.launch building:=...
// First the localizer, not told the floor, finds it from the plates (amcl/floor) and converges on the true
// pose (amcl_pose against base_pose_ground_truth at the same stamp) within max_localize_sim_s of simulated
// time; then go_to_room to a room of another floor: the status gives the lift instruction, the robot waits at
// the lift's stop, the checker rides the lift (ride_lift, as a user would), the robot localizes on the room's
// floor and stops in front of the room's plate. Every wait is on a condition with a wall-clock timeout.
#include <cmath>
#include <cstdio>
#include <deque>
#include <string>
#include <vector>

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <tf2/utils.h>

#include "doorplate_localization/maps/building_map.h"
#include "rostest_util.h"

namespace doorplate_localization {
namespace {

using rostest_util::PrivateParam;
using rostest_util::StartsWith;
using rostest_util::TruthNear;
using rostest_util::WaitFor;

Pose2D PoseOf(const geometry_msgs::Pose& p) { return {p.position.x, p.position.y, tf2::getYaw(p.orientation)}; }

// What the checker hears: the localizer, the simulator's truth and true floor, go_to_room's statuses.
struct Listener {
  ros::NodeHandle nh;
  std::string floor, state, true_floor;
  std::vector<std::string> statuses;
  std::deque<geometry_msgs::PoseWithCovarianceStamped::ConstPtr> poses;  // the last ~100
  std::deque<nav_msgs::Odometry::ConstPtr> truth;                        // the last ~40 s
  int truths = 0;                                                        // heard in all
  std::vector<ros::Subscriber> subs;

  Listener() {
    const auto text = [this](const char* topic, std::string* into) {
      subs.push_back(nh.subscribe<std_msgs::String>(topic, 10, [into](const std_msgs::String::ConstPtr& m) {
        *into = m->data;
      }));
    };
    text("amcl/floor", &floor);
    text("amcl/state", &state);
    text("corridor_sim/floor", &true_floor);
    subs.push_back(nh.subscribe<std_msgs::String>("go_to_room/status", 50, [this](const std_msgs::String::ConstPtr& m) {
      statuses.push_back(m->data);
      std::printf("go_to_room/status: %s\n", m->data.c_str());
      std::fflush(stdout);
    }));
    subs.push_back(nh.subscribe<geometry_msgs::PoseWithCovarianceStamped>(
        "amcl_pose", 10, [this](const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& m) {
          poses.push_back(m);
          if (poses.size() > 100) poses.pop_front();
        }));
    subs.push_back(nh.subscribe<nav_msgs::Odometry>(
        "base_pose_ground_truth", 100, [this](const nav_msgs::Odometry::ConstPtr& m) {
          truth.push_back(m);
          ++truths;
          if (truth.size() > 2000) truth.pop_front();
        }));
  }

  nav_msgs::Odometry::ConstPtr TruthAt(const ros::Time& stamp) const { return TruthNear(truth, stamp); }
  const std::string& Status() const {
    static const std::string none;
    return statuses.empty() ? none : statuses.back();
  }
  bool Ended() const {
    return StartsWith(Status(), "arrived") || StartsWith(Status(), "failed") || StartsWith(Status(), "refused");
  }
};

Listener* listener = nullptr;

TEST(BuildingFloors, TheLocalizerFindsTheFloorFromThePlatesAndConvergesOnTheTruePose) {
  Listener& l = *listener;
  const std::string start_floor = PrivateParam<std::string>("start_floor");
  ASSERT_TRUE(WaitFor([&] { return l.true_floor == start_floor && !l.floor.empty(); }, 120.0))
      << "simulator floor '" << l.true_floor << "', localizer floor '" << l.floor << "'";
  std::printf("at start: the localizer's floor '%s' (%s), the robot's '%s'\n", l.floor.c_str(), l.state.c_str(),
              l.true_floor.c_str());
  ASSERT_TRUE(WaitFor([&] { return l.floor == start_floor && l.state == "converged"; }, 900.0))
      << "amcl/floor '" << l.floor << "', amcl/state '" << l.state << "'";
  const double converged_s = ros::Time::now().toSec();
  std::printf("the localizer converged on floor %s at %.1f s of simulated time\n", l.floor.c_str(), converged_s);
  EXPECT_LT(converged_s, PrivateParam<double>("max_localize_sim_s"));
  // amcl_pose comes within max_position_error_m of the truth (at the estimate's stamp).
  const double max_error_m = PrivateParam<double>("max_position_error_m");
  double error_m = 1e9;
  EXPECT_TRUE(WaitFor([&] {
    if (l.poses.empty()) return false;
    const auto truth = l.TruthAt(l.poses.back()->header.stamp);
    if (!truth) return false;
    const Pose2D estimate = PoseOf(l.poses.back()->pose.pose), true_pose = PoseOf(truth->pose.pose);
    error_m = Norm(estimate.Position() - true_pose.Position());
    return error_m < max_error_m;
  }, 60.0)) << "last amcl_pose " << error_m << " m from the truth";
  std::printf("amcl_pose %.3f m from the truth on floor %s\n", error_m, l.floor.c_str());
  EXPECT_EQ(l.true_floor, start_floor);
}

TEST(BuildingFloors, GoesToARoomOnAnotherFloorByTheLiftTheCheckerRides) {
  Listener& l = *listener;
  const std::string room = PrivateParam<std::string>("room"), room_floor = PrivateParam<std::string>("room_floor");
  const std::string building_file = PrivateParam<std::string>("building_file");
  const BuildingMaps maps = LoadBuildingMaps(LoadBuildingFile(building_file), building_file);
  ros::NodeHandle nh;
  ros::Publisher request = nh.advertise<std_msgs::String>("go_to_room", 1, /*latch=*/true);
  ros::Publisher ride = nh.advertise<std_msgs::String>("ride_lift", 1, /*latch=*/false);
  ASSERT_TRUE(WaitFor([&] { return request.getNumSubscribers() > 0 && ride.getNumSubscribers() > 0; }, 60.0))
      << "go_to_room and the simulator (one manager, one connection) subscribe ride_lift";
  l.statuses.clear();
  std_msgs::String msg;
  msg.data = room;
  request.publish(msg);

  // The route: "to_lift: room 256 is on floor 2: take lift A from floor 3 to floor 2 (wait at ...)".
  const std::string instruction = "to_lift: room " + room + " is on floor " + room_floor + ": take lift ";
  std::string lift;
  ASSERT_TRUE(WaitFor([&] {
    for (const std::string& s : l.statuses) {
      if (StartsWith(s, instruction)) {
        lift = s.substr(instruction.size(), s.find(' ', instruction.size()) - instruction.size());
      }
    }
    return !lift.empty() || l.Ended();
  }, 120.0)) << "go_to_room/status: " << l.Status();
  ASSERT_FALSE(lift.empty()) << l.Status();
  ASSERT_TRUE(WaitFor([&] { return StartsWith(l.Status(), "waiting_for_lift:") || l.Ended(); }, 400.0))
      << "go_to_room/status: " << l.Status();
  ASSERT_TRUE(StartsWith(l.Status(), "waiting_for_lift: waiting for lift " + lift + " to floor " + room_floor))
      << l.Status();
  const Lift* the_lift = nullptr;
  for (const Lift& candidate : maps.lifts) the_lift = candidate.id == lift ? &candidate : the_lift;
  ASSERT_NE(the_lift, nullptr) << "lift '" << lift << "'";
  const LiftStop* stop = the_lift->StopOn(l.true_floor);
  ASSERT_NE(stop, nullptr);
  ASSERT_FALSE(l.truth.empty());
  const Pose2D at_lift = PoseOf(l.truth.back()->pose.pose);
  std::printf("waiting at (%.2f, %.2f), %.3f m from the stop of lift %s on floor %s\n", at_lift.x_m, at_lift.y_m,
              Norm(at_lift.Position() - stop->pose.Position()), lift.c_str(), l.true_floor.c_str());
  EXPECT_LT(Norm(at_lift.Position() - stop->pose.Position()), 0.3);

  // Rides the simulator cannot make are refused naming the topic and the message; nothing moves, go_to_room
  // keeps waiting: the other lift (its stop is 2 m away), a floor the building does not have.
  const rostest_util::RosoutLog warnings;
  const std::string other_lift = lift == "A" ? "B" : "A";
  for (const std::string& bad : {other_lift + " " + room_floor, lift + " 9"}) {
    msg.data = bad;
    int tries = 0;  // again about once a second, until /rosout is connected
    EXPECT_TRUE(WaitFor([&] { return warnings.Has("/ride_lift: '" + bad + "': ", "the robot stays"); }, 30.0,
                        [&] { if (tries++ % 50 == 0) ride.publish(msg); }))
        << bad;
  }
  EXPECT_EQ(l.true_floor, PrivateParam<std::string>("start_floor"));
  EXPECT_TRUE(StartsWith(l.Status(), "waiting_for_lift:")) << l.Status();

  msg.data = lift + " " + room_floor;
  ride.publish(msg);
  ASSERT_TRUE(WaitFor([&] { return l.true_floor == room_floor; }, 30.0)) << "the simulator's floor " << l.true_floor;
  ASSERT_TRUE(WaitFor([&] { return l.Ended(); }, 900.0)) << "go_to_room/status: " << l.Status();
  ASSERT_TRUE(StartsWith(l.Status(), "arrived: room " + room)) << l.Status();
  bool searched = false;
  for (const std::string& s : l.statuses) {
    searched = searched || StartsWith(s, "localizing: room " + room + ": rode lift");
  }
  EXPECT_TRUE(searched) << "no 'localizing: ... rode lift' status after the ride";
  EXPECT_EQ(l.floor, room_floor);

  // In front of the room's plate on its floor (the built-in maps are the worlds' ground truth).
  const TextMap& text_map = *maps.floors[static_cast<size_t>(maps.FloorIndex(room_floor))].text_map;
  ASSERT_EQ(text_map.Find(room).size(), 1u);
  const Pose2D& plate = text_map.landmarks[static_cast<size_t>(text_map.Find(room).front())].pose;
  const int heard = l.truths;
  ASSERT_TRUE(WaitFor([&] { return l.truths > heard; }, 10.0)) << "no ground truth since the arrival";
  const Pose2D robot = PoseOf(l.truth.back()->pose.pose);
  const Pose2D rel = plate.Between(robot);  // x: out of the plate's wall, y: along it
  std::printf("room %s: true pose (%.2f, %.2f, %.2f rad): %.3f m along the plate, %.3f m from its wall\n",
              room.c_str(), robot.x_m, robot.y_m, robot.theta_rad, rel.y_m, rel.x_m);
  EXPECT_LT(std::fabs(rel.y_m), 0.3) << "along the wall from plate " << room;
  EXPECT_NEAR(rel.x_m, 0.6, 0.15) << "distance from the wall";
  EXPECT_LT(std::fabs(NormalizeAngle(robot.theta_rad - (plate.theta_rad + M_PI))), 10.0 * M_PI / 180.0)
      << "facing the door";
}

}  // namespace
}  // namespace doorplate_localization

int main(int argc, char** argv) {
  return doorplate_localization::rostest_util::RunCheckerTests(argc, argv, "building_floors_checker", [] {
    doorplate_localization::Listener listener;  // after ros::init: it subscribes
    doorplate_localization::listener = &listener;
    return RUN_ALL_TESTS();
  });
}

// Checker node of bad_input_nodelets.test (issue 8): the simulator and the wall follower get broken
// messages; each must be reported on /rosout naming the topic, and the nodelets must keep working. Every
// wait is on a condition with a wall-clock timeout.
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <string>

#include <geometry_msgs/Pose2D.h>
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>
#include "rostest_util.h"

namespace doorplate_localization {
namespace {

using rostest_util::WaitFor;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

struct Listener {
  ros::NodeHandle nh;
  sensor_msgs::LaserScan::ConstPtr scan;  // the simulator's latest
  int scans = 0;
  geometry_msgs::Twist::ConstPtr follower_cmd;
  int follower_cmds = 0;
  std::string follower_state;
  rostest_util::RosoutLog logs;  // WARN and above from /rosout
  ros::Subscriber subs[3];

  Listener() {
    subs[0] = nh.subscribe<sensor_msgs::LaserScan>("scan", 5, [this](const sensor_msgs::LaserScan::ConstPtr& m) {
      scan = m;
      ++scans;
    });
    subs[1] = nh.subscribe<geometry_msgs::Twist>("follower_cmd_vel", 20, [this](const geometry_msgs::Twist::ConstPtr& m) {
      follower_cmd = m;
      ++follower_cmds;
    });
    subs[2] = nh.subscribe<std_msgs::String>("corridor_follower/state", 10,
                                             [this](const std_msgs::String::ConstPtr& m) { follower_state = m->data; });
  }

  // A WARN/ERROR log holding both `topic` and `text`.
  bool Logged(const std::string& topic, const std::string& text) const { return logs.Has(topic, text); }
};

Listener* listener = nullptr;

TEST(CorridorSimNodelet, IgnoresNonFiniteCommandsAndTeleportsNamingTheTopicAndKeepsPublishing) {
  ros::NodeHandle nh;
  ros::Publisher cmd_pub = nh.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  ros::Publisher teleport_pub = nh.advertise<geometry_msgs::Pose2D>("corridor_sim/teleport", 1);
  ASSERT_TRUE(WaitFor([] { return listener->scans > 0; }, 60.0)) << "no scan from the simulator";
  geometry_msgs::Twist nan_cmd;
  nan_cmd.linear.x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(WaitFor([] { return listener->Logged("/cmd_vel", "ignoring non-finite command"); }, 30.0,
                      [&] { cmd_pub.publish(nan_cmd); }));
  geometry_msgs::Pose2D nan_pose;
  nan_pose.x = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(WaitFor([] { return listener->Logged("/corridor_sim/teleport", "ignoring a non-finite pose"); }, 30.0,
                      [&] { teleport_pub.publish(nan_pose); }));
  const int before = listener->scans;
  EXPECT_TRUE(WaitFor([&] { return listener->scans > before + 5; }));
  for (float r : listener->scan->ranges) EXPECT_FALSE(std::isnan(r));  // the robot is still somewhere sane
}

TEST(WallFollowerNodelet, StopsOnBadScansNamingTheTopicAndDrivesAgainOnAGoodOne) {
  ros::NodeHandle nh;
  ros::Publisher scan_pub = nh.advertise<sensor_msgs::LaserScan>("follower_scan", 1);
  ASSERT_TRUE(WaitFor([] { return listener->scan != nullptr; }, 60.0)) << "no scan from the simulator";
  const auto bad = [](const std::function<void(sensor_msgs::LaserScan*)>& spoil) {
    sensor_msgs::LaserScan s = *listener->scan;
    s.header.stamp = ros::Time::now();
    spoil(&s);
    return s;
  };
  struct Case {
    const char* name;
    std::function<void(sensor_msgs::LaserScan*)> spoil;
    const char* message;
  };
  const Case cases[] = {
      {"NaN increment", [](sensor_msgs::LaserScan* s) { s->angle_increment = kNaN; }, "angle_increment must be finite"},
      {"no ranges", [](sensor_msgs::LaserScan* s) { s->ranges.clear(); }, "no ranges"},
      {"unknown frame", [](sensor_msgs::LaserScan* s) { s->header.frame_id = "nowhere"; }, "no tf from 'nowhere' to 'base_link'"},
  };
  for (const Case& c : cases) {
    const sensor_msgs::LaserScan scan = bad(c.spoil);
    EXPECT_TRUE(WaitFor([&] { return listener->Logged("/follower_scan", c.message); }, 30.0,
                        [&] { scan_pub.publish(scan); }))
        << c.name;
    // The log comes through /rosout; the state and the stop command on their own topics.
    const auto stopped = [] {
      const auto& cmd = listener->follower_cmd;
      return listener->follower_state == "no_valid_scan" && cmd && cmd->linear.x == 0.0 && cmd->angular.z == 0.0;
    };
    EXPECT_TRUE(WaitFor(stopped, 30.0, [&] { scan_pub.publish(scan); })) << c.name << ": " << listener->follower_state;
  }
  // Valid geometry but not one usable range (NaN, -inf, negative): no wall to follow, nothing to drive on.
  const sensor_msgs::LaserScan blind = bad([](sensor_msgs::LaserScan* s) {
    for (size_t i = 0; i < s->ranges.size(); ++i) {
      s->ranges[i] = i % 3 == 0 ? kNaN : i % 3 == 1 ? -std::numeric_limits<float>::infinity() : -1.0f;
    }
  });
  EXPECT_TRUE(WaitFor([] { return listener->follower_state == "no_wall"; }, 30.0, [&] { scan_pub.publish(blind); }))
      << listener->follower_state;
  // A good scan again (the simulator's): the follower drives on.
  EXPECT_TRUE(WaitFor([] { return listener->follower_cmd && listener->follower_cmd->linear.x > 0.0; }, 30.0,
                      [&] { scan_pub.publish(bad([](sensor_msgs::LaserScan*) {})); }))
      << listener->follower_state;
}

}  // namespace
}  // namespace doorplate_localization

int main(int argc, char** argv) {
  return doorplate_localization::rostest_util::RunCheckerTests(argc, argv, "bad_input_checker", [] {
    doorplate_localization::Listener listener;  // after ros::init: it subscribes
    doorplate_localization::listener = &listener;
    return RUN_ALL_TESTS();
  });
}

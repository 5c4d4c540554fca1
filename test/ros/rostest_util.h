// Helpers shared by the rostest checker nodes (test/ros/*_rostest.cpp): waiting on a condition with a
// wall-clock timeout while processing callbacks, prefix tests, reading the checker's private parameters,
// capturing /rosout, and checking that an option loader's error names the parameter. Header-only; the
// checkers are single-threaded (callbacks run inside WaitFor, on the global callback queue).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <string>

#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>

namespace doorplate_localization {
namespace rostest_util {

// Processes callbacks until `condition` holds (true) or `timeout_s` of wall time pass (false); `each` runs
// before every check.
inline bool WaitFor(const std::function<bool()>& condition, double timeout_s = 30.0,
                    const std::function<void()>& each = [] {}) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout_s);
  while (ros::ok() && ros::WallTime::now() < deadline) {
    each();
    if (condition()) return true;
    ros::getGlobalCallbackQueue()->callAvailable(ros::WallDuration(0.02));
  }
  return false;
}

inline bool StartsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

// The ground-truth message (the simulator's base_pose_ground_truth) closest in time to `stamp` among
// `truth`; null if none is within `max_dt_s`.
inline nav_msgs::Odometry::ConstPtr TruthNear(const std::deque<nav_msgs::Odometry::ConstPtr>& truth,
                                              const ros::Time& stamp, double max_dt_s = 0.1) {
  nav_msgs::Odometry::ConstPtr best;
  double best_dt = max_dt_s;
  for (const auto& m : truth) {
    const double dt = std::fabs((m->header.stamp - stamp).toSec());
    if (dt <= best_dt) {
      best_dt = dt;
      best = m;
    }
  }
  return best;
}

// The checker's private parameter ~name; a missing or mistyped one is a test failure ("missing ~name")
// and gives T{}.
template <typename T>
T PrivateParam(const std::string& name) {
  T value{};
  EXPECT_TRUE(ros::NodeHandle("~").getParam(name, value)) << "missing ~" << name;
  return value;
}

// The /rosout messages at `min_level` or above (rosgraph_msgs::Log::WARN, ERROR, ...), the newest `keep`
// of them, from construction on (delivered by WaitFor's callback processing).
class RosoutLog {
 public:
  explicit RosoutLog(std::uint8_t min_level = rosgraph_msgs::Log::WARN, std::size_t keep = 500)
      : min_level_(min_level), keep_(keep) {
    sub_ = nh_.subscribe<rosgraph_msgs::Log>("/rosout", 200, [this](const rosgraph_msgs::Log::ConstPtr& m) {
      if (m->level < min_level_) return;
      messages_.push_back(m->msg);
      if (messages_.size() > keep_) messages_.pop_front();
    });
  }
  RosoutLog(const RosoutLog&) = delete;
  RosoutLog& operator=(const RosoutLog&) = delete;

  // True if one message contains both `a` and `b` (e.g. the topic and the problem).
  bool Has(const std::string& a, const std::string& b = "") const {
    for (const std::string& m : messages_) {
      if (m.find(a) != std::string::npos && m.find(b) != std::string::npos) return true;
    }
    return false;
  }
  const std::deque<std::string>& messages() const { return messages_; }

 private:
  ros::NodeHandle nh_;
  std::uint8_t min_level_;
  std::size_t keep_;
  std::deque<std::string> messages_;
  ros::Subscriber sub_;
};

// Expects load(nh) (a Load...Options function) to throw an Error (ParameterError) whose message contains
// `parameter` resolved in nh.
template <typename Error, typename Load>
void ExpectLoadErrorNaming(const Load& load, const ros::NodeHandle& nh, const std::string& parameter) {
  try {
    load(nh);
    ADD_FAILURE() << "no error for " << parameter;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(nh.resolveName(parameter)), std::string::npos) << e.what();
  }
}

// A checker's main(): gtest's and ros::init's arguments, the node named `node_name`, kept up for the whole
// run by one NodeHandle (the node would shut down each time a test's last handle goes), then run()'s status
// (by default RUN_ALL_TESTS(); a checker with a shared listener makes it there first).
inline int RunCheckerTests(int argc, char** argv, const std::string& node_name,
                           const std::function<int()>& run = [] { return RUN_ALL_TESTS(); }) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, node_name);
  ros::NodeHandle keep_node_alive;
  return run();
}

}  // namespace rostest_util
}  // namespace doorplate_localization

// Checker of text_amcl_reconfigure.test: amcl's dynamic_reconfigure service (/amcl/set_parameters) on a
// running Text AMCL. Waits on conditions (service up, replies, published clouds), never on sleeps.
#include <string>

#include <dynamic_reconfigure/Reconfigure.h>
#include <geometry_msgs/PoseArray.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>

#include "rostest_util.h"

namespace doorplate_localization {
namespace {

using rostest_util::WaitFor;

// Sets one parameter through the service; the reply's config (the values in force afterwards).
dynamic_reconfigure::Config Set(const std::string& name, double value, bool is_int) {
  dynamic_reconfigure::Reconfigure srv;
  if (is_int) {
    dynamic_reconfigure::IntParameter p;
    p.name = name;
    p.value = static_cast<int>(value);
    srv.request.config.ints.push_back(p);
  } else {
    dynamic_reconfigure::DoubleParameter p;
    p.name = name;
    p.value = value;
    srv.request.config.doubles.push_back(p);
  }
  EXPECT_TRUE(ros::service::call("/amcl/set_parameters", srv)) << name;
  return srv.response.config;
}

double Value(const dynamic_reconfigure::Config& config, const std::string& name) {
  for (const auto& p : config.ints) {
    if (p.name == name) return p.value;
  }
  for (const auto& p : config.doubles) {
    if (p.name == name) return p.value;
  }
  ADD_FAILURE() << name << " is not in the reply";
  return std::nan("");
}

TEST(TextAmclReconfigure, AGoodValueTakesEffectAndBadOnesAreRefusedKeepingTheValuesInForce) {
  ros::NodeHandle nh;
  rostest_util::RosoutLog log(rosgraph_msgs::Log::INFO);
  geometry_msgs::PoseArray::ConstPtr cloud;
  ros::Subscriber cloud_sub = nh.subscribe<geometry_msgs::PoseArray>(
      "/particlecloud", 2, [&](const geometry_msgs::PoseArray::ConstPtr& m) { cloud = m; });
  ASSERT_TRUE(WaitFor([] { return ros::service::exists("/amcl/set_parameters", false); }, 60.0));
  ASSERT_TRUE(WaitFor([&] { return cloud != nullptr; })) << "no particlecloud";
  EXPECT_EQ(cloud->poses.size(), 1000u) << "~max_particles as loaded";

  // Good: the reply, the parameter server and the next global localization (it draws max_particles).
  EXPECT_EQ(Value(Set("max_particles", 300, true), "max_particles"), 300.0);
  int on_server = 0;
  EXPECT_TRUE(nh.getParam("/amcl/max_particles", on_server));
  EXPECT_EQ(on_server, 300);
  EXPECT_TRUE(WaitFor([&] { return log.Has("/amcl/set_parameters", "max_particles 1000 -> 300"); }));
  cloud.reset();
  std_srvs::Empty empty;
  ASSERT_TRUE(ros::service::call("/global_localization", empty));
  ASSERT_TRUE(WaitFor([&] { return cloud != nullptr; }));
  EXPECT_EQ(cloud->poses.size(), 300u) << "the reconfigured max_particles";

  // Bad: an open end of a range (kld_err > 0), and a pair each valid alone (min_particles > max_particles).
  EXPECT_DOUBLE_EQ(Value(Set("kld_err", 0.0, false), "kld_err"), 0.01);
  EXPECT_TRUE(WaitFor([&] { return log.Has("refused: /amcl/kld_err must be finite and > 0, got 0.0"); }));
  EXPECT_EQ(Value(Set("min_particles", 400, true), "min_particles"), 100.0);
  EXPECT_TRUE(WaitFor([&] { return log.Has("refused: /amcl/min_particles = 400, /amcl/max_particles = 300"); }));
  double kld_err = 0.0;
  EXPECT_TRUE(nh.getParam("/amcl/kld_err", kld_err));
  EXPECT_DOUBLE_EQ(kld_err, 0.01);
  cloud.reset();
  ASSERT_TRUE(ros::service::call("/global_localization", empty));
  ASSERT_TRUE(WaitFor([&] { return cloud != nullptr; }));
  EXPECT_EQ(cloud->poses.size(), 300u) << "a refused request changed the filter";
}

}  // namespace
}  // namespace doorplate_localization

int main(int argc, char** argv) {
  return doorplate_localization::rostest_util::RunCheckerTests(argc, argv, "text_amcl_reconfigure_checker");
}

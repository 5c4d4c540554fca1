// LoadTextAmclOptions (src/ros/text_amcl_options.cpp) on a parameter server: amcl's defaults, an error naming
// the parameter for every bad value, and the shipped config/text_amcl.yaml as text_amcl_nodelet.test loads it
// under /amcl. Run by that .test beside text_amcl_nodelet_rostest (one roscore for both).
#include <cmath>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <ros/ros.h>

#include "text_amcl_options.h"
#include "rostest_util.h"

namespace doorplate_localization {
namespace {

// Parameters set under this node's private namespace.
TEST(LoadTextAmclOptions, WithoutParametersGivesAmclsDefaultsExceptRecovery) {
  const TextAmclNodeOptions o = LoadTextAmclOptions(ros::NodeHandle("~empty"));
  EXPECT_EQ(o.session.setup.filter.min_particles, 100);
  EXPECT_EQ(o.session.setup.filter.max_particles, 5000);
  EXPECT_DOUBLE_EQ(o.session.setup.filter.kld_err, 0.01);
  EXPECT_DOUBLE_EQ(o.session.setup.filter.update_min_a_rad, M_PI / 6.0);
  EXPECT_EQ(o.session.setup.likelihood_field.beams.laser_max_beams, 30);  // amcl's (the core's: 60)
  EXPECT_EQ(o.session.setup.beam.beams.laser_max_beams, 30);
  EXPECT_EQ(o.session.setup.laser_model_type, LaserModelType::kLikelihoodField);
  EXPECT_EQ(o.session.setup.motion.noise_law, OdometryNoiseLaw::kDiff);
  EXPECT_DOUBLE_EQ(o.session.setup.filter.recovery_alpha_slow, 0.001);  // amcl: 0 (documented)
  EXPECT_DOUBLE_EQ(o.transform_tolerance_s, 0.1);
  EXPECT_DOUBLE_EQ(o.session.initial_covariance(0, 0), 0.25);
  EXPECT_DOUBLE_EQ(o.session.initial_covariance(2, 2), (M_PI / 12.0) * (M_PI / 12.0));
  EXPECT_EQ(o.global_frame_id, "map");
  EXPECT_FALSE(o.use_map_topic);
  EXPECT_TRUE(o.map_file.empty());
}

void ExpectErrorNaming(const ros::NodeHandle& nh, const std::string& parameter) {
  rostest_util::ExpectLoadErrorNaming<ParameterError>(LoadTextAmclOptions, nh, parameter);
}

TEST(LoadTextAmclOptions, RejectsOutOfRangeMistypedAndUnsupportedValuesNamingTheParameter) {
  ros::NodeHandle nh("~bad");
  const std::pair<std::string, XmlRpc::XmlRpcValue> cases[] = {
      {"kld_err", XmlRpc::XmlRpcValue(0.0)},
      {"min_particles", XmlRpc::XmlRpcValue("many")},
      {"odom_model_type", XmlRpc::XmlRpcValue("omni")},
      {"laser_model_type", XmlRpc::XmlRpcValue("sonar")},
      {"laser_z_hit", XmlRpc::XmlRpcValue(1.5)},
      {"base_frame_id", XmlRpc::XmlRpcValue("/base_link")},
      {"selective_resampling", XmlRpc::XmlRpcValue(true)},
      {"recovery_alpha_fast", XmlRpc::XmlRpcValue(0.0001)},  // < recovery_alpha_slow (0.001)
      {"text_max_view_angle_rad", XmlRpc::XmlRpcValue(2.0)},
      {"max_particles", XmlRpc::XmlRpcValue(1000000000)},  // above limits::kMaxParticles (was std::bad_alloc)
      {"scan_timeout_s", XmlRpc::XmlRpcValue("soon")},
  };
  for (const auto& c : cases) {
    nh.setParam(c.first, c.second);
    ExpectErrorNaming(nh, c.first);
    nh.deleteParam(c.first);
  }
  nh.setParam("max_particles", 50);  // < min_particles
  ExpectErrorNaming(nh, "max_particles");
}

TEST(LoadTextAmclOptions, TheShippedConfigLoads) {
  const TextAmclNodeOptions o = LoadTextAmclOptions(ros::NodeHandle("/amcl"));
  EXPECT_EQ(o.session.setup.likelihood_field.beams.laser_max_beams, 60);
  EXPECT_EQ(o.session.setup.motion.noise_law, OdometryNoiseLaw::kDiffCorrected);
  EXPECT_TRUE(o.session.setup.use_text);
  EXPECT_NE(o.map_file.find("paper_sim_closed_doors.yaml"), std::string::npos);
  EXPECT_NE(o.text_map_file.find("paper_sim_closed_doors.text_map.yaml"), std::string::npos);
}

}  // namespace
}  // namespace doorplate_localization

int main(int argc, char** argv) {
  return doorplate_localization::rostest_util::RunCheckerTests(argc, argv, "text_amcl_options_checker");
}

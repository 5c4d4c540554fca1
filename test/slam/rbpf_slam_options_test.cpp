#include "doorplate_localization/slam/rbpf_slam_options.h"

#include <algorithm>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

TEST(RbpfSlamOptions, EveryNamedOptionCanBeSetAndReadBack) {
  RbpfSlamOptions options;
  const std::vector<std::string> names = RbpfSlamOptionNames();
  EXPECT_GT(names.size(), 30u);
  for (const std::string& name : names) {
    const double value = GetRbpfSlamOption(name, options) + 3.0;  // whole, so integer options take it
    SetRbpfSlamOption(name, value, &options);
    EXPECT_EQ(GetRbpfSlamOption(name, options), value) << name;
  }
}

TEST(RbpfSlamOptions, NamesFollowTheStructFields) {
  RbpfSlamOptions options;
  SetRbpfSlamOption("matcher.field_sigma_m", 0.07, &options);
  SetRbpfSlamOption("num_particles", 12, &options);
  SetRbpfSlamOption("motion.rot_noise_from_trans", 0.03, &options);
  EXPECT_EQ(options.matcher.field_sigma_m, 0.07);
  EXPECT_EQ(options.num_particles, 12);
  EXPECT_EQ(options.motion.rot_noise_from_trans, 0.03);
}

TEST(RbpfSlamOptions, UnknownNamesAndFractionalCountsAreErrorsNamingTheOption) {
  RbpfSlamOptions options;
  try {
    SetRbpfSlamOption("matcher.sigma", 1.0, &options);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("matcher.sigma"), std::string::npos);
  }
  EXPECT_THROW(SetRbpfSlamOption("num_particles", 2.5, &options), std::invalid_argument);
  EXPECT_EQ(options.num_particles, RbpfSlamOptions{}.num_particles);
}

}  // namespace
}  // namespace doorplate_localization

// The laser part of a world file's `sensors` block (src/sim/world_sensor_fields.cpp), through ParseWorldYaml.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "doorplate_localization/sim/world_loader.h"

namespace doorplate_localization {
namespace {

const char* kMinimal = R"(
format_version: 1
name: tiny
walls:
  - {id: south, from: [0, 0], to: [10, 0], corridor_side: left}
  - {id: north, from: [0, 2], to: [10, 2], corridor_side: right}
robot:
  start: {x_m: 1, y_m: 1, theta_deg: 90}
)";

World WithLaser(const std::string& laser) {
  return ParseWorldYaml(std::string(kMinimal) + "sensors: {laser: " + laser + "}\n", "w.yaml");
}

std::string ErrorOf(const std::string& laser) {
  try {
    WithLaser(laser);
  } catch (const WorldFileError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(WorldSensorFields, TheLaserErrorModelIsGaussianUnlessTheWorldSaysFitted) {
  EXPECT_EQ(ParseWorldYaml(kMinimal, "w.yaml").sensors.laser.error_model, "gaussian");
  const LaserOptions fitted = WithLaser("{error_model: fitted}").sensors.laser;
  EXPECT_EQ(fitted.error_model, "fitted");
  EXPECT_DOUBLE_EQ(fitted.fitted.noise_base_m, FittedLaserErrorOptions{}.noise_base_m);  // the fitted defaults
}

TEST(WorldSensorFields, EveryFittedParameterCanBeOverridden) {
  const FittedLaserErrorOptions f =
      WithLaser("{error_model: fitted, fitted: {noise_base_m: 0.02, noise_fraction: 0.003, noise_grazing_gain: 0.1, "
                "dropout_probability: 0.02, dropout_per_m: 0.001, dropout_grazing_probability: 0.3, "
                "dropout_grazing_from_deg: 70, depth_edge_m: 0.4, mixed_pixel_probability: 0.2, "
                "short_probability: 0.01, short_mean_m: 1.5}}")
          .sensors.laser.fitted;
  EXPECT_DOUBLE_EQ(f.noise_base_m, 0.02);
  EXPECT_DOUBLE_EQ(f.noise_fraction, 0.003);
  EXPECT_DOUBLE_EQ(f.noise_grazing_gain, 0.1);
  EXPECT_DOUBLE_EQ(f.dropout_probability, 0.02);
  EXPECT_DOUBLE_EQ(f.dropout_per_m, 0.001);
  EXPECT_DOUBLE_EQ(f.dropout_grazing_probability, 0.3);
  EXPECT_DOUBLE_EQ(f.dropout_grazing_from_deg, 70);
  EXPECT_DOUBLE_EQ(f.depth_edge_m, 0.4);
  EXPECT_DOUBLE_EQ(f.mixed_pixel_probability, 0.2);
  EXPECT_DOUBLE_EQ(f.short_probability, 0.01);
  EXPECT_DOUBLE_EQ(f.short_mean_m, 1.5);
}

TEST(WorldSensorFields, BadLaserErrorFieldsAreNamed) {
  EXPECT_EQ(ErrorOf("{error_model: sick}"), "w.yaml: sensors.laser.error_model: must be 'gaussian' or 'fitted', got 'sick'");
  EXPECT_EQ(ErrorOf("{error_model: fitted, fitted: {short_probability: 2}}"),
            "w.yaml: sensors.laser.fitted.short_probability: must be in [0, 1]");
  EXPECT_EQ(ErrorOf("{error_model: fitted, fitted: {dropout_grazing_from_deg: 90}}"),
            "w.yaml: sensors.laser.fitted.dropout_grazing_from_deg: must be in [0, 90)");
  EXPECT_NE(ErrorOf("{error_model: fitted, fitted: {noise_sigma: 1}}").find("w.yaml: sensors.laser.fitted"),
            std::string::npos);
  // A parameter of the model not in use would be ignored: refused.
  EXPECT_EQ(ErrorOf("{fitted: {short_probability: 0.1}}"),
            "w.yaml: sensors.laser.fitted: is only used with error_model: fitted");
  EXPECT_EQ(ErrorOf("{error_model: fitted, range_noise_stddev_m: 0.02}"),
            "w.yaml: sensors.laser.range_noise_stddev_m: is a parameter of error_model 'gaussian'; set fitted.* "
            "instead");
}

// The odometry part: sensors.odometry.slip.
OdometryNoiseOptions WithOdometry(const std::string& odometry) {
  return ParseWorldYaml(std::string(kMinimal) + "sensors: {odometry: " + odometry + "}\n", "w.yaml").sensors.odometry;
}

TEST(WorldSensorFields, OdometrySlipIsOffUnlessTheWorldOptsIn) {
  EXPECT_FALSE(ParseWorldYaml(kMinimal, "w.yaml").sensors.odometry.slip.Enabled());
  const OdometrySlipOptions slip =
      WithOdometry("{slip: {scale_stddev: 0.01, scale_correlation_length_m: 12, turn_scale_error_m_per_rad: 0.1, "
                   "turn_rotation_error_rad_per_rad: 0.04}}")
          .slip;
  EXPECT_TRUE(slip.Enabled());
  EXPECT_DOUBLE_EQ(slip.scale_stddev, 0.01);
  EXPECT_DOUBLE_EQ(slip.scale_correlation_length_m, 12);
  EXPECT_DOUBLE_EQ(slip.turn_scale_error_m_per_rad, 0.1);
  EXPECT_DOUBLE_EQ(slip.turn_rotation_error_rad_per_rad, 0.04);
}

TEST(WorldSensorFields, BadOdometrySlipFieldsAreNamed) {
  auto error_of = [](const std::string& odometry) -> std::string {
    try {
      WithOdometry(odometry);
    } catch (const WorldFileError& e) {
      return e.what();
    }
    return "(no error)";
  };
  EXPECT_NE(error_of("{slip: {scale_stddev: -0.1}}").find("scale_stddev"), std::string::npos);
  EXPECT_NE(error_of("{slip: {scale_correlation_length_m: 0}}").find("scale_correlation_length_m"), std::string::npos);
  EXPECT_NE(error_of("{slip: {turn_rotation_error_rad_per_rad: 0.7}}").find("turn_rotation_error_rad_per_rad"),
            std::string::npos);
  EXPECT_NE(error_of("{slip: {turn_scale_error_m_per_rad: 2}}").find("turn_scale_error_m_per_rad"), std::string::npos);
  EXPECT_NE(error_of("{slip: {scale_sd: 0.1}}").find("scale_sd"), std::string::npos);  // unknown key
}

}  // namespace
}  // namespace doorplate_localization

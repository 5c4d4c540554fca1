#include "doorplate_localization/sim/odometry_simulator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace doorplate_localization {
namespace {

struct Stats {
  double mean = 0.0, stddev = 0.0;
};

Stats Summarize(const std::vector<double>& v) {
  Stats s;
  for (double x : v) s.mean += x;
  s.mean /= v.size();
  for (double x : v) s.stddev += (x - s.mean) * (x - s.mean);
  s.stddev = std::sqrt(s.stddev / (v.size() - 1));
  return s;
}

// Drives `distance_m` straight along x in steps of `step_m`; returns the final odometry pose.
Pose2D DriveStraight(const OdometryNoiseOptions& options, double distance_m, double step_m, std::mt19937_64& rng) {
  OdometrySimulator odom(options);
  Pose2D truth;
  const int steps = static_cast<int>(std::lround(distance_m / step_m));
  for (int i = 0; i < steps; ++i) {
    Pose2D next = truth;
    next.x_m += step_m;
    odom.Update(truth, next, rng);
    truth = next;
  }
  return odom.pose();
}

TEST(OdometrySimulator, NoiseFreeOdometryFollowsTheTruthExactly) {
  OdometryNoiseOptions options;
  options.alpha1_rad2_per_rad = options.alpha2_rad2_per_m = options.alpha3_m2_per_m = options.alpha4_m2_per_rad = 0;
  options.scale_error = options.heading_drift_rad_per_m = 0;
  OdometrySimulator odom(options);
  std::mt19937_64 rng(1);
  const Pose2D a{0, 0, 0}, b{1.0, 0.5, 0.8}, c{0.2, 0.9, -2.5};
  odom.Update(a, b, rng);
  const Pose2D end = odom.Update(b, c, rng);
  EXPECT_NEAR(end.x_m, c.x_m, 1e-9);
  EXPECT_NEAR(end.y_m, c.y_m, 1e-9);
  EXPECT_NEAR(end.theta_rad, c.theta_rad, 1e-9);
}

TEST(OdometrySimulator, ScaleErrorAndTranslationNoiseMatchTheirOptions) {
  OdometryNoiseOptions options;  // defaults: alpha3 = 0.0004 m²/m, scale +2 %
  std::mt19937_64 rng(42);
  std::vector<double> x;
  for (int run = 0; run < 400; ++run) x.push_back(DriveStraight(options, 10.0, 0.05, rng).x_m);
  const Stats s = Summarize(x);
  EXPECT_NEAR(s.mean, 10.0 * (1.0 + options.scale_error), 0.02);
  EXPECT_NEAR(s.stddev, std::sqrt(options.alpha3_m2_per_m * 10.0), 0.01);
}

TEST(OdometrySimulator, ErrorDoesNotDependOnTheStepSize) {
  OdometryNoiseOptions options;
  std::mt19937_64 rng(3);
  std::vector<double> coarse, fine;
  for (int run = 0; run < 300; ++run) {
    coarse.push_back(DriveStraight(options, 10.0, 0.5, rng).theta_rad);
    fine.push_back(DriveStraight(options, 10.0, 0.01, rng).theta_rad);
  }
  const Stats c = Summarize(coarse), f = Summarize(fine);
  EXPECT_NEAR(c.stddev, f.stddev, 0.25 * c.stddev);
  // Heading drift is systematic: 0.002 rad/m over 10 m.
  EXPECT_NEAR(f.mean, options.heading_drift_rad_per_m * 10.0, 0.01);
}

TEST(OdometrySimulator, DrivingBackwardsIsANegativeTranslationNotAHalfTurn) {
  OdometryNoiseOptions options;
  options.alpha1_rad2_per_rad = options.alpha2_rad2_per_m = options.alpha3_m2_per_m = options.alpha4_m2_per_rad = 0;
  options.heading_drift_rad_per_m = 0;
  options.scale_error = 0.1;
  OdometrySimulator odom(options);
  std::mt19937_64 rng(1);
  const Pose2D end = odom.Update({0, 0, 0}, {-1.0, 0, 0}, rng);
  EXPECT_NEAR(end.x_m, -1.1, 1e-9);
  EXPECT_NEAR(end.theta_rad, 0.0, 1e-9);
  EXPECT_NEAR(odom.odometer_m(), 1.1, 1e-9);
}

}  // namespace
}  // namespace doorplate_localization

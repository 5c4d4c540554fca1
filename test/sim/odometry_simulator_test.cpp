#include "doorplate_localization/sim/odometry_simulator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
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

// Drives a circle arc of 0.05 m steps turning `turn_per_step_rad` each step; returns the simulator.
OdometrySimulator DriveArc(const OdometryNoiseOptions& options, int steps, double turn_per_step_rad,
                           std::mt19937_64& rng) {
  OdometrySimulator odom(options);
  Pose2D truth;
  for (int i = 0; i < steps; ++i) {
    const Pose2D next{truth.x_m + 0.05 * std::cos(truth.theta_rad), truth.y_m + 0.05 * std::sin(truth.theta_rad),
                      truth.theta_rad + turn_per_step_rad};
    odom.Update(truth, next, rng);
    truth = next;
  }
  return odom;
}

OdometryNoiseOptions NoiseFree() {
  OdometryNoiseOptions options;
  options.alpha1_rad2_per_rad = options.alpha2_rad2_per_m = options.alpha3_m2_per_m = options.alpha4_m2_per_rad = 0;
  options.scale_error = options.heading_drift_rad_per_m = 0;
  return options;
}

TEST(OdometrySimulator, WithoutSlipTheOdometryIsExactlyAsBeforeSlipExisted) {
  // Golden values of the model before OdometrySlipOptions (same seed, same arc), to the last bit, and the
  // random stream left in the same state: worlds that do not opt in replay exactly.
  OdometryNoiseOptions options;
  options.slip.scale_correlation_length_m = 3.0;  // a parameter alone does not switch slip on
  std::mt19937_64 rng(7);
  const OdometrySimulator odom = DriveArc(options, 200, 0.01, rng);
  EXPECT_EQ(odom.pose().x_m, 4.9876698079663075);
  EXPECT_EQ(odom.pose().y_m, 7.090031252279311);
  EXPECT_EQ(odom.pose().theta_rad, 1.9037192857615681);
  EXPECT_EQ(rng(), 12677557796074916861ULL);
}

TEST(OdometrySimulator, SlowScaleErrorHasItsSpreadAndCorrelationLength) {
  OdometryNoiseOptions options = NoiseFree();
  options.slip.scale_stddev = 0.02;
  options.slip.scale_correlation_length_m = 10.0;
  std::mt19937_64 rng(5);
  OdometrySimulator odom(options);
  std::vector<double> samples;  // every metre over 5 km
  Pose2D truth;
  for (int i = 0; i < 50000; ++i) {
    const Pose2D next{truth.x_m + 0.1, 0.0, 0.0};
    odom.Update(truth, next, rng);
    truth = next;
    if (i % 10 == 9) samples.push_back(odom.slip_scale_error());
  }
  const Stats s = Summarize(samples);
  EXPECT_NEAR(s.mean, 0.0, 0.005);
  EXPECT_NEAR(s.stddev, 0.02, 0.003);
  double c10 = 0.0;  // correlation at 10 m: e^-1
  for (size_t k = 0; k + 10 < samples.size(); ++k) c10 += samples[k] * samples[k + 10];
  c10 /= (samples.size() - 10) * s.stddev * s.stddev;
  EXPECT_NEAR(c10, std::exp(-1.0), 0.12);
  // The odometry reads the distance with that scale error: after the drive it is not exactly 5000 m.
  EXPECT_GT(std::fabs(odom.pose().x_m - 5000.0), 1e-6);
}

TEST(OdometrySimulator, SlowScaleErrorDoesNotDependOnTheStepSize) {
  OdometryNoiseOptions options = NoiseFree();
  options.slip.scale_stddev = 0.03;
  options.slip.scale_correlation_length_m = 5.0;
  std::mt19937_64 rng(9);
  std::vector<double> coarse, fine;
  for (int run = 0; run < 400; ++run) {
    coarse.push_back(DriveStraight(options, 10.0, 0.5, rng).x_m);
    fine.push_back(DriveStraight(options, 10.0, 0.02, rng).x_m);
  }
  const Stats c = Summarize(coarse), f = Summarize(fine);
  EXPECT_NEAR(c.stddev, f.stddev, 0.2 * f.stddev);
  EXPECT_GT(f.stddev, 0.1);  // 10 m at 3 % partly correlated: well above zero
}

TEST(OdometrySimulator, TurnsOverReadRotationAndStretchDistance) {
  OdometryNoiseOptions options = NoiseFree();
  options.slip.turn_rotation_error_rad_per_rad = 0.05;
  options.slip.turn_scale_error_m_per_rad = 0.1;
  std::mt19937_64 rng(1);
  // A quarter circle of radius 1 m: 31.4 steps of 0.05 m turning 0.05 rad each; then a straight.
  const OdometrySimulator turn = DriveArc(options, 31, 0.05, rng);
  EXPECT_NEAR(turn.pose().theta_rad, 31 * 0.05 * 1.05, 1e-9);
  EXPECT_NEAR(turn.odometer_m(), 31 * 0.05 + 0.1 * 31 * 0.05, 1e-9);
  const OdometrySimulator straight = DriveArc(options, 31, 0.0, rng);
  EXPECT_NEAR(straight.odometer_m(), 31 * 0.05, 1e-9);  // no turn, no slip
  EXPECT_NEAR(straight.pose().theta_rad, 0.0, 1e-12);
}

TEST(OdometrySimulator, InvalidSlipOptionsAreNamed) {
  auto message = [](OdometryNoiseOptions options) -> std::string {
    try {
      OdometrySimulator odom(options);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no error)";
  };
  OdometryNoiseOptions a;
  a.slip.scale_stddev = -0.01;
  EXPECT_NE(message(a).find("scale_stddev"), std::string::npos);
  OdometryNoiseOptions b;
  b.slip.scale_correlation_length_m = 0.0;
  EXPECT_NE(message(b).find("scale_correlation_length_m"), std::string::npos);
  OdometryNoiseOptions c;
  c.slip.turn_rotation_error_rad_per_rad = -0.6;
  EXPECT_NE(message(c).find("turn_rotation_error_rad_per_rad"), std::string::npos);
}

}  // namespace
}  // namespace doorplate_localization

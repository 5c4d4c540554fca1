#include "doorplate_localization/odometry_fit/odometry_slip_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace doorplate_localization {
namespace {

// Contiguous 1 m segments along a path; scale error = a + b·turn + slow[k] + white noise, rotation error
// = c·Δθ + h·d.
struct Truth {
  double a = 0.0, b = 0.0, c = 0.0, h = 0.0;
  double white_stddev = 0.0;
};

std::vector<OdometrySegment> Segments(const Truth& t, const std::vector<double>& slow, std::mt19937_64& rng) {
  std::normal_distribution<double> white(0.0, t.white_stddev > 0 ? t.white_stddev : 1e-12);
  std::uniform_real_distribution<double> turn(-1.0, 1.0);
  std::vector<OdometrySegment> segments;
  for (size_t k = 0; k < slow.size(); ++k) {
    OdometrySegment g;
    g.first_step = static_cast<int>(k) * 5;
    g.num_steps = 5;
    g.start_arc_m = static_cast<double>(k);
    g.reference_distance_m = 1.0;
    g.reference_rotation_rad = turn(rng);
    g.odometry_distance_m = 1.0 + t.a + t.b * std::fabs(g.reference_rotation_rad) + slow[k] + white(rng);
    g.odometry_rotation_rad = g.reference_rotation_rad * (1.0 + t.c) + t.h;
    segments.push_back(g);
  }
  return segments;
}

TEST(OdometrySlipFit, RecoversScaleTurnSlipAndHeadingDrift) {
  std::mt19937_64 rng(3);
  Truth t{0.015, 0.02, -0.03, 0.004, 0.005};
  const auto segments = Segments(t, std::vector<double>(200, 0.0), rng);
  OdometrySlipFitOptions options;
  options.bootstrap_samples = 200;
  const OdometrySlipFit fit = FitOdometrySlip(segments, options, rng);
  EXPECT_EQ(fit.segments_used, 200);
  EXPECT_NEAR(fit.scale_error.value, 0.015, 0.002);
  EXPECT_NEAR(fit.turn_scale_error_m_per_rad.value, 0.02, 0.004);
  EXPECT_NEAR(fit.turn_rotation_error.value, -0.03, 1e-9);
  EXPECT_NEAR(fit.heading_drift_rad_per_m.value, 0.004, 1e-9);
  EXPECT_LT(fit.scale_error.low, 0.015);
  EXPECT_GT(fit.scale_error.high, 0.015);
  EXPECT_LT(fit.scale_error.high - fit.scale_error.low, 0.01);
}

TEST(OdometrySlipFit, FindsTheCorrelationLengthOfASlowlyVaryingScale) {
  std::mt19937_64 rng(7);
  const double sigma = 0.03, length_m = 8.0, rho = std::exp(-1.0 / length_m);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::vector<double> slow(4000);
  slow[0] = sigma * unit(rng);
  for (size_t k = 1; k < slow.size(); ++k) slow[k] = rho * slow[k - 1] + sigma * std::sqrt(1 - rho * rho) * unit(rng);
  const auto segments = Segments({0.0, 0.0, 0.0, 0.0, 0.01}, slow, rng);
  OdometrySlipFitOptions options;
  options.bootstrap_samples = 20;
  const OdometrySlipFit fit = FitOdometrySlip(segments, options, rng);
  EXPECT_NEAR(fit.ou_stddev, sigma, 0.006);
  EXPECT_NEAR(fit.ou_correlation_length_m, length_m, 3.0);
  EXPECT_GT(fit.lag1_correlation, 0.7);
  EXPECT_EQ(fit.lag1_pairs, 3999);
}

TEST(OdometrySlipFit, SeesNoSlowVariationInWhiteNoise) {
  std::mt19937_64 rng(11);
  const auto segments = Segments({0.0, 0.0, 0.0, 0.0, 0.02}, std::vector<double>(2000, 0.0), rng);
  OdometrySlipFitOptions options;
  options.bootstrap_samples = 20;
  const OdometrySlipFit fit = FitOdometrySlip(segments, options, rng);
  EXPECT_LT(std::fabs(fit.lag1_correlation), 0.1);
  EXPECT_NEAR(fit.residual_stddev, 0.02, 0.002);
  EXPECT_LT(fit.zone_chi2, 16.3);  // chi2(3) 99.9 % quantile
}

TEST(OdometrySlipFit, TellsFloorZonesWithDifferentScaleApart) {
  std::mt19937_64 rng(5);
  std::vector<double> slow(200, 0.0);
  for (size_t k = 100; k < 200; ++k) slow[k] = 0.04;  // the second half of the floor reads 4 % longer
  const auto segments = Segments({0.0, 0.0, 0.0, 0.0, 0.01}, slow, rng);
  OdometrySlipFitOptions options;
  options.bootstrap_samples = 20;
  options.num_zones = 2;
  const OdometrySlipFit fit = FitOdometrySlip(segments, options, rng);
  ASSERT_EQ(fit.zones.size(), 2u);
  EXPECT_NEAR(fit.zones[0].mean, 0.0, 0.005);
  EXPECT_NEAR(fit.zones[1].mean, 0.04, 0.005);
  EXPECT_EQ(fit.zone_dof, 1);
  EXPECT_GT(fit.zone_chi2, 100.0);
}

TEST(OdometrySlipFit, LeavesOutFailedReferencesAndNeedsThreeSegments) {
  std::mt19937_64 rng(1);
  auto segments = Segments({}, std::vector<double>(4, 0.0), rng);
  segments[1].odometry_distance_m = 2.0;  // 100 % scale error: a failed reference
  segments[2].odometry_distance_m = 0.5;
  OdometrySlipFitOptions options;
  options.bootstrap_samples = 5;
  EXPECT_THROW(FitOdometrySlip(segments, options, rng), std::invalid_argument);
  segments[2].odometry_distance_m = 1.0;
  const OdometrySlipFit fit = FitOdometrySlip(segments, options, rng);
  EXPECT_EQ(fit.segments_used, 3);
  EXPECT_EQ(fit.segments_rejected, 1);
}

}  // namespace
}  // namespace doorplate_localization

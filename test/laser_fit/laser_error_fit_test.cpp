#include "doorplate_localization/laser_fit/laser_error_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "doorplate_localization/sim/laser_error_model.h"
#include "../sim/quiet_laser_errors.h"

namespace doorplate_localization {
namespace {

TEST(RobustSpreadOf, IsTheGaussianSigmaBlindToOutliers) {
  std::mt19937_64 rng(1);
  std::normal_distribution<float> noise(0.5f, 0.02f);
  std::vector<float> v;
  for (int i = 0; i < 20000; ++i) v.push_back(i % 10 == 0 ? 100.0f : noise(rng));  // 10 % wild
  const RobustSpread s = RobustSpreadOf(v);
  EXPECT_EQ(s.count, 20000);
  // The outliers (all above) move the median to the normal's 0.5 / 0.9 quantile (0.14 sigma) and widen the
  // MAD by about a sixth: a thousandth of what they do to the standard deviation.
  EXPECT_NEAR(s.median, 0.5 + 0.14 * 0.02, 0.001);
  EXPECT_NEAR(s.sigma, 0.02 * 1.16, 0.002);
  EXPECT_DOUBLE_EQ(RobustSpreadOf({1.0f, 2.0f, 4.0f}).median, 2.0);
  EXPECT_DOUBLE_EQ(RobustSpreadOf({}).sigma, 0.0);
}

// Scans the model makes of known geometry: plain walls at ranges 0.5-15 m seen at 0-85° (one range per
// scan, so no depth edges), and scans across a 2 m / 6 m depth edge.
BeamTally TallyOf(const FittedLaserErrorOptions& truth, const BeamTallyOptions& bins) {
  const FittedLaserErrorModel model(truth);
  BeamTallier tallier(bins);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> range(0.5, 15.0), incidence_deg(0.0, 85.0);
  for (int scan = 0; scan < 3000; ++scan) {
    const double r = range(rng);
    std::vector<ExpectedBeam> expected;
    std::vector<float> ranges, incidence;
    for (int i = 0; i < 180; ++i) {
      const double a = incidence_deg(rng) * M_PI / 180;
      expected.push_back({ExpectedKind::kHit, r, a, true});
      ranges.push_back(static_cast<float>(r)), incidence.push_back(static_cast<float>(a));
    }
    model.Apply(&ranges, incidence, 0.01, 40.0, false, rng);
    tallier.AddScan(expected, ranges, 40.0);
  }
  for (int scan = 0; scan < 2000; ++scan) {
    std::vector<ExpectedBeam> expected;
    std::vector<float> ranges;
    for (int i = 0; i < 4; ++i) {
      expected.push_back({ExpectedKind::kHit, i < 2 ? 2.0 : 6.0, 0.0, true});
      ranges.push_back(i < 2 ? 2.0f : 6.0f);
    }
    model.Apply(&ranges, {}, 0.01, 40.0, false, rng);
    tallier.AddScan(expected, ranges, 40.0);
  }
  return tallier.tally();
}

FittedLaserErrorOptions Quiet() { return test::QuietLaserErrors(); }

TEST(FitLaserErrors, RecoversTheParametersOfSimulatedScans) {
  FittedLaserErrorOptions truth = Quiet();
  truth.noise_base_m = 0.01, truth.noise_fraction = 0.004, truth.noise_grazing_gain = 0.2;
  truth.dropout_probability = 0.02, truth.dropout_per_m = 0.002;
  truth.dropout_near_probability = 0.05, truth.dropout_near_range_m = 1.5;
  truth.dropout_grazing_probability = 0.3, truth.dropout_grazing_from_deg = 70;
  truth.mixed_pixel_probability = 0.3, truth.short_probability = 0.01, truth.short_mean_m = 1.5;
  const BeamTallyOptions bins;
  const FittedLaserErrorOptions fit = FitLaserErrors(TallyOf(truth, bins), bins, LaserErrorFitOptions{});
  EXPECT_NEAR(fit.noise_base_m, 0.01, 0.0015);
  EXPECT_NEAR(fit.noise_fraction, 0.004, 0.0005);
  EXPECT_NEAR(fit.noise_grazing_gain, 0.2, 0.05);
  EXPECT_NEAR(fit.dropout_probability, 0.02, 0.004);
  EXPECT_NEAR(fit.dropout_per_m, 0.002, 0.0005);
  EXPECT_NEAR(fit.dropout_near_probability, 0.05, 0.01);
  EXPECT_DOUBLE_EQ(fit.dropout_near_range_m, 1.5);
  EXPECT_NEAR(fit.dropout_grazing_probability, 0.3, 0.04);
  EXPECT_NEAR(fit.dropout_grazing_from_deg, 70, 5.1);
  EXPECT_NEAR(fit.mixed_pixel_probability, 0.3, 0.03);
  EXPECT_NEAR(fit.short_probability, 0.01, 0.0015);
  EXPECT_NEAR(fit.short_mean_m, 1.5, 0.15);
}

TEST(FitLaserErrors, NoEffectGivesNoParameter) {
  const FittedLaserErrorOptions truth = Quiet();
  const BeamTallyOptions bins;
  const FittedLaserErrorOptions fit = FitLaserErrors(TallyOf(truth, bins), bins, LaserErrorFitOptions{});
  EXPECT_NEAR(fit.noise_base_m, 0.01, 0.001);
  EXPECT_LT(fit.noise_fraction, 0.0005);
  EXPECT_LT(fit.noise_grazing_gain, 0.03);
  EXPECT_LT(fit.dropout_probability + fit.dropout_grazing_probability + fit.dropout_near_probability, 0.002);
  EXPECT_LT(fit.dropout_per_m, 0.0002);
  EXPECT_DOUBLE_EQ(fit.mixed_pixel_probability, 0.0);
  EXPECT_DOUBLE_EQ(fit.short_probability, 0.0);
}

TEST(FitLaserErrors, AnEmptyTallyIsAnError) {
  EXPECT_THROW(FitLaserErrors(BeamTally{}, BeamTallyOptions{}, LaserErrorFitOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

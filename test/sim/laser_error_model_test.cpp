#include "doorplate_localization/sim/laser_error_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>
#include "quiet_laser_errors.h"

namespace doorplate_localization {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

FittedLaserErrorOptions Quiet() { return test::QuietLaserErrors(); }

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

// Fraction of beams at `range_m` and `incidence_rad` the model drops (n beams, no depth edge).
double DropRate(const FittedLaserErrorModel& model, double range_m, double incidence_rad, int n, std::uint64_t seed) {
  std::vector<float> ranges(n, static_cast<float>(range_m)), incidence(n, static_cast<float>(incidence_rad));
  std::mt19937_64 rng(seed);
  model.Apply(&ranges, incidence, 0.1, 30.0, false, rng);
  int dropped = 0;
  for (const float r : ranges) dropped += std::isinf(r);
  return static_cast<double>(dropped) / n;
}

// Sample standard deviation of the readings of n beams at `range_m`, head-on.
double NoiseStddev(const FittedLaserErrorModel& model, double range_m, int n) {
  std::vector<float> ranges(n, static_cast<float>(range_m));
  std::mt19937_64 rng(3);
  model.Apply(&ranges, {}, 0.1, 30.0, false, rng);
  double sum = 0, sum2 = 0;
  for (const float r : ranges) sum += r - range_m, sum2 += (r - range_m) * (r - range_m);
  return std::sqrt(sum2 / n - (sum / n) * (sum / n));
}

TEST(GaussianLaserErrorModel, DrawsLikeTheSimulatorBeforeIssue20) {
  // The loop LaserSimulator::Simulate ran before the error models: the same numbers must come out.
  std::vector<float> exact = {1.0f, kInf, 2.5f, 15.99f, -kInf, 0.16f, 7.0f};
  std::vector<float> old = exact;
  std::mt19937_64 old_rng(11);
  {
    std::normal_distribution<double> noise(0.0, 0.05);
    std::bernoulli_distribution dropout(0.2);
    for (float& r : old) {
      const double n = noise(old_rng);
      const bool lost = dropout(old_rng);
      if (!std::isfinite(r)) continue;
      if (lost) {
        r = kInf;
        continue;
      }
      const double noisy = r + n;
      r = noisy > 16.0 ? kInf : static_cast<float>(std::max(noisy, 0.15));
    }
  }
  std::mt19937_64 rng(11);
  GaussianLaserErrorModel(0.05, 0.2).Apply(&exact, {}, 0.15, 16.0, true, rng);
  for (size_t i = 0; i < exact.size(); ++i) EXPECT_EQ(exact[i], old[i]) << i;
  EXPECT_EQ(rng(), old_rng());
}

TEST(FittedLaserErrorModel, NoiseGrowsWithRange) {
  FittedLaserErrorOptions o = Quiet();
  o.noise_base_m = 0.01, o.noise_fraction = 0.01;
  const FittedLaserErrorModel model(o);
  EXPECT_NEAR(NoiseStddev(model, 1.0, 20000), std::hypot(0.01, 0.01), 0.001);
  EXPECT_NEAR(NoiseStddev(model, 10.0, 20000), std::hypot(0.01, 0.1), 0.005);
  EXPECT_NEAR(model.NoiseStddev(10.0, 0.0), std::hypot(0.01, 0.1), 1e-12);
}

TEST(FittedLaserErrorModel, NoiseGrowsAtGrazingIncidence) {
  FittedLaserErrorOptions o = Quiet();
  o.noise_grazing_gain = 0.5;
  const FittedLaserErrorModel model(o);
  EXPECT_DOUBLE_EQ(model.NoiseStddev(3.0, 0.0), 0.01);
  EXPECT_NEAR(model.NoiseStddev(3.0, M_PI / 3), 0.01 * 1.5, 1e-12);  // 1/cos 60° = 2
  EXPECT_DOUBLE_EQ(model.NoiseStddev(3.0, 1.5), model.NoiseStddev(3.0, 80 * M_PI / 180));  // capped at 80°
}

TEST(FittedLaserErrorModel, DropsMoreBeamsAtGrazingIncidence) {
  FittedLaserErrorOptions o = Quiet();
  o.dropout_probability = 0.01, o.dropout_grazing_probability = 0.4, o.dropout_grazing_from_deg = 60;
  const FittedLaserErrorModel model(o);
  EXPECT_NEAR(DropRate(model, 3.0, 0.0, 20000, 1), 0.01, 0.003);
  EXPECT_NEAR(DropRate(model, 3.0, 50 * M_PI / 180, 20000, 2), 0.01, 0.003);
  EXPECT_NEAR(DropRate(model, 3.0, 75 * M_PI / 180, 20000, 3), 0.01 + 0.2, 0.015);
  EXPECT_NEAR(model.DropoutProbability(3.0, M_PI / 2), 0.41, 1e-12);
}

TEST(FittedLaserErrorModel, LosesWeakEchoesBeyondTheDetectionRangeSoonerAtGrazingIncidence) {
  FittedLaserErrorOptions o = Quiet();
  o.dropout_probability = 0.0, o.detection_range_m = 10.0, o.detection_edge_fraction = 0.2;
  const FittedLaserErrorModel model(o);
  EXPECT_DOUBLE_EQ(model.DropoutProbability(8.0, 0.0), 0.0);    // within r_max = 10 m head-on
  EXPECT_DOUBLE_EQ(model.DropoutProbability(10.0, 0.0), 0.5);   // at r_max: the middle of the edge
  EXPECT_DOUBLE_EQ(model.DropoutProbability(12.0, 0.0), 1.0);   // beyond the edge
  // At 80° the echo is cos 80° = 0.17 as strong: r_max = 10 m × sqrt(0.17) = 4.2 m.
  EXPECT_DOUBLE_EQ(model.DropoutProbability(3.5, 80 * M_PI / 180), 0.0);
  EXPECT_DOUBLE_EQ(model.DropoutProbability(5.2, 80 * M_PI / 180), 1.0);
  EXPECT_NEAR(DropRate(model, 10.0, 0.0, 20000, 6), 0.5, 0.02);
  o.detection_range_m = 0.0;  // off
  EXPECT_DOUBLE_EQ(FittedLaserErrorModel(o).DropoutProbability(50.0, 1.5), 0.0);
}

TEST(FittedLaserErrorModel, DropsMoreBeamsFarAway) {
  FittedLaserErrorOptions o = Quiet();
  o.dropout_probability = 0.0, o.dropout_per_m = 0.01;
  const FittedLaserErrorModel model(o);
  EXPECT_NEAR(DropRate(model, 2.0, 0.0, 20000, 4), 0.02, 0.005);
  EXPECT_NEAR(DropRate(model, 20.0, 0.0, 20000, 5), 0.2, 0.015);
}

TEST(FittedLaserErrorModel, DropsMoreBeamsNearTheLaser) {
  FittedLaserErrorOptions o = Quiet();
  o.dropout_near_probability = 0.1, o.dropout_near_range_m = 1.0;
  const FittedLaserErrorModel model(o);
  EXPECT_NEAR(DropRate(model, 0.5, 0.0, 20000, 6), 0.1, 0.01);
  EXPECT_EQ(DropRate(model, 1.5, 0.0, 20000, 7), 0.0);
}

TEST(FittedLaserErrorModel, MixedPixelsLieBetweenTheSurfacesOfADepthEdge) {
  FittedLaserErrorOptions o = Quiet();
  o.mixed_pixel_probability = 1.0, o.depth_edge_m = 0.5;
  const FittedLaserErrorModel model(o);
  // Beams 0-2 on a near wall at 2 m, beams 3-5 on a far one at 6 m: beams 2 and 3 straddle the edge.
  std::vector<float> ranges = {2, 2, 2, 6, 6, 6};
  std::mt19937_64 rng(5);
  model.Apply(&ranges, {}, 0.1, 30.0, false, rng);
  for (const int edge : {2, 3}) {
    EXPECT_GT(ranges[edge], 2.0f + 0.05f) << edge;
    EXPECT_LT(ranges[edge], 6.0f - 0.05f) << edge;
  }
  for (const int inside : {0, 1, 4, 5}) EXPECT_NEAR(ranges[inside], inside < 3 ? 2.0 : 6.0, 0.1) << inside;
}

TEST(FittedLaserErrorModel, WrapAroundMakesTheFirstAndLastBeamsNeighbours) {
  FittedLaserErrorOptions o = Quiet();
  o.mixed_pixel_probability = 1.0, o.noise_base_m = 0.0;
  const FittedLaserErrorModel model(o);
  std::vector<float> open = {2, 2, 2, 6}, wrapped = open;
  std::mt19937_64 a(1), b(1);
  model.Apply(&open, {}, 0.1, 30.0, false, a);
  model.Apply(&wrapped, {}, 0.1, 30.0, true, b);
  EXPECT_EQ(open[0], 2.0f);
  EXPECT_GT(wrapped[0], 2.0f);
}

TEST(FittedLaserErrorModel, ShortReturnsComeBeforeTheSurfaceAndInFreeSpace) {
  FittedLaserErrorOptions o = Quiet();
  o.short_probability = 1.0, o.short_mean_m = 1.0, o.noise_base_m = 0.0;
  const FittedLaserErrorModel model(o);
  std::vector<float> far(20000, 12.0f), free_space(20000, kInf), near(20000, 1.2f);
  std::mt19937_64 rng(9);
  model.Apply(&far, {}, 0.2, 30.0, false, rng);
  model.Apply(&free_space, {}, 0.2, 30.0, false, rng);
  model.Apply(&near, {}, 0.2, 30.0, false, rng);
  double sum = 0;
  int near_short = 0;
  for (size_t i = 0; i < far.size(); ++i) {
    ASSERT_GE(far[i], 0.2f);
    ASSERT_LT(far[i], 12.0f);
    ASSERT_TRUE(std::isfinite(free_space[i]));
    sum += far[i];
    near_short += near[i] < 1.2f;
  }
  EXPECT_NEAR(sum / far.size(), 0.2 + 1.0, 0.03);  // the wall at 12 m hides almost nothing
  // With the wall 1 m beyond the minimum range, only objects nearer than it are seen: 1 - e^-1.
  EXPECT_NEAR(near_short / 20000.0, 1.0 - std::exp(-1.0), 0.01);
}

TEST(FittedLaserErrorModel, TheRandomStreamDoesNotDependOnTheGeometry) {
  FittedLaserErrorOptions o = Quiet();
  o.mixed_pixel_probability = 0.5, o.short_probability = 0.1, o.dropout_probability = 0.1;
  const FittedLaserErrorModel model(o);
  std::vector<float> walls = {2, 2, 6, 6, 1}, nothing(5, kInf);
  std::mt19937_64 a(21), b(21);
  model.Apply(&walls, {}, 0.1, 30.0, true, a);
  model.Apply(&nothing, {}, 0.1, 30.0, true, b);
  EXPECT_EQ(a(), b());
}

TEST(FittedLaserErrorModel, UnknownAndTooCloseBeamsAreLeftAlone) {
  FittedLaserErrorOptions o = Quiet();
  o.short_probability = 1.0;
  const FittedLaserErrorModel model(o);
  std::vector<float> ranges = {NAN, -kInf};
  std::mt19937_64 rng(1);
  model.Apply(&ranges, {}, 0.1, 30.0, false, rng);
  EXPECT_TRUE(std::isnan(ranges[0]));
  EXPECT_EQ(ranges[1], -kInf);
}

TEST(FittedLaserErrorModel, BadOptionsAreNamed) {
  FittedLaserErrorOptions o = Quiet();
  o.short_mean_m = 0.0;
  EXPECT_EQ(ErrorOf([&] { FittedLaserErrorModel m(o); }),
            "FittedLaserErrorOptions.short_mean_m: must be > 0, got 0.000000");
  o = Quiet();
  o.mixed_pixel_probability = 1.5;
  EXPECT_EQ(ErrorOf([&] { FittedLaserErrorModel m(o); }),
            "FittedLaserErrorOptions.mixed_pixel_probability: must be in [0, 1], got 1.500000");
}

TEST(MakeLaserErrorModel, PicksTheNamedModelAndNamesAnUnknownOne) {
  LaserOptions options;
  EXPECT_FALSE(MakeLaserErrorModel(options)->NeedsIncidence());
  options.error_model = "fitted";
  EXPECT_TRUE(MakeLaserErrorModel(options)->NeedsIncidence());
  options.error_model = "sick";
  EXPECT_EQ(ErrorOf([&] { MakeLaserErrorModel(options); }),
            "LaserOptions.error_model: must be 'gaussian' or 'fitted', got 'sick'");
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/mcl/resampler.h"

#include <gtest/gtest.h>

#include <cmath>

namespace doorplate_localization {
namespace {

std::vector<Particle> Weighted(std::vector<double> weights) {
  std::vector<Particle> ps;
  for (size_t i = 0; i < weights.size(); ++i) ps.push_back({{static_cast<double>(i), 0.0, 0.0}, weights[i]});
  return ps;
}

std::vector<int> Counts(const std::vector<int>& selected, size_t n) {
  std::vector<int> counts(n, 0);
  for (int i : selected) ++counts.at(i);
  return counts;
}

TEST(LowVarianceResampler, SelectsEachParticleFloorOrCeilOfItsExpectedCount) {
  const LowVarianceResampler resampler;
  const auto ps = Weighted({0.1, 0.2, 0.3, 0.4});
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    std::mt19937_64 rng(seed);
    const auto counts = Counts(resampler.Select(ps, 1000, rng), ps.size());
    for (size_t i = 0; i < ps.size(); ++i) EXPECT_NEAR(counts[i], 1000 * ps[i].weight, 1.0) << "seed " << seed;
  }
  // Thirds into 10: every particle 3 or 4 times.
  std::mt19937_64 rng(4);
  for (int c : Counts(resampler.Select(Weighted({1, 1, 1}), 10, rng), 3)) {
    EXPECT_GE(c, 3);
    EXPECT_LE(c, 4);
  }
}

TEST(LowVarianceResampler, UnnormalizedAndAllZeroWeightsWork) {
  const LowVarianceResampler resampler;
  std::mt19937_64 rng(1);
  const auto scaled = Counts(resampler.Select(Weighted({10.0, 30.0}), 100, rng), 2);
  EXPECT_NEAR(scaled[0], 25, 1);
  const auto zero = Counts(resampler.Select(Weighted({0.0, 0.0}), 100, rng), 2);
  EXPECT_NEAR(zero[0], 50, 1);  // uniform
  EXPECT_TRUE(resampler.Select({}, 10, rng).empty());
  EXPECT_TRUE(resampler.Select(Weighted({1.0}), 0, rng).empty());
}

TEST(LowVarianceResampler, NeverSelectsAZeroWeightParticle) {
  const LowVarianceResampler resampler;
  std::mt19937_64 rng(9);
  const auto counts = Counts(resampler.Select(Weighted({0.0, 0.5, 0.0, 0.5, 0.0}), 777, rng), 5);
  EXPECT_EQ(counts[0] + counts[2] + counts[4], 0);
}

TEST(MultinomialResampler, KeepsTheExpectedCountsOnAverage) {
  const MultinomialResampler resampler;
  std::mt19937_64 rng(3);
  const auto counts = Counts(resampler.Select(Weighted({0.1, 0.2, 0.3, 0.4}), 20000, rng), 4);
  for (int i = 0; i < 4; ++i) {
    const double p = 0.1 * (i + 1), sd = std::sqrt(20000 * p * (1 - p));
    EXPECT_NEAR(counts[i], 20000 * p, 5 * sd);
  }
}

}  // namespace
}  // namespace doorplate_localization

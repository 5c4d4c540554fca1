#include "doorplate_localization/mcl/particle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace doorplate_localization {
namespace {

std::vector<Particle> Weighted(std::vector<double> weights) {
  std::vector<Particle> particles;
  for (double w : weights) particles.push_back({{}, w});
  return particles;
}

TEST(NormalizeWeights, ScalesToOneAndReturnsThePreviousSum) {
  auto p = Weighted({1.0, 3.0});
  EXPECT_DOUBLE_EQ(NormalizeWeights(&p), 4.0);
  EXPECT_DOUBLE_EQ(p[0].weight, 0.25);
  EXPECT_DOUBLE_EQ(p[1].weight, 0.75);
}

TEST(NormalizeWeights, ZeroOrNonFiniteTotalBecomesUniform) {
  auto zero = Weighted({0.0, 0.0, 0.0, 0.0});
  EXPECT_EQ(NormalizeWeights(&zero), 0.0);
  for (const Particle& q : zero) EXPECT_DOUBLE_EQ(q.weight, 0.25);
  auto nan = Weighted({std::nan(""), 1.0});
  EXPECT_EQ(NormalizeWeights(&nan), 0.0);
  EXPECT_DOUBLE_EQ(nan[0].weight, 0.5);
}

TEST(EffectiveSampleSize, IsNForUniformAndOneForADegenerateSet) {
  EXPECT_NEAR(EffectiveSampleSize(Weighted({0.25, 0.25, 0.25, 0.25})), 4.0, 1e-12);
  EXPECT_NEAR(EffectiveSampleSize(Weighted({0.0, 1.0, 0.0})), 1.0, 1e-12);
  EXPECT_EQ(EffectiveSampleSize({}), 0.0);
}

TEST(ApplyLogLikelihoods, MultipliesWeightsAndReturnsTheLogMeanLikelihood) {
  auto p = Weighted({0.5, 0.5});
  const double log_mean = ApplyLogLikelihoods({std::log(0.2), std::log(0.6)}, &p);
  EXPECT_NEAR(p[0].weight, 0.25, 1e-12);
  EXPECT_NEAR(p[1].weight, 0.75, 1e-12);
  EXPECT_NEAR(log_mean, std::log(0.5 * 0.2 + 0.5 * 0.6), 1e-12);
}

TEST(ApplyLogLikelihoods, SurvivesLikelihoodsFarBelowTheSmallestDouble) {
  // Products of hundreds of beam probabilities: exp(-3000) underflows, the log domain does not.
  auto p = Weighted({0.5, 0.5});
  const double log_mean = ApplyLogLikelihoods({-3000.0, -3000.0 + std::log(3.0)}, &p);
  EXPECT_NEAR(p[0].weight, 0.25, 1e-12);
  EXPECT_NEAR(p[1].weight, 0.75, 1e-12);
  EXPECT_NEAR(log_mean, -3000.0 + std::log(2.0), 1e-9);
}

TEST(ApplyLogLikelihoods, NanLikelihoodZeroesThatParticleOnly) {
  auto p = Weighted({0.5, 0.5});
  ApplyLogLikelihoods({std::nan(""), 0.0}, &p);
  EXPECT_EQ(p[0].weight, 0.0);
  EXPECT_DOUBLE_EQ(p[1].weight, 1.0);
}

TEST(ApplyLogLikelihoods, NoParticleExplainingTheMeasurementKeepsTheWeights) {
  auto p = Weighted({0.2, 0.8});
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(ApplyLogLikelihoods({-inf, -inf}, &p), -inf);
  EXPECT_DOUBLE_EQ(p[0].weight, 0.2);
  EXPECT_DOUBLE_EQ(p[1].weight, 0.8);
}

TEST(ApplyLogLikelihoods, RejectsASizeMismatch) {
  auto p = Weighted({1.0});
  EXPECT_THROW(ApplyLogLikelihoods({0.0, 0.0}, &p), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

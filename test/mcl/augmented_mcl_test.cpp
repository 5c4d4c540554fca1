#include "doorplate_localization/mcl/augmented_mcl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace doorplate_localization {
namespace {

TEST(AugmentedMclAverages, FirstMeasurementInitializesBothAverages) {
  AugmentedMclAverages a(0.1, 0.5);
  EXPECT_FALSE(a.initialized());
  EXPECT_EQ(a.FastToSlowRatio(), 1.0);
  a.Update(std::log(0.8));
  EXPECT_TRUE(a.initialized());
  EXPECT_NEAR(a.log_w_slow(), std::log(0.8), 1e-12);
  EXPECT_EQ(a.RandomParticleProbability(), 0.0);
}

TEST(AugmentedMclAverages, FollowsThrunsTable83Recurrences) {
  // w_avg = 1.0 then 0.2: w_slow = 1 + 0.1 (0.2 - 1) = 0.92, w_fast = 1 + 0.5 (0.2 - 1) = 0.6,
  // inject with probability 1 - 0.6 / 0.92 = 0.347826.
  AugmentedMclAverages a(0.1, 0.5);
  a.Update(0.0);
  a.Update(std::log(0.2));
  EXPECT_NEAR(std::exp(a.log_w_slow()), 0.92, 1e-12);
  EXPECT_NEAR(std::exp(a.log_w_fast()), 0.6, 1e-12);
  EXPECT_NEAR(a.RandomParticleProbability(), 1.0 - 0.6 / 0.92, 1e-12);
  // Better-than-usual measurements never inject.
  a.Update(std::log(5.0));
  EXPECT_GT(a.FastToSlowRatio(), 1.0);
  EXPECT_EQ(a.RandomParticleProbability(), 0.0);
}

TEST(AugmentedMclAverages, WorksWithLikelihoodsThatUnderflowDoubles) {
  // The same recurrence at a scale of e^-5000 (a product of hundreds of beam probabilities).
  AugmentedMclAverages a(0.1, 0.5);
  a.Update(-5000.0);
  a.Update(-5000.0 + std::log(0.2));
  EXPECT_NEAR(a.RandomParticleProbability(), 1.0 - 0.6 / 0.92, 1e-9);
}

TEST(AugmentedMclAverages, ZeroAlphasNeverInjectAndResetForgets) {
  AugmentedMclAverages off(0.0, 0.0);
  off.Update(0.0);
  off.Update(-50.0);
  EXPECT_EQ(off.RandomParticleProbability(), 0.0);
  AugmentedMclAverages a(0.1, 0.5);
  a.Update(0.0);
  a.Update(-3.0);
  EXPECT_GT(a.RandomParticleProbability(), 0.0);
  a.Reset();
  EXPECT_FALSE(a.initialized());
  EXPECT_EQ(a.RandomParticleProbability(), 0.0);
  a.Update(std::nan(""));  // ignored
  EXPECT_FALSE(a.initialized());
}

TEST(AugmentedMclAverages, RejectsASlowAlphaAboveTheFastOne) {
  EXPECT_THROW(AugmentedMclAverages(0.5, 0.1), std::invalid_argument);
  EXPECT_THROW(AugmentedMclAverages(-0.1, 0.1), std::invalid_argument);
  EXPECT_THROW(AugmentedMclAverages(0.1, 1.5), std::invalid_argument);
}

// dynamic_reconfigure (issue 19): a filter with new alphas goes on from the old averages.
TEST(AugmentedMclAverages, TakesAnothersAveragesAndKeepsItsOwnAlphas) {
  AugmentedMclAverages old_alphas(0.1, 0.5);
  old_alphas.Update(0.0);
  old_alphas.Update(std::log(0.2));
  AugmentedMclAverages new_alphas(0.0, 1.0);
  new_alphas.TakeAveragesFrom(old_alphas);
  EXPECT_TRUE(new_alphas.initialized());
  EXPECT_EQ(new_alphas.log_w_slow(), old_alphas.log_w_slow());
  EXPECT_EQ(new_alphas.log_w_fast(), old_alphas.log_w_fast());
  new_alphas.Update(std::log(0.5));  // alpha_slow 0: w_slow stays; alpha_fast 1: w_fast is the measurement
  EXPECT_NEAR(new_alphas.log_w_slow(), old_alphas.log_w_slow(), 1e-12);
  EXPECT_NEAR(new_alphas.log_w_fast(), std::log(0.5), 1e-12);
}

}  // namespace
}  // namespace doorplate_localization

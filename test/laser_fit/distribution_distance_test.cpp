#include "doorplate_localization/laser_fit/distribution_distance.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace doorplate_localization {
namespace {

TEST(Histogram, CountsValuesInEqualBinsAndDropsTheRest) {
  const std::vector<double> h = Histogram({-1.0f, 0.0f, 0.24f, 0.26f, 0.99f, 1.0f}, 0.0, 1.0, 4);
  EXPECT_EQ(h, (std::vector<double>{2, 1, 0, 1}));
}

TEST(JensenShannonDivergence, IsZeroForTheSameShapeAndOneForDisjointOnes) {
  EXPECT_DOUBLE_EQ(JensenShannonDivergence({1, 2, 3}, {10, 20, 30}), 0.0);
  EXPECT_DOUBLE_EQ(JensenShannonDivergence({1, 0}, {0, 5}), 1.0);
  const double half = JensenShannonDivergence({1, 1}, {1, 0});  // 0.311 bits
  EXPECT_NEAR(half, 0.3113, 1e-4);
  EXPECT_DOUBLE_EQ(half, JensenShannonDivergence({1, 0}, {1, 1}));  // symmetric
  EXPECT_THROW(JensenShannonDivergence({1}, {1, 2}), std::invalid_argument);
  EXPECT_THROW(JensenShannonDivergence({0, 0}, {1, 2}), std::invalid_argument);
}

TEST(Wasserstein1, IsTheShiftBetweenTwoShiftedSamples) {
  EXPECT_NEAR(Wasserstein1({0, 1, 2, 3}, {0.5, 1.5, 2.5, 3.5}), 0.5, 1e-6);
  EXPECT_NEAR(Wasserstein1({0, 0, 0, 1}, {0, 1}), 0.25, 1e-6);  // a quarter of the mass moves by 1
  EXPECT_DOUBLE_EQ(Wasserstein1({2, 1}, {1, 2}), 0.0);
  EXPECT_THROW(Wasserstein1({}, {1}), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

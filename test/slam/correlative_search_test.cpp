#include "doorplate_localization/slam/correlative_search.h"

#include <cmath>

#include <gtest/gtest.h>

#include "slam_test_worlds.h"

namespace doorplate_localization {
namespace {

std::array<float, 256> Field(double resolution_m, double sigma_m) {
  std::array<float, 256> field{};
  for (int d2 = 0; d2 < 255; ++d2) field[d2] = static_cast<float>(std::exp(-0.5 * d2 * resolution_m * resolution_m / (sigma_m * sigma_m)));
  return field;
}

PosePrior FlatPrior(const Pose2D& mean) { return {mean, 0.0, 0.0, 2.0, 5.0}; }

TEST(PosePrior, IsQuadraticNearTheMeanAndLinearBeyondTheHuberThreshold) {
  const PosePrior prior{{0, 0, 0}, 1.0 / (0.1 * 0.1), 1.0 / (0.1 * 0.1), 2.0, 1.0};
  EXPECT_NEAR(prior.Penalty(0.1, 0, 0), 0.5, 1e-12);   // 1 sigma: ½
  EXPECT_NEAR(prior.Penalty(0.2, 0, 0), 2.0, 1e-12);   // 2 sigmas: ½ · 4
  EXPECT_NEAR(prior.Penalty(0.4, 0, 0), 6.0, 1e-12);   // 4 sigmas: 2 · 4 − 2 (not 8)
  EXPECT_NEAR(prior.Penalty(0, 0, 0.1 + 2 * M_PI), 0.5, 1e-9);  // angles wrap
}

TEST(CorrelativeSearch, ExhaustiveSearchFindsTheTrueCellAndHeading) {
  const TiledGrid map = test::MapFrom(test::Room(), {{-1, -0.5, 0}, {0.5, -1, 1.0}});
  const auto field = Field(0.05, 0.1);
  const CorrelativeSearch search(field, 0.05, 0.01);
  const Pose2D truth{0.0, 0.0, 0.0};
  const Pose2D centre{0.1, -0.05, 0.03};
  const Pose2D found = search.Search(map, test::Points(test::Scan(test::Room(), truth)), centre, {0.2, 0.06},
                                     FlatPrior(centre));
  EXPECT_NEAR(found.x_m, truth.x_m, 0.026);
  EXPECT_NEAR(found.y_m, truth.y_m, 0.026);
  EXPECT_NEAR(found.theta_rad, truth.theta_rad, 0.006);
}

TEST(CorrelativeSearch, CoarseToFineSearchFindsAHalfTurnError) {
  const TiledGrid map = test::MapFrom(test::Room(), {{-1, -0.5, 0}, {0.5, -1, 1.0}});
  const auto field = Field(0.05, 0.1);
  const CorrelativeSearch search(field, 0.05, 0.01, /*exhaustive_budget=*/10000);
  const Pose2D truth{0.3, 0.2, 0.5};
  const Pose2D centre{0.4, 0.1, 0.5 + 1.4};  // odometry turned 80° too far
  const Pose2D found = search.Search(map, test::Points(test::Scan(test::Room(), truth)), centre, {0.3, 1.6},
                                     FlatPrior(centre));
  EXPECT_NEAR(found.x_m, truth.x_m, 0.026);
  EXPECT_NEAR(found.y_m, truth.y_m, 0.026);
  EXPECT_NEAR(NormalizeAngle(found.theta_rad - truth.theta_rad), 0.0, 0.0101);  // one angle step
}

TEST(CorrelativeSearch, ThePriorDecidesBetweenEqualMatches) {
  const TiledGrid map = test::MapFrom(test::Corridor(), test::PosesAlongX(-4, 4, 0.05));
  const auto field = Field(0.05, 0.1);
  const CorrelativeSearch search(field, 0.05, 0.01);
  const Pose2D mean{0.1, 0.0, 0.0};
  const PosePrior prior{mean, 1.0 / (0.1 * 0.1), 1.0 / (0.05 * 0.05), 2.0, 5.0};
  // Along the corridor every cell scores the same; the window's edge is 0.2 m from the prior.
  const Pose2D found = search.Search(map, test::Points(test::Scan(test::Corridor(), {0, 0, 0})), {0.3, 0, 0},
                                     {0.2, 0.02}, prior);
  EXPECT_NEAR(found.x_m, mean.x_m, 0.026);
}

}  // namespace
}  // namespace doorplate_localization

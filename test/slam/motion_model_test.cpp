#include "doorplate_localization/slam/motion_model.h"

#include <cmath>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

TEST(OdometryMotionModel, StandingStillAddsNoNoise) {
  const OdometryMotionModel model{MotionModelOptions{}};
  EXPECT_EQ(model.Spread({0, 0, 0}).linear_m, 0.0);
  EXPECT_EQ(model.Spread({0, 0, 0}).angular_rad, 0.0);
  EXPECT_GT(model.Spread({0, 0, 0.3}).angular_rad, 0.0);  // turning on the spot does
}

TEST(OdometryMotionModel, SpreadGrowsWithDistanceAndTurning) {
  const OdometryMotionModel model{MotionModelOptions{}};
  const StepSpread short_move = model.Spread({0.5, 0, 0});
  const StepSpread long_move = model.Spread({1.0, 0, 0});
  const StepSpread turn = model.Spread({1.0, 0, 0.5});
  EXPECT_GT(long_move.linear_m, short_move.linear_m);
  EXPECT_GT(long_move.angular_rad, short_move.angular_rad);
  EXPECT_GT(turn.angular_rad, long_move.angular_rad);
}

TEST(OdometryMotionModel, DrivingBackwardsIsAHalfTurnEachWayAndMuchNoisier) {
  const OdometryMotionModel model{MotionModelOptions{}};
  const StepSpread forward = model.Spread({0.5, 0, 0});
  const StepSpread backward = model.Spread({-0.5, 0, 0});
  EXPECT_GT(backward.angular_rad, 5 * forward.angular_rad);
}

TEST(OdometryMotionModel, AShortMoveHasUnknownDirectionSoItsHeadingIsUncertain) {
  MotionModelOptions options;
  options.min_translation_m = 0.05;
  const OdometryMotionModel model{options};
  // 3 cm forward: below min_translation_m, the direction is not trusted.
  EXPECT_GT(model.Spread({0.03, 0, 0}).angular_rad, model.Spread({0.06, 0, 0}).angular_rad);
}

TEST(OdometryMotionModel, AccumulatedSpreadsAddVariances) {
  const StepSpread total = OdometryMotionModel::Accumulate({0.3, 0.4}, {0.4, 0.3});
  EXPECT_NEAR(total.linear_m, 0.5, 1e-12);
  EXPECT_NEAR(total.angular_rad, 0.5, 1e-12);
}

TEST(OdometryMotionModel, SamplesAreCentredOnTheOdometryWithTheGivenSpread) {
  std::mt19937_64 rng(7);
  const Pose2D from{1.0, 2.0, 0.5};
  const Pose2D delta{1.0, 0.0, 0.2};
  const Pose2D expected = from.Compose(delta);
  const int n = 20000;
  double sx = 0, sxx = 0, st = 0, stt = 0;
  for (int i = 0; i < n; ++i) {
    const Pose2D p = OdometryMotionModel::Sample(from, delta, {0.1, 0.05}, rng);
    const double dx = p.x_m - expected.x_m, dt = NormalizeAngle(p.theta_rad - expected.theta_rad);
    sx += dx, sxx += dx * dx, st += dt, stt += dt * dt;
  }
  EXPECT_NEAR(sx / n, 0.0, 0.003);
  EXPECT_NEAR(std::sqrt(sxx / n), 0.1, 0.003);
  EXPECT_NEAR(st / n, 0.0, 0.0015);
  EXPECT_NEAR(std::sqrt(stt / n), 0.05, 0.0015);
}

TEST(OdometryMotionModel, NegativeNoiseIsRejected) {
  MotionModelOptions options;
  options.rot_stddev_rad_per_m = -0.1;
  EXPECT_THROW(OdometryMotionModel{options}, std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

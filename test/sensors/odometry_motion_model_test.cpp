#include "doorplate_localization/sensors/odometry_motion_model.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

const Pose2D kOrigin{0, 0, 0};

TEST(OdometryMotionModel, DecomposesIntoTurnTowardsTravelThenDriveThenFinalTurn) {
  const OdometryMotionModel model{OdometryMotionModelOptions{}};
  // Facing north at (1, 1); moves 1 m west and ends facing south.
  const OdometryStep m = model.Decompose({1, 1, M_PI / 2}, {0, 1, -M_PI / 2});
  EXPECT_NEAR(m.rot1_rad, M_PI / 2, 1e-12);
  EXPECT_NEAR(m.trans_m, 1.0, 1e-12);
  EXPECT_NEAR(std::fabs(m.rot2_rad), M_PI / 2, 1e-12);
}

TEST(OdometryMotionModel, AMoveBelowTheHeadingThresholdIsATurnInPlace) {
  OdometryMotionModelOptions o;
  o.min_translation_for_heading_m = 0.05;
  const OdometryStep m = OdometryMotionModel(o).Decompose(kOrigin, {0.0, 0.03, 0.4});
  EXPECT_EQ(m.rot1_rad, 0.0);
  EXPECT_NEAR(m.rot2_rad, 0.4, 1e-12);
}

TEST(OdometryMotionModel, StandingStillAddsNoNoiseUnderEveryLaw) {
  for (OdometryNoiseLaw law : {OdometryNoiseLaw::kDiffCorrected, OdometryNoiseLaw::kDiff, OdometryNoiseLaw::kLinear}) {
    OdometryMotionModelOptions o = MapperOdometryDefaults();
    o.noise_law = law;
    const OdometryMotionModel model{o};
    EXPECT_EQ(model.Spread(kOrigin, kOrigin).linear_m, 0.0);
    EXPECT_EQ(model.Spread(kOrigin, kOrigin).angular_rad, 0.0);
    EXPECT_GT(model.Spread(kOrigin, {0, 0, 0.3}).angular_rad, 0.0);  // turning on the spot does
  }
}

TEST(OdometryMotionModel, LinearLawSpreadGrowsInProportionToDistance) {
  const OdometryMotionModel model{MapperOdometryDefaults()};
  const StepSpread half = model.Spread(kOrigin, {0.5, 0, 0});
  const StepSpread whole = model.Spread(kOrigin, {1.0, 0, 0});
  const StepSpread turn = model.Spread(kOrigin, {1.0, 0, 0.5});
  EXPECT_NEAR(whole.angular_rad, 2 * half.angular_rad, 1e-12);
  EXPECT_GT(whole.linear_m, half.linear_m);
  EXPECT_GT(turn.angular_rad, whole.angular_rad);
}

TEST(OdometryMotionModel, CorrectedLawHasTheBooksVariances) {
  OdometryMotionModelOptions o;
  o.rot_noise_from_rot = 0.04, o.rot_noise_from_trans = 0.01, o.trans_noise_from_trans = 0.09, o.trans_noise_from_rot = 0;
  const OdometryStep s = OdometryMotionModel(o).NoiseStddev({0.5, 2.0, 0.0});
  EXPECT_NEAR(s.rot1_rad, std::sqrt(0.04 * 0.25 + 0.01 * 4.0), 1e-12);
  EXPECT_NEAR(s.trans_m, std::sqrt(0.09 * 4.0), 1e-12);
  EXPECT_NEAR(s.rot2_rad, std::sqrt(0.01 * 4.0), 1e-12);
}

TEST(OdometryMotionModel, ReversingIsAHalfTurnEachWayUnlessFoldedAsForward) {
  OdometryMotionModelOptions unfolded = MapperOdometryDefaults();
  const OdometryMotionModel mapper{unfolded};
  EXPECT_GT(mapper.Spread(kOrigin, {-0.5, 0, 0}).angular_rad, 5 * mapper.Spread(kOrigin, {0.5, 0, 0}).angular_rad);
  OdometryMotionModelOptions folded = unfolded;
  folded.reverse_is_forward = true;
  const OdometryMotionModel amcl_like{folded};
  EXPECT_NEAR(amcl_like.Spread(kOrigin, {-0.5, 0, 0}).angular_rad, amcl_like.Spread(kOrigin, {0.5, 0, 0}).angular_rad,
              1e-12);
}

TEST(OdometryMotionModel, AShortMoveOfUnknownDirectionHasAnUncertainHeading) {
  OdometryMotionModelOptions o = MapperOdometryDefaults();
  o.min_translation_for_heading_m = 0.05;
  const OdometryMotionModel unknown{o};
  // 3 cm forward: below the threshold, the direction is not trusted.
  EXPECT_GT(unknown.Spread(kOrigin, {0.03, 0, 0}).angular_rad, unknown.Spread(kOrigin, {0.06, 0, 0}).angular_rad);
  o.short_move_rule = ShortMoveRule::kTurnInPlace;
  const OdometryMotionModel in_place{o};
  EXPECT_LT(in_place.Spread(kOrigin, {0.03, 0, 0}).angular_rad, in_place.Spread(kOrigin, {0.06, 0, 0}).angular_rad);
}

TEST(OdometryMotionModel, AccumulatedSpreadsAddVariances) {
  const StepSpread total = OdometryMotionModel::Accumulate({0.3, 0.4}, {0.4, 0.3});
  EXPECT_NEAR(total.linear_m, 0.5, 1e-12);
  EXPECT_NEAR(total.angular_rad, 0.5, 1e-12);
}

TEST(OdometryMotionModel, IsotropicSamplesAreCentredOnTheOdometryWithTheGivenSpread) {
  std::mt19937_64 rng(7);
  const Pose2D from{1.0, 2.0, 0.5};
  const Pose2D delta{1.0, 0.0, 0.2};
  const Pose2D expected = from.Compose(delta);
  const int n = 20000;
  double sx = 0, sxx = 0, st = 0, stt = 0;
  for (int i = 0; i < n; ++i) {
    const Pose2D p = OdometryMotionModel::SampleIsotropic(from, delta, {0.1, 0.05}, rng);
    const double dx = p.x_m - expected.x_m, dt = NormalizeAngle(p.theta_rad - expected.theta_rad);
    sx += dx, sxx += dx * dx, st += dt, stt += dt * dt;
  }
  EXPECT_NEAR(sx / n, 0.0, 0.003);
  EXPECT_NEAR(std::sqrt(sxx / n), 0.1, 0.003);
  EXPECT_NEAR(st / n, 0.0, 0.0015);
  EXPECT_NEAR(std::sqrt(stt / n), 0.05, 0.0015);
}

TEST(OdometryMotionModel, ComponentSampleWithoutNoiseIsTheMotionInTheStartPosesFrame) {
  std::mt19937_64 rng(1);
  OdometryStepSampler sampler({0, 1, M_PI / 2}, {});
  const Pose2D p = sampler.Sample({5, 5, M_PI / 2}, rng);
  EXPECT_NEAR(p.x_m, 5.0, 1e-12);
  EXPECT_NEAR(p.y_m, 6.0, 1e-12);
  EXPECT_NEAR(p.theta_rad, M_PI, 1e-12);
}

TEST(OdometryMotionModel, ANegativeOrNonFiniteCoefficientIsRejectedByName) {
  OdometryMotionModelOptions o;
  o.rot_noise_from_trans = -0.1;
  try {
    OdometryMotionModel model{o};
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("rot_noise_from_trans"), std::string::npos) << e.what();
  }
  o = OdometryMotionModelOptions{};
  o.min_translation_for_heading_m = NAN;
  EXPECT_THROW(OdometryMotionModel{o}, std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

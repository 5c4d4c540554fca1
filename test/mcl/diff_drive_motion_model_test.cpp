#include "doorplate_localization/mcl/diff_drive_motion_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace doorplate_localization {
namespace {

struct Stats {
  double mean_x = 0, mean_y = 0, mean_theta = 0, sd_x = 0, sd_y = 0, sd_theta = 0;
};

Stats Summarize(const std::vector<Particle>& ps) {
  Stats s;
  const double n = ps.size();
  for (const auto& p : ps) s.mean_x += p.pose.x_m / n, s.mean_y += p.pose.y_m / n, s.mean_theta += p.pose.theta_rad / n;
  for (const auto& p : ps) {
    s.sd_x += std::pow(p.pose.x_m - s.mean_x, 2) / (n - 1);
    s.sd_y += std::pow(p.pose.y_m - s.mean_y, 2) / (n - 1);
    s.sd_theta += std::pow(p.pose.theta_rad - s.mean_theta, 2) / (n - 1);
  }
  s.sd_x = std::sqrt(s.sd_x), s.sd_y = std::sqrt(s.sd_y), s.sd_theta = std::sqrt(s.sd_theta);
  return s;
}

// Moves `n` particles starting at `start` by the odometry motion before -> after.
std::vector<Particle> Move(const OdometryMotionModelOptions& o, const Pose2D& start, const Pose2D& before,
                           const Pose2D& after, int n = 20000, std::uint64_t seed = 7) {
  std::vector<Particle> ps(n, Particle{start, 1.0 / n});
  std::mt19937_64 rng(seed);
  DiffDriveMotionModel(o).Predict(before, after, &ps, rng);
  return ps;
}

OdometryMotionModelOptions Alphas(double a1, double a2, double a3, double a4,
                                   OdometryNoiseLaw type = OdometryNoiseLaw::kDiffCorrected) {
  OdometryMotionModelOptions o;
  o.noise_law = type;
  o.rot_noise_from_rot = a1, o.rot_noise_from_trans = a2, o.trans_noise_from_trans = a3, o.trans_noise_from_rot = a4;
  return o;
}

TEST(DiffDriveMotionModel, NoiseFreeMotionIsAppliedInEachParticlesOwnFrame) {
  // Odometry: 1 m forward then a 90° left turn, starting from an odometry heading of 0. A particle
  // facing north must end 1 m further north, facing west.
  const auto ps = Move(Alphas(0, 0, 0, 0), {5.0, 5.0, M_PI / 2}, {0, 0, 0}, {1.0, 0.0, M_PI / 2}, 3);
  for (const auto& p : ps) {
    EXPECT_NEAR(p.pose.x_m, 5.0, 1e-12);
    EXPECT_NEAR(p.pose.y_m, 6.0, 1e-12);
    EXPECT_NEAR(p.pose.theta_rad, M_PI, 1e-12);
  }
}

TEST(DiffDriveMotionModel, CorrectedTranslationNoiseHasStddevSqrtAlpha3TimesDistance) {
  const auto ps = Move(Alphas(0, 0, 0.01, 0), {}, {}, {2.0, 0.0, 0.0});
  const Stats s = Summarize(ps);
  EXPECT_NEAR(s.mean_x, 2.0, 0.005);
  EXPECT_NEAR(s.sd_x, std::sqrt(0.01) * 2.0, 0.005);  // 0.2 m
  EXPECT_NEAR(s.sd_y, 0.0, 1e-12);                    // no rotation noise configured
}

TEST(DiffDriveMotionModel, LegacyDiffUsesTheVarianceTermAsStddev) {
  // amcl's original "diff" (navigation #20): sigma = alpha3 · trans² = 0.01 · 4 = 0.04 m, not 0.2 m.
  const auto ps = Move(Alphas(0, 0, 0.01, 0, OdometryNoiseLaw::kDiff), {}, {}, {2.0, 0.0, 0.0});
  EXPECT_NEAR(Summarize(ps).sd_x, 0.04, 0.002);
}

TEST(DiffDriveMotionModel, TranslationCausesHeadingNoiseThroughAlpha2) {
  // rot1 and rot2 each get sigma = sqrt(alpha2) · trans; the heading gets their sum: sqrt(2) · 0.1 · 1.
  const auto ps = Move(Alphas(0, 0.01, 0, 0), {}, {}, {1.0, 0.0, 0.0});
  const Stats s = Summarize(ps);
  EXPECT_NEAR(s.sd_theta, std::sqrt(2.0) * 0.1, 0.005);
  EXPECT_NEAR(s.sd_y, 0.1 * 1.0, 0.005);  // rot1 noise swings the 1 m translation sideways
}

TEST(DiffDriveMotionModel, RotationInPlaceOnlyPerturbsTheHeading) {
  const auto ps = Move(Alphas(0.04, 0, 0, 0), {}, {}, {0.0, 0.0, 1.0});
  const Stats s = Summarize(ps);
  EXPECT_NEAR(s.mean_theta, 1.0, 0.005);
  EXPECT_NEAR(s.sd_theta, std::sqrt(0.04) * 1.0, 0.005);  // rot1 = 0 (no travel direction), rot2 = 1 rad
  EXPECT_NEAR(s.sd_x, 0.0, 1e-12);
}

TEST(DiffDriveMotionModel, DrivingBackwardsIsAsNoisyAsForwards) {
  const auto forward = Summarize(Move(Alphas(0.05, 0.01, 0.01, 0.05), {}, {}, {1.0, 0.0, 0.0}));
  const auto backward = Summarize(Move(Alphas(0.05, 0.01, 0.01, 0.05), {}, {}, {-1.0, 0.0, 0.0}));
  EXPECT_NEAR(backward.mean_x, -1.0, 0.01);
  EXPECT_NEAR(backward.sd_x, forward.sd_x, 0.005);
  EXPECT_NEAR(backward.sd_theta, forward.sd_theta, 0.005);
}

TEST(DiffDriveMotionModel, RejectsANegativeCoefficientByName) {
  OdometryMotionModelOptions o;
  o.trans_noise_from_trans = -0.1;
  try {
    DiffDriveMotionModel m(o);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("trans_noise_from_trans"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace doorplate_localization

// TextAmcl's resampling: KLD-sampling of the particle count and Augmented MCL's random particles.
#include "doorplate_localization/mcl/text_amcl.h"

#include <gtest/gtest.h>

#include <cmath>

#include "amcl_drive.h"

namespace doorplate_localization {
namespace {

class TextAmclResampleTest : public ::testing::Test {
 protected:
  std::shared_ptr<LocalizationGrid> room_ = std::make_shared<LocalizationGrid>(test::AsymmetricRoom());
  test::FilterSetup setup_;
  std::mt19937_64 rng_{23};
  test::Robot robot_{{1.0, 0.6, 0.0}, {}};

  std::unique_ptr<TextAmcl> ConvergedFilter() {
    auto amcl = test::MakeFilter(room_, nullptr, setup_);
    amcl->Initialize({1.0, 0.6, 0.0}, Eigen::Vector3d(0.01, 0.01, 0.003).asDiagonal());
    amcl->UpdateOdometry(robot_.odom);
    amcl->UpdateLaser(test::SyntheticScan(*room_, robot_.truth, &rng_));
    for (int i = 0; i < 8; ++i) test::Turn(amcl.get(), *room_, &robot_, 0.6, rng_);  // 4.8 rad in place
    return amcl;
  }

  // Kidnaps the robot to `to` (odometry does not notice) and keeps turning in place for `turns` updates.
  void KidnapAndTurn(TextAmcl* amcl, const Pose2D& to, int turns) {
    robot_.truth = to;
    for (int i = 0; i < turns; ++i) test::Turn(amcl, *room_, &robot_, 0.6, rng_);
  }
};

TEST_F(TextAmclResampleTest, KldKeepsManyParticlesWhileSpreadAndFewOnceConverged) {
  auto amcl = test::MakeFilter(room_, nullptr, setup_);  // max_particles 5000
  amcl->GlobalLocalization();
  ASSERT_EQ(amcl->Status().particle_count, 5000);
  amcl->UpdateOdometry(robot_.odom);
  amcl->UpdateLaser(test::SyntheticScan(*room_, robot_.truth, &rng_));
  test::Turn(amcl.get(), *room_, &robot_, 0.6, rng_);  // second update: first resampling
  EXPECT_EQ(amcl->Status().resamples, 1);
  EXPECT_EQ(amcl->Status().particle_count, 5000);  // spread over thousands of bins: the bound exceeds the max
  auto converged = ConvergedFilter();
  EXPECT_EQ(converged->State(), LocalizationState::kConverged);
  // Tens of bins of 0.5 m × 0.5 m × 10°: amcl's kld_err 0.01 and kld_z 0.99 ask 1500-3000 particles.
  EXPECT_LT(converged->Status().particle_count, 3000);
}

TEST_F(TextAmclResampleTest, RecoveryInjectsRandomParticlesWhenScansStopFitting) {
  auto amcl = ConvergedFilter();
  ASSERT_EQ(amcl->State(), LocalizationState::kConverged);
  ASSERT_EQ(amcl->Status().total_random_particles, 0);  // scans fit as well as ever: no injection
  KidnapAndTurn(amcl.get(), {4.0, 2.0, 2.5}, 10);
  const TextAmclStatus s = amcl->Status();
  EXPECT_GT(s.total_random_particles, 50);
  EXPECT_LT(s.w_fast_over_w_slow, 1.0);
  EXPECT_EQ(s.state, LocalizationState::kLost);
  EXPECT_EQ(s.lost_reason, LostReason::kLikelihoodCollapse);
}

TEST_F(TextAmclResampleTest, NoRandomParticlesWhenRecoveryIsDisabled) {
  setup_.amcl.recovery_alpha_slow = setup_.amcl.recovery_alpha_fast = 0.0;  // amcl's shipped default
  auto amcl = ConvergedFilter();
  KidnapAndTurn(amcl.get(), {4.0, 2.0, 2.5}, 12);
  EXPECT_EQ(amcl->Status().total_random_particles, 0);
  EXPECT_NE(amcl->State(), LocalizationState::kLost);  // and the filter cannot even tell it is lost
}

TEST_F(TextAmclResampleTest, RandomParticlesRecoverAKidnappedRobotInAnAsymmetricRoom) {
  setup_.amcl.min_particles = 500;
  auto amcl = ConvergedFilter();
  const Pose2D kidnapped_to{4.0, 2.0, 2.5};
  KidnapAndTurn(amcl.get(), kidnapped_to, 60);
  EXPECT_LT(test::PositionError(amcl->Estimate().pose, robot_.truth), 0.2);
  EXPECT_EQ(amcl->State(), LocalizationState::kConverged);
}

// After global localization with a text model the filter does not claim kConverged on scans alone, even
// where they pin the pose, until a plate reading has been used (on a symmetric floor the scans alone
// converge on a twin pose: docs/results/floor-localize.md). Without text, or with the rule off: amcl's.
TEST_F(TextAmclResampleTest, AfterGlobalLocalizationWithTextItConvergesOnlyOnceAPlateIsUsed) {
  const std::shared_ptr<LocalizationGrid> grid = room_;
  auto plates = std::make_shared<TextMap>();
  TextLandmark plate;
  plate.text = "101";
  plate.pose = {4.5, 1.6, -M_PI / 2};  // ahead on the left, 1.0 m off the drive line, facing it
  plates->landmarks.push_back(plate);
  for (const int variant : {0, 1, 2}) {  // 0: the rule; 1: the rule off; 2: no text model
    test::FilterSetup setup = setup_;
    setup.amcl.converge_after_plate = variant != 1;
    auto amcl = test::MakeFilter(grid, variant == 2 ? nullptr : plates, setup);
    test::Robot robot{{0.6, 0.6, 0.0}, {}};
    std::mt19937_64 rng(5);
    amcl->GlobalLocalization();
    amcl->UpdateOdometry(robot.odom);
    amcl->UpdateLaser(test::SyntheticScan(*grid, robot.truth, &rng));
    bool ever_converged = false;
    for (int i = 0; i < 30; ++i) {  // 3 m east along y = 0.6, below the box
      test::Drive(amcl.get(), *grid, *plates, &robot, 0.1, false, rng);
      ever_converged = ever_converged || amcl->State() == LocalizationState::kConverged;
    }
    if (variant != 0) {
      EXPECT_TRUE(ever_converged) << "variant " << variant;  // amcl's rule: on scans alone
      continue;
    }
    EXPECT_FALSE(ever_converged);
    EXPECT_EQ(amcl->State(), LocalizationState::kTracking);
    ASSERT_TRUE(amcl->UpdatePlate(test::ReadingOf(plate, robot.truth)).used);
    test::Drive(amcl.get(), *grid, *plates, &robot, 0.5, false, rng);
    EXPECT_EQ(amcl->State(), LocalizationState::kConverged);
    EXPECT_LT(test::PositionError(amcl->Estimate().pose, robot.truth), 0.3);
  }
}

TEST_F(TextAmclResampleTest, AmclStyleResetInjectsInBursts) {
  auto book = ConvergedFilter();
  KidnapAndTurn(book.get(), {4.0, 2.0, 2.5}, 12);
  setup_.amcl.recovery_reset_after_injection = true;
  robot_ = {{1.0, 0.6, 0.0}, {}};
  auto amcl_style = ConvergedFilter();
  KidnapAndTurn(amcl_style.get(), {4.0, 2.0, 2.5}, 12);
  EXPECT_GT(amcl_style->Status().total_random_particles, 0);
  EXPECT_LT(amcl_style->Status().total_random_particles, book->Status().total_random_particles);
}

}  // namespace
}  // namespace doorplate_localization

// TextAmcl with doorplates in the symmetric, periodic corridor of mcl_fixtures.h, where a laser alone
// cannot tell where the robot is.
#include "doorplate_localization/mcl/text_amcl.h"

#include <gtest/gtest.h>

#include <cmath>

#include "amcl_drive.h"

namespace doorplate_localization {
namespace {

class TextAmclPlateTest : public ::testing::Test {
 protected:
  test::SymmetricCorridor corridor_ = test::MakeSymmetricCorridor();
  test::FilterSetup setup_;
  std::mt19937_64 rng_{29};

  void SetUp() override { setup_.amcl.max_particles = 3000; }

  bool Localized(const TextAmcl& amcl, const Pose2D& truth) const {
    const PoseEstimate e = amcl.Estimate();
    return amcl.State() == LocalizationState::kConverged && test::PositionError(e.pose, truth) < 0.3 &&
           std::fabs(NormalizeAngle(e.pose.theta_rad - truth.theta_rad)) < 0.1;
  }

  struct RunResult {
    bool localized = false;
    double best_cluster_weight = 0.0;
    double error_m = 0.0;
  };

  // Global localization, then 14 m east along the centre line from x = 10.3 (reading 106, 108, 110, 112
  // on the north wall when `read_plates`).
  RunResult GlobalRun(std::uint64_t seed, bool read_plates) {
    setup_.amcl.random_seed = seed;
    auto amcl = test::MakeFilter(corridor_.grid, corridor_.text_map, setup_);
    std::mt19937_64 scan_rng(seed);
    test::Robot robot{{10.3, 1.0, 0.0}, {}};
    amcl->GlobalLocalization();
    amcl->UpdateOdometry(robot.odom);
    amcl->UpdateLaser(test::SyntheticScan(*corridor_.grid, robot.truth, &scan_rng));
    test::Drive(amcl.get(), *corridor_.grid, *corridor_.text_map, &robot, 14.0, read_plates, scan_rng);
    test::Settle(amcl.get(), *corridor_.grid, robot, scan_rng);
    return {Localized(*amcl, robot.truth), amcl->Status().best_cluster_weight,
            test::PositionError(amcl->Estimate().pose, robot.truth)};
  }
};

TEST_F(TextAmclPlateTest, ConvergesFromAGlobalStartOnlyWhenPlatesAreRead) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    EXPECT_TRUE(GlobalRun(seed, true).localized) << "seed " << seed;
    // Laser only: periodic doors and a half-turn symmetry leave ~18 equally good hypotheses. The filter
    // ends split between clusters or converged on a wrong one (the symmetric failure amcl users report).
    const RunResult laser_only = GlobalRun(seed, false);
    EXPECT_FALSE(laser_only.localized) << "seed " << seed;
    EXPECT_TRUE(laser_only.best_cluster_weight < 0.9 || laser_only.error_m > 1.0) << "seed " << seed;
  }
}

TEST_F(TextAmclPlateTest, RepeatedRoomNumberKeepsTwoHypothesesUntilADistinctPlateIsRead) {
  // Plate 110 (north wall, door 4) gets a twin: its half-turn image on the south wall also reads 110.
  auto map = std::make_shared<TextMap>(*corridor_.text_map);
  const int plate = corridor_.NorthPlate(4);
  const int twin = corridor_.SouthPlate(corridor_.door_x.size() - 1 - 4);
  map->landmarks[twin].text = map->landmarks[plate].text;
  auto amcl = test::MakeFilter(corridor_.grid, map, setup_);
  test::Robot robot{{17.0, 1.0, 0.0}, {}};
  amcl->GlobalLocalization();
  amcl->UpdateOdometry(robot.odom);
  amcl->UpdateLaser(test::SyntheticScan(*corridor_.grid, robot.truth, &rng_));
  // Drive past plate 110 (at x = 18.8) and 2 m on: both 110 plates explain everything seen so far.
  const auto first = test::Drive(amcl.get(), *corridor_.grid, *map, &robot, 3.8, true, rng_);
  ASSERT_EQ(first.plates_read, std::vector<int>{plate});
  EXPECT_GT(first.plate_results[0].reseeded_particles, 0);  // not converged: seeds at both 110s
  const double at_truth = test::WeightNear(*amcl, robot.truth);
  const double at_image = test::WeightNear(*amcl, corridor_.HalfTurn(robot.truth));
  EXPECT_GT(at_truth, 0.15);
  EXPECT_GT(at_image, 0.15);
  EXPECT_GT(at_truth + at_image, 0.85);  // every other hypothesis is gone
  EXPECT_NE(amcl->State(), LocalizationState::kConverged);
  // Plate 112 (x = 22.8): the half-turn hypothesis would be passing plate 109 on the south wall instead.
  const auto second = test::Drive(amcl.get(), *corridor_.grid, *map, &robot, 2.5, true, rng_);
  ASSERT_EQ(second.plates_read, std::vector<int>{corridor_.NorthPlate(5)});
  EXPECT_LT(test::PositionError(amcl->Estimate().pose, robot.truth), 0.3);
  EXPECT_LT(test::WeightNear(*amcl, corridor_.HalfTurn(robot.truth)), 0.1);
  // One more plate (114 at x = 26.8) and the image is gone.
  test::Drive(amcl.get(), *corridor_.grid, *map, &robot, 4.0, true, rng_);
  test::Settle(amcl.get(), *corridor_.grid, robot, rng_);
  EXPECT_TRUE(Localized(*amcl, robot.truth));
  EXPECT_LT(test::WeightNear(*amcl, corridor_.HalfTurn(robot.truth)), 0.01);
}

TEST_F(TextAmclPlateTest, KidnappedRobotIsRecoveredAfterReadingAPlate) {
  auto amcl = test::MakeFilter(corridor_.grid, corridor_.text_map, setup_);
  test::Robot robot{{12.0, 1.0, 0.0}, {}};
  amcl->Initialize(robot.truth, Eigen::Vector3d(0.01, 0.01, 0.003).asDiagonal());
  amcl->UpdateOdometry(robot.odom);
  amcl->UpdateLaser(test::SyntheticScan(*corridor_.grid, robot.truth, &rng_));
  test::Drive(amcl.get(), *corridor_.grid, *corridor_.text_map, &robot, 4.0, true, rng_);
  test::Settle(amcl.get(), *corridor_.grid, robot, rng_);
  ASSERT_TRUE(Localized(*amcl, robot.truth));
  // Carried 8 m back (two door periods): the laser sees exactly the same corridor.
  robot.truth.x_m -= 8.0;
  const auto log = test::Drive(amcl.get(), *corridor_.grid, *corridor_.text_map, &robot, 3.0, true, rng_);
  ASSERT_EQ(log.plate_results.size(), 1u);
  EXPECT_TRUE(log.plate_results[0].contradicted_estimate);  // read 106 where 110 was expected
  EXPECT_GT(log.plate_results[0].reseeded_particles, 0);
  EXPECT_EQ(amcl->Status().plate_contradictions, 1);
  EXPECT_EQ(amcl->State(), LocalizationState::kLost);
  EXPECT_EQ(amcl->Status().lost_reason, LostReason::kPlateContradiction);
  test::Drive(amcl.get(), *corridor_.grid, *corridor_.text_map, &robot, 4.5, true, rng_);  // reads 108
  test::Settle(amcl.get(), *corridor_.grid, robot, rng_);
  EXPECT_TRUE(Localized(*amcl, robot.truth));
  EXPECT_EQ(amcl->Status().lost_reason, LostReason::kNone);
}

TEST_F(TextAmclPlateTest, AReadingTheEstimateExplainsChangesNothingStructural) {
  auto amcl = test::MakeFilter(corridor_.grid, corridor_.text_map, setup_);
  test::Robot robot{{12.0, 1.0, 0.0}, {}};
  amcl->Initialize(robot.truth, Eigen::Vector3d(0.01, 0.01, 0.003).asDiagonal());
  amcl->UpdateOdometry(robot.odom);
  const auto log = test::Drive(amcl.get(), *corridor_.grid, *corridor_.text_map, &robot, 4.0, true, rng_);
  ASSERT_EQ(log.plate_results.size(), 1u);
  const PlateUpdateResult& r = log.plate_results[0];
  EXPECT_TRUE(r.used);
  EXPECT_GT(r.explained_ratio, setup_.amcl.text_explained_ratio);
  EXPECT_FALSE(r.contradicted_estimate);
  EXPECT_EQ(r.reseeded_particles, 0);
  EXPECT_EQ(amcl->State(), LocalizationState::kConverged);
}

TEST_F(TextAmclPlateTest, IgnoresUnusableReadings) {
  auto amcl = test::MakeFilter(corridor_.grid, corridor_.text_map, setup_);
  const TextLandmark& plate = corridor_.text_map->landmarks[corridor_.NorthPlate(3)];
  const Pose2D truth{plate.pose.x_m, 1.0, 0.0};
  EXPECT_EQ(amcl->UpdatePlate(test::ReadingOf(plate, truth)).ignored_reason, "not initialized");
  amcl->Initialize(truth, Eigen::Matrix3d::Identity() * 0.01);
  const PlateUpdateResult low = amcl->UpdatePlate(test::ReadingOf(plate, truth, 0.3));
  EXPECT_FALSE(low.used);
  EXPECT_NE(low.ignored_reason.find("text_min_confidence"), std::string::npos);
  PlateReading invalid = test::ReadingOf(plate, truth);
  invalid.confidence = -1.0;
  EXPECT_THROW(amcl->UpdatePlate(invalid), std::invalid_argument);
  setup_.with_text = false;
  auto laser_only = test::MakeFilter(corridor_.grid, corridor_.text_map, setup_);
  laser_only->Initialize(truth, Eigen::Matrix3d::Identity() * 0.01);
  EXPECT_EQ(laser_only->UpdatePlate(test::ReadingOf(plate, truth)).ignored_reason, "no text observation model");
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/mcl/plate_likelihood_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "mcl_fixtures.h"

namespace doorplate_localization {
namespace {

class PlateLikelihoodModelTest : public ::testing::Test {
 protected:
  test::SymmetricCorridor corridor_ = test::MakeSymmetricCorridor();
  PlateLikelihoodModel model_{corridor_.text_map, corridor_.grid, {}};
  const TextLandmark& plate_ = corridor_.text_map->landmarks[corridor_.NorthPlate(2)];  // "106"
  // Driving east 1 m from the north wall, abeam of the plate.
  const Pose2D truth_{plate_.pose.x_m, 1.0, 0.0};
  const double floor_ = PlateLikelihoodModelOptions().floor_probability;
};

TEST_F(PlateLikelihoodModelTest, TruePoseScoresHighestAndWrongPosesGetTheFloor) {
  const PlateReading r = test::ReadingOf(plate_, truth_);
  ASSERT_EQ(r.text, "106");
  EXPECT_NEAR(model_.Likelihood(r, truth_), floor_ + 0.9, 1e-9);
  // 0.3 m along the corridor: bearing off by ~17°, range by ~0.04 m.
  EXPECT_LT(model_.Likelihood(r, {truth_.x_m + 0.3, 1.0, 0.0}), 0.9 * std::exp(-0.5 * 2.5 * 2.5) + floor_);
  // Next door's position (4 m on): plate 108 there, one non-confusable edit from 106.
  EXPECT_NEAR(model_.Likelihood(r, {truth_.x_m + 4.0, 1.0, 0.0}), floor_ + 0.1 * 0.05, 1e-9);
  // Facing west at the same spot: the plate would be on the right (bearing -90°).
  EXPECT_DOUBLE_EQ(model_.Likelihood(r, {truth_.x_m, 1.0, M_PI}), floor_);
}

TEST_F(PlateLikelihoodModelTest, PlatesAreReadOnlyFromInFront) {
  const int north = corridor_.NorthPlate(2);
  EXPECT_TRUE(model_.InView(north, truth_.Position()));
  EXPECT_FALSE(model_.InView(north, {plate_.pose.x_m, 2.5}));         // behind the plate (in the wall)
  EXPECT_FALSE(model_.InView(north, {plate_.pose.x_m + 5.0, 1.9}));   // 89° off its normal
  EXPECT_FALSE(model_.InView(north, {plate_.pose.x_m + 7.0, 0.2}));   // farther than max_view_distance_m
}

TEST(PlateLikelihoodModel, ObstaclesHidePlates) {
  // A plate on the room's east wall facing west; the inner box (x 2..2.6, y 1..1.4) hides it from (1, 1.2).
  auto grid = std::make_shared<LocalizationGrid>(test::AsymmetricRoom());
  auto map = std::make_shared<TextMap>();
  TextLandmark plate;
  plate.text = "7";
  plate.pose = {6.0, 1.2, M_PI};
  map->landmarks.push_back(plate);
  const PlateLikelihoodModel model(map, grid, {});
  EXPECT_FALSE(model.InView(0, {1.0, 1.2}));
  EXPECT_TRUE(model.InView(0, {1.0, 2.0}));  // the sight line passes above the box
  PlateLikelihoodModelOptions no_check;
  no_check.check_line_of_sight = false;
  EXPECT_TRUE(PlateLikelihoodModel(map, grid, no_check).InView(0, {1.0, 1.2}));
  EXPECT_TRUE(PlateLikelihoodModel(map, nullptr, {}).InView(0, {1.0, 1.2}));  // no grid: no check
}

TEST_F(PlateLikelihoodModelTest, RepeatedNumbersSupportEveryPlateShowingThem) {
  auto map = std::make_shared<TextMap>(*corridor_.text_map);
  const int a = corridor_.NorthPlate(2), b = corridor_.SouthPlate(7);
  map->landmarks[b].text = map->landmarks[a].text;  // two "106" plates
  PlateLikelihoodModel model(map, corridor_.grid, {});
  const PlateReading r = test::ReadingOf(map->landmarks[a], truth_);
  const Pose2D twin_view{map->landmarks[b].pose.x_m, 1.0, M_PI};  // driving west, plate on the left
  EXPECT_NEAR(model.Likelihood(r, truth_), floor_ + 0.9, 1e-9);
  EXPECT_NEAR(model.Likelihood(r, twin_view), floor_ + 0.9, 1e-9);
}

TEST_F(PlateLikelihoodModelTest, ConfusedReadingsScoreBelowExactOnesButAboveTheFloor) {
  PlateReading r = test::ReadingOf(plate_, truth_);
  r.text = "105";  // 5 for 6
  const double confused = model_.Likelihood(r, truth_);
  EXPECT_NEAR(confused, floor_ + 0.1 * 0.3, 1e-9);
  r.text = "999";
  EXPECT_DOUBLE_EQ(model_.Likelihood(r, truth_), floor_);  // never zero: a wrong reading cannot kill
}

TEST_F(PlateLikelihoodModelTest, ARangeSharpensTheLikelihood) {
  PlateReading with_range = test::ReadingOf(plate_, truth_);
  PlateReading without = with_range;
  without.range_m.reset();
  const Pose2D farther{truth_.x_m, 0.4, 0.0};  // same bearing, 0.6 m farther
  EXPECT_NEAR(model_.Likelihood(without, farther), floor_ + 0.9, 1e-9);
  EXPECT_LT(model_.Likelihood(with_range, farther), floor_ + 0.9 * std::exp(-0.5 * 4.0) + 1e-9);
}

TEST_F(PlateLikelihoodModelTest, LogLikelihoodsMatchAndUnexplainedIsTheFloor) {
  const PlateReading r = test::ReadingOf(plate_, truth_);
  std::vector<Particle> ps{{truth_, 0.5}, {{truth_.x_m, 1.0, M_PI}, 0.5}};  // the second faces west
  std::vector<double> ll;
  model_.LogLikelihoods(r, ps, &ll);
  ASSERT_EQ(ll.size(), 2u);
  EXPECT_NEAR(ll[0], std::log(floor_ + 0.9), 1e-9);
  EXPECT_NEAR(ll[1], model_.UnexplainedLogLikelihood(r), 1e-12);
  PlateReading bad = r;
  bad.confidence = 2.0;
  EXPECT_THROW(model_.LogLikelihoods(bad, ps, &ll), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

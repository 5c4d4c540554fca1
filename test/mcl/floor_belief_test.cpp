#include "doorplate_localization/mcl/floor_belief.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

TEST(FloorBelief, FromAnUnknownStartTwoReadingsOfOneFloorMakeItCertainOneDoesNot) {
  FloorBelief belief(FloorBeliefOptions{}, 2, -1);
  EXPECT_DOUBLE_EQ(belief.probabilities()[0], 0.5);
  EXPECT_EQ(belief.CertainFloor(), -1);
  ASSERT_TRUE(belief.Update({false, true}));
  EXPECT_NEAR(belief.probabilities()[1], 0.95, 1e-12);
  EXPECT_EQ(belief.CertainFloor(), -1);
  ASSERT_TRUE(belief.Update({false, true}));
  EXPECT_GT(belief.probabilities()[1], 0.99);
  EXPECT_EQ(belief.CertainFloor(), 1);
}

TEST(FloorBelief, OneMisreadDoesNotMoveACertainFloorThreeReadingsOfAnotherDo) {
  FloorBelief belief(FloorBeliefOptions{}, 2, 0);
  belief.Update({false, true});
  EXPECT_EQ(belief.MostLikely(), 0);
  EXPECT_EQ(belief.CertainFloor(), -1);  // no longer certain, not yet moved
  belief.Update({false, true});
  EXPECT_EQ(belief.MostLikely(), 1);
  EXPECT_EQ(belief.CertainFloor(), -1);
  belief.Update({false, true});
  EXPECT_EQ(belief.CertainFloor(), 1);
}

TEST(FloorBelief, TwoReadingsOfTheCurrentFloorRestoreCertaintyAfterAMisread) {
  FloorBelief belief(FloorBeliefOptions{}, 2, 0);
  belief.Update({false, true});
  belief.Update({true, false});
  EXPECT_EQ(belief.CertainFloor(), -1);
  belief.Update({true, false});
  EXPECT_EQ(belief.CertainFloor(), 0);
}

TEST(FloorBelief, ARoomOnEveryFloorOrOnNoneChangesNothing) {
  FloorBelief belief(FloorBeliefOptions{}, 3, -1);
  EXPECT_FALSE(belief.Update({true, true, true}));
  EXPECT_FALSE(belief.Update({false, false, false}));
  for (double p : belief.probabilities()) EXPECT_DOUBLE_EQ(p, 1.0 / 3.0);
}

TEST(FloorBelief, ARoomOnTwoOfThreeFloorsSplitsTheBeliefBetweenThem) {
  FloorBelief belief(FloorBeliefOptions{}, 3, -1);
  belief.Update({true, true, false});
  EXPECT_NEAR(belief.probabilities()[0], belief.probabilities()[1], 1e-12);
  EXPECT_LT(belief.probabilities()[2], 0.05);
  belief.Update({false, true, false});
  EXPECT_EQ(belief.MostLikely(), 1);
}

TEST(FloorBelief, AOneFloorBuildingIsAlwaysCertain) {
  FloorBelief belief(FloorBeliefOptions{}, 1, -1);
  EXPECT_EQ(belief.CertainFloor(), 0);
  EXPECT_FALSE(belief.Update({false}));
  EXPECT_EQ(belief.CertainFloor(), 0);
}

TEST(FloorBelief, RefusesBadOptionsAndCountsNamingTheField) {
  FloorBeliefOptions bad;
  bad.misread_probability = 0.5;
  try {
    FloorBelief belief(bad, 2, -1);
    FAIL() << "accepted misread_probability 0.5";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("FloorBeliefOptions.misread_probability"), std::string::npos) << e.what();
  }
  bad = FloorBeliefOptions{};
  bad.certain_probability = 1.0;
  EXPECT_THROW(FloorBelief(bad, 2, -1), std::invalid_argument);
  EXPECT_THROW(FloorBelief(FloorBeliefOptions{}, 0, -1), std::invalid_argument);
  EXPECT_THROW(FloorBelief(FloorBeliefOptions{}, 2, 2), std::invalid_argument);
  FloorBelief belief(FloorBeliefOptions{}, 2, -1);
  EXPECT_THROW(belief.Update({true}), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

// The rigid fit of mapped plates onto true ones, on a handful of hand-placed plates.
#include "plate_alignment.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace doorplate_localization {
namespace {

TextMap Plates(const std::vector<std::pair<std::string, Vec2>>& plates) {
  TextMap map;
  for (const auto& [text, p] : plates) {
    TextLandmark l;
    l.text = text;
    l.pose = {p.x, p.y, 0.0};
    map.landmarks.push_back(l);
  }
  return map;
}

const TextMap kTruth = Plates({{"201", {2, 0}}, {"202", {6, 0}}, {"203", {10, 2}}, {"204", {14, 2}}, {"205", {18, 0}}});

// The true plates seen from a map frame placed at `world_from_map` (and listed in another order).
TextMap MappedFrom(const Pose2D& world_from_map) {
  const Pose2D map_from_world = world_from_map.Inverse();
  TextMap mapped;
  for (int i : {3, 0, 4, 1, 2}) {
    TextLandmark l = kTruth.landmarks[i];
    const Vec2 p = map_from_world.TransformPoint(l.pose.Position());
    l.pose = {p.x, p.y, 0.0};
    mapped.landmarks.push_back(l);
  }
  return mapped;
}

TEST(AlignPlates, RecoversTheRotationAndTranslationOfAnUndistortedMap) {
  const Pose2D world_from_map{3.0, -1.5, 0.35};
  const PlateAlignment a = AlignPlates(MappedFrom(world_from_map), kTruth);
  ASSERT_TRUE(a.ok);
  EXPECT_EQ(a.pairs, 5);
  EXPECT_NEAR(a.world_from_map.x_m, 3.0, 1e-9);
  EXPECT_NEAR(a.world_from_map.y_m, -1.5, 1e-9);
  EXPECT_NEAR(a.world_from_map.theta_rad, 0.35, 1e-9);
  EXPECT_NEAR(a.rmse_m, 0.0, 1e-9);
  ASSERT_EQ(a.residuals_m.size(), 5u);
  for (double r : a.residuals_m) EXPECT_NEAR(r, 0.0, 1e-9);
}

// One plate mapped 0.5 m off: the fit spreads the error, and leaves less than the true transform does.
TEST(AlignPlates, ResidualsOfADistortedMapAreTheLeastSquaresOnes) {
  const Pose2D world_from_map{1.0, 2.0, -0.2};
  TextMap mapped = MappedFrom(world_from_map);
  mapped.landmarks[2].pose.x_m += 0.5;  // "205"
  const PlateAlignment a = AlignPlates(mapped, kTruth);
  ASSERT_TRUE(a.ok);
  EXPECT_GT(a.residuals_m[2], 0.2);
  EXPECT_LT(a.residuals_m[2], 0.5);
  EXPECT_GT(a.max_residual_m, 0.0);
  double fitted2 = 0.0;
  for (double r : a.residuals_m) fitted2 += r * r;
  EXPECT_NEAR(a.rmse_m, std::sqrt(fitted2 / 5), 1e-12);
  EXPECT_LT(fitted2, 0.5 * 0.5);  // under world_from_map the squared errors sum to 0.25
}

TEST(AlignPlates, RepeatedAndUnknownRoomsAreLeftOut) {
  TextMap truth = kTruth;
  truth.landmarks.push_back(truth.landmarks[0]);  // "201" twice
  truth.landmarks.back().pose.y_m = 2.0;
  TextMap mapped = MappedFrom(Pose2D{});
  mapped.landmarks.push_back(mapped.landmarks[0]);  // "204" twice in the map
  TextLandmark stranger;
  stranger.text = "999";
  mapped.landmarks.push_back(stranger);
  const PlateAlignment a = AlignPlates(mapped, truth);
  ASSERT_TRUE(a.ok);
  EXPECT_EQ(a.pairs, 3);  // 202, 203, 205
  EXPECT_DOUBLE_EQ(a.residuals_m[0], -1.0);  // 204 (repeated in the map)
  EXPECT_DOUBLE_EQ(a.residuals_m[1], -1.0);  // 201 (repeated in the truth)
  EXPECT_DOUBLE_EQ(a.residuals_m[6], -1.0);  // 999
  EXPECT_NEAR(a.residuals_m[2], 0.0, 1e-9);
}

TEST(AlignPlates, FewerThanTwoPairsOnlyShiftTheCentroid) {
  const TextMap one = Plates({{"203", {1, 1}}});
  const PlateAlignment a = AlignPlates(one, kTruth);
  EXPECT_FALSE(a.ok);
  EXPECT_EQ(a.pairs, 1);
  EXPECT_NEAR(a.world_from_map.x_m, 9.0, 1e-12);
  EXPECT_NEAR(a.world_from_map.y_m, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(a.world_from_map.theta_rad, 0.0);
  EXPECT_NEAR(a.residuals_m[0], 0.0, 1e-12);
  const PlateAlignment none = AlignPlates(Plates({{"999", {1, 1}}}), kTruth);
  EXPECT_FALSE(none.ok);
  EXPECT_EQ(none.pairs, 0);
  EXPECT_DOUBLE_EQ(none.residuals_m[0], -1.0);
}

}  // namespace
}  // namespace doorplate_localization

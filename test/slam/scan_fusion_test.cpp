#include "doorplate_localization/slam/scan_fusion.h"

#include <cmath>
#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

// Echoes (base_link) of a wall along y = 1 m from x = -3 to 3 m seen from (x_m, 0), one every 5 cm of wall,
// each off the wall by Gaussian noise of `sigma_m`.
std::vector<Vec2> NoisyWall(double x_m, double sigma_m, std::mt19937* rng) {
  std::normal_distribution<double> noise(0.0, sigma_m);
  std::vector<Vec2> points;
  for (double x = -3.0; x <= 3.0; x += 0.05) points.push_back({x - x_m, 1.0 + noise(*rng)});
  return points;
}

double RmsOffWall(const std::vector<Vec2>& points) {
  double sum = 0.0;
  for (const Vec2& p : points) sum += (p.y - 1.0) * (p.y - 1.0);
  return std::sqrt(sum / points.size());
}

ScanFusionOptions Neighbours(int before, int after) {
  ScanFusionOptions o;
  o.scans_before = before;
  o.scans_after = after;
  return o;
}

TEST(ScanFusion, WithoutNeighbouringScansReturnsThePointsAsGiven) {
  std::mt19937 rng(1);
  ScanFusion fusion(ScanFusionOptions{});
  EXPECT_FALSE(fusion.enabled());
  const std::vector<Vec2> points = NoisyWall(0.0, 0.02, &rng);
  const long id = fusion.Add(points, {});
  const std::vector<Vec2> fused = fusion.Fuse(id);
  ASSERT_EQ(fused.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(fused[i].x, points[i].x);
    EXPECT_EQ(fused[i].y, points[i].y);
  }
}

// Scans 4 cm apart along x (0.4 m/s at 10 Hz) of the noisy wall; scan `center`'s points fused with the rest
// are at least twice as close to the wall as they were, and moved (nearly) across it only.
void ExpectFusionHalvesTheNoise(int before, int after, int center) {
  std::mt19937 rng(2);
  ScanFusion fusion(Neighbours(before, after));
  std::vector<Vec2> own;
  for (int k = 0; k <= before + after; ++k) {
    const double x = 0.04 * k;
    std::vector<Vec2> points = NoisyWall(x, 0.02, &rng);
    if (k == center) own = points;
    EXPECT_EQ(fusion.Add(std::move(points), {x, 0.0, 0.0}), k);
  }
  EXPECT_EQ(fusion.UsableScansBefore(center), std::min(center, before));
  EXPECT_EQ(fusion.UsableScansAfter(center), std::min(before + after - center, after));
  const std::vector<Vec2> fused = fusion.Fuse(center);
  ASSERT_EQ(fused.size(), own.size());
  const double raw = RmsOffWall(own), after_fusion = RmsOffWall(fused);
  EXPECT_GT(raw, 0.015);
  EXPECT_LT(after_fusion, 0.5 * raw) << "raw " << raw << " m, fused " << after_fusion << " m";
  for (std::size_t i = 0; i < fused.size(); ++i) EXPECT_NEAR(fused[i].x, own[i].x, 0.02) << "point " << i;
}

TEST(ScanFusion, FourScansBeforeWhileDrivingAlongAWallHalveTheNoiseAcrossIt) { ExpectFusionHalvesTheNoise(4, 0, 4); }

TEST(ScanFusion, TwoScansBeforeAndTwoAfterHalveTheNoiseAcrossIt) { ExpectFusionHalvesTheNoise(2, 2, 2); }

TEST(ScanFusion, IsCompleteOnceTheScansAfterAreInOrTheRobotDroveOn) {
  ScanFusion fusion(Neighbours(0, 3));
  const long id = fusion.Add({{1.0, 1.0}}, {0.0, 0.0, 0.0});
  EXPECT_FALSE(fusion.Complete(id));
  fusion.Add({{1.0, 1.0}}, {0.1, 0.0, 0.0});
  fusion.Add({{1.0, 1.0}}, {0.2, 0.0, 0.0});
  EXPECT_FALSE(fusion.Complete(id));
  fusion.Add({{1.0, 1.0}}, {0.25, 0.0, 0.0});
  EXPECT_TRUE(fusion.Complete(id));  // three after it

  const long next = fusion.Add({{1.0, 1.0}}, {1.0, 0.0, 0.0});
  fusion.Add({{1.0, 1.0}}, {1.5, 0.0, 0.0});  // 0.5 m on: beyond max_distance_m
  EXPECT_TRUE(fusion.Complete(next));
  EXPECT_EQ(fusion.UsableScansAfter(next), 0);
}

TEST(ScanFusion, ScansBeyondTheOdometryLimitsAreNotUsed) {
  std::mt19937 rng(3);
  ScanFusion fusion(Neighbours(4, 0));
  fusion.Add(NoisyWall(0.0, 0.02, &rng), {0.0, 0.0, 0.0});
  fusion.Add(NoisyWall(0.0, 0.02, &rng), {0.0, 0.0, 0.3});  // turned 0.3 rad > max_rotation_rad
  const std::vector<Vec2> far = NoisyWall(0.5, 0.02, &rng);
  const long id = fusion.Add(far, {0.5, 0.0, 0.0});  // 0.5 m > max_distance_m from both
  EXPECT_EQ(fusion.UsableScansBefore(id), 0);
  const std::vector<Vec2> fused = fusion.Fuse(id);
  ASSERT_EQ(fused.size(), far.size());
  for (std::size_t i = 0; i < far.size(); ++i) EXPECT_EQ(fused[i].y, far[i].y) << "point " << i;
}

TEST(ScanFusion, NoiseFreeWallsStayAndACornerIsRoundedByLessThanItsNeighbourhood) {
  // Two walls meeting at (2, 1), seen five times without noise from the same place: a point whose
  // neighbourhood is one wall stays where it is; the corner's neighbourhood holds both walls, fits a line
  // badly and moves its points by at most a few centimetres.
  std::vector<Vec2> points;
  for (double x = 0.0; x < 2.0; x += 0.05) points.push_back({x, 1.0});
  for (double y = 1.0; y >= -1.0; y -= 0.05) points.push_back({2.0, y});
  ScanFusion fusion(Neighbours(4, 0));
  long id = 0;
  for (int k = 0; k < 5; ++k) id = fusion.Add(points, {});
  const std::vector<Vec2> fused = fusion.Fuse(id);
  ASSERT_EQ(fused.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double moved = Norm(fused[i] - points[i]);
    if (Norm(points[i] - Vec2{2.0, 1.0}) > 0.15) {
      EXPECT_LT(moved, 1e-9) << "point " << i;
    } else {
      EXPECT_LT(moved, 0.045) << "point " << i;
    }
  }
}

TEST(ScanFusion, PointsWhoseNeighbourhoodIsNoLineStayWhereTheyAre) {
  // Echoes 0.12 m apart across, alternating (a railing's bars, clutter): every neighbourhood scatters 6 cm
  // off its best line, above max_residual_m + max_residual_per_m × range (~4 cm here), so nothing moves.
  std::vector<Vec2> points;
  for (int i = 0; i < 40; ++i) points.push_back({-1.0 + 0.05 * i, (i % 2 == 0) ? 1.0 : 1.12});
  ScanFusion fusion(Neighbours(4, 0));
  long id = 0;
  for (int k = 0; k < 5; ++k) id = fusion.Add(points, {});
  const std::vector<Vec2> fused = fusion.Fuse(id);
  ASSERT_EQ(fused.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) EXPECT_LT(Norm(fused[i] - points[i]), 1e-9) << "point " << i;
}

TEST(ScanFusion, AScanNoLongerRememberedIsAnErrorNamingIt) {
  ScanFusion fusion(Neighbours(1, 1));
  for (int k = 0; k < 5; ++k) fusion.Add({{1.0, 1.0}}, {});
  EXPECT_THROW(fusion.Fuse(0), std::out_of_range);  // only scans 2-4 are remembered
  EXPECT_FALSE(fusion.Remembered(0));
  EXPECT_TRUE(fusion.Remembered(2));
  EXPECT_FALSE(fusion.Remembered(5));
  EXPECT_TRUE(fusion.Complete(0));
  EXPECT_NO_THROW(fusion.Fuse(3));
}

TEST(ScanFusion, RejectsOptionsOutOfRangeNamingTheField) {
  const auto expect_names = [](ScanFusionOptions o, const std::string& field) {
    try {
      ScanFusion fusion(o);
      FAIL() << "accepted bad " << field;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("ScanFusionOptions." + field), std::string::npos) << e.what();
    }
  };
  ScanFusionOptions o;
  o.scans_before = -1;
  expect_names(o, "scans_before");
  o = {};
  o.radius_m = 0.0;
  expect_names(o, "radius_m");
  o = {};
  o.min_neighbours = 2;
  expect_names(o, "min_neighbours");
  o = {};
  o.max_distance_m = -1.0;
  expect_names(o, "max_distance_m");
}

}  // namespace
}  // namespace doorplate_localization

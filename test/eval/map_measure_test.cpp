// Corridor extent and plate scoring on hand-made grids and text maps.
#include "map_measure.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

// An axis-aligned corridor drawn as occupied cell rows/columns: inner length × width, 5 cm cells,
// the corridor's inner faces at cell centres 0 .. length along x and 0 .. width along y.
OccupancyGrid DrawnCorridor(double length_m, double width_m, Pose2D origin = {-1.0, -1.0, 0.0}) {
  const double res = 0.05;
  OccupancyGrid grid(static_cast<int>((length_m + 2) / res) + 1, static_cast<int>((width_m + 2) / res) + 1, res,
                     origin, OccupancyGrid::kFree);
  const auto mark = [&](double x, double y) {
    int cx, cy;
    if (grid.WorldToCell({x, y}, &cx, &cy)) grid.At(cx, cy) = OccupancyGrid::kOccupied;
  };
  for (double x = 0; x <= length_m; x += res / 2) mark(x, 0.01), mark(x, width_m + 0.01);
  for (double y = 0; y <= width_m; y += res / 2) mark(0.01, y), mark(length_m + 0.01, y);
  return grid;
}

TEST(MeasureCorridor, ReadsLengthAndWidthOfADrawnCorridorToACell) {
  const CorridorExtent e = MeasureCorridor(DrawnCorridor(20.0, 1.85));
  ASSERT_TRUE(e.ok);
  EXPECT_NEAR(e.length_m, 20.0, 0.05);
  EXPECT_NEAR(e.width_m, 1.85, 0.05);
  EXPECT_NEAR(std::abs(e.axis.x), 1.0, 1e-3);
}

TEST(MeasureCorridor, IgnoresAFewStrayCellsBeyondTheEndWall) {
  OccupancyGrid grid = DrawnCorridor(20.0, 1.85);
  int cx, cy;
  ASSERT_TRUE(grid.WorldToCell({20.8, 0.9}, &cx, &cy));
  grid.At(cx, cy) = OccupancyGrid::kOccupied;
  const CorridorExtent e = MeasureCorridor(grid);
  EXPECT_NEAR(e.length_m, 20.0, 0.05);
}

// Walls whose surfaces lie on cell boundaries (y = 0 and 1.90 m) get mapped two cells thick, in uneven
// shares: the median of each wall's cells picks one row (the inner rows are 1.85 m apart), the mean of the
// wall's cells lies between its rows.
TEST(MeasureCorridor, PlacesAWallMappedTwoCellsThickBetweenItsCells) {
  OccupancyGrid grid(static_cast<int>(24.0 / 0.05), static_cast<int>(4.0 / 0.05), 0.05, {-2.0, -1.0, 0.0},
                     OccupancyGrid::kFree);
  const auto mark = [&](double x, double y) {
    int cx, cy;
    if (grid.WorldToCell({x, y}, &cx, &cy)) grid.At(cx, cy) = OccupancyGrid::kOccupied;
  };
  for (int i = 0; i < 400; ++i) {  // x from 0 to 20 m, one cell each
    const double x = 0.025 + 0.05 * i;
    const bool inner = i % 20 < 11;  // 55 % of the columns in the inner row
    mark(x, inner ? 0.025 : -0.025);  // south wall: cells centred 0.025 (inner) or -0.025
    mark(x, inner ? 1.875 : 1.925);   // north wall: cells centred 1.875 (inner) or 1.925
  }
  for (double y = 0.0; y <= 1.85; y += 0.05) mark(-0.05, y), mark(20.05, y);
  const CorridorExtent e = MeasureCorridor(grid);
  ASSERT_TRUE(e.ok);
  EXPECT_NEAR(e.width_m, 1.90, 0.015);
}

// The south wall mapped two cells thick along the first half only, the north wall along the second half
// only: the cells' principal axis tilts and a median of all cells would sit on the south wall. The fitted
// walls are still 1.85 m apart (inner faces at cell centres 0 and 1.85 m; outer rows 5 cm further out).
TEST(MeasureCorridor, WallsMappedThickerAtOppositeEndsKeepTheirWidth) {
  OccupancyGrid grid = DrawnCorridor(40.0, 1.85);
  const auto mark = [&](double x, double y) {
    int cx, cy;
    if (grid.WorldToCell({x, y}, &cx, &cy)) grid.At(cx, cy) = OccupancyGrid::kOccupied;
  };
  for (double x = 0.0; x <= 40.0; x += 0.025) (x < 20.0 ? mark(x, -0.04) : mark(x, 1.85 + 0.06));
  const CorridorExtent e = MeasureCorridor(grid);
  ASSERT_TRUE(e.ok);
  EXPECT_NEAR(e.width_m, 1.85 + 0.05, 0.03);
  EXPECT_NEAR(e.length_m, 40.0, 0.05);
}

TEST(MeasureCorridor, AnEmptyGridIsNotMeasured) {
  EXPECT_FALSE(MeasureCorridor(OccupancyGrid(10, 10, 0.05, {}, OccupancyGrid::kFree)).ok);
}

TEST(MeasureSegments, GivesTheRectangleOfTheWalls) {
  const CorridorExtent e = MeasureSegments({{{0, 0}, {43.5, 0}}, {{0, 1.85}, {43.5, 1.85}}, {{0, 0}, {0, 1.85}}});
  EXPECT_NEAR(e.length_m, 43.5, 1e-9);
  EXPECT_NEAR(e.width_m, 1.85, 1e-9);
}

TEST(ExtentAccuracy, IsOneMinusTheRelativeError) {
  EXPECT_NEAR(ExtentAccuracy(32.11, 43.5), 0.7382, 1e-4);  // paper Table II, gmapping
  EXPECT_NEAR(ExtentAccuracy(44.0, 40.0), 0.9, 1e-12);
  EXPECT_EQ(ExtentAccuracy(1.0, 0.0), 0.0);
}

TextLandmark Plate(const std::string& text, double x, double y) {
  TextLandmark l;
  l.text = text;
  l.pose = {x, y, 0.0};
  return l;
}

TEST(MeasureOutLeg, ComparesTheEstimatedAndTrueDistanceFromTheStartToTheFarthestTruePose) {
  // Out 40 m along x and back to 2 m; the estimate shrank the out leg by 10 % and came back "past" its start.
  std::vector<Pose2D> truth, estimated;
  for (double x = 0.0; x <= 40.0; x += 1.0) truth.push_back({x, 0, 0}), estimated.push_back({0.9 * x, 0.1, 0});
  for (double x = 39.0; x >= 2.0; x -= 1.0) truth.push_back({x, 1, M_PI}), estimated.push_back({x - 5.0, 1, M_PI});
  const OutLeg leg = MeasureOutLeg(estimated, truth);
  EXPECT_EQ(leg.turn_index, 40);
  EXPECT_NEAR(leg.true_m, 40.0, 1e-9);
  EXPECT_NEAR(leg.estimated_m, std::hypot(36.0, 0.0), 1e-9);
  EXPECT_NEAR(leg.accuracy, 0.9, 1e-9);
}

TEST(MeasureOutLeg, IsEmptyWithFewerThanTwoPoses) {
  EXPECT_EQ(MeasureOutLeg({{1, 2, 0}}, {{1, 2, 0}}).turn_index, -1);
  EXPECT_EQ(MeasureOutLeg({}, {}).accuracy, 0.0);
}

TEST(ScorePlates, MatchesSameTextNearestFirstThroughTheMapPose) {
  TextMap truth, mapped;
  truth.landmarks = {Plate("201", 2, 0), Plate("202", 2, 2), Plate("203", 6, 0)};
  // Map frame = world shifted by (1, 0): the world's (2, 0) is the map's (1, 0).
  mapped.landmarks = {Plate("201", 1.1, 0), Plate("202", 1.0, 2.0), Plate("203", 9, 0), Plate("209", 1, 0)};
  const PlateScore s = ScorePlates(mapped, truth, {1.0, 0.0, 0.0});
  EXPECT_EQ(s.plates_true, 3);
  EXPECT_EQ(s.plates_in_map, 4);
  EXPECT_EQ(s.plates_mapped, 2);  // 203 is 4 m off, 209 does not exist
  EXPECT_NEAR(s.errors_m[0], 0.1, 1e-9);
  EXPECT_NEAR(s.errors_m[1], 0.0, 1e-9);
  EXPECT_EQ(s.errors_m[2], -1.0);
  EXPECT_NEAR(s.rmse_m, std::sqrt(0.01 / 2), 1e-9);
  EXPECT_NEAR(s.max_error_m, 0.1, 1e-9);
}

TEST(ScorePlates, ARepeatedTextMatchesEachTruePlateOnce) {
  TextMap truth, mapped;
  truth.landmarks = {Plate("220", 0, 0), Plate("220", 0, 2)};
  mapped.landmarks = {Plate("220", 0, 0.1), Plate("220", 0, 0.2)};
  const PlateScore s = ScorePlates(mapped, truth, {});
  EXPECT_EQ(s.plates_mapped, 1);  // the second one is 1.8 m from the other 220
  EXPECT_NEAR(s.errors_m[0], 0.1, 1e-9);
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/slam/tiled_grid.h"

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

TiledGridOptions Options() {
  TiledGridOptions o;
  o.resolution_m = 0.1;
  o.distance_field_radius_m = 0.3;  // 3 cells
  return o;
}

TEST(TiledGrid, UnwrittenCellsAreUnknownWithNoObstacleNear) {
  const TiledGrid grid(Options());
  EXPECT_FALSE(grid.Observed({5, -7}));
  EXPECT_EQ(grid.LogOdds({5, -7}), 0.0);
  EXPECT_EQ(grid.Dist2Cells({5, -7}), TiledGrid::kFar);
  EXPECT_EQ(grid.TileCount(), 0u);
}

TEST(TiledGrid, CellsCoverHalfOpenSquaresAlsoAtNegativeCoordinates) {
  const TiledGrid grid(Options());
  EXPECT_EQ(grid.CellOf({0.0, 0.0}).x, 0);
  EXPECT_EQ(grid.CellOf({-0.01, 0.0}).x, -1);
  EXPECT_EQ(grid.CellOf({0.0, -0.1}).y, -1);
  EXPECT_NEAR(grid.CellCenter({-1, 2}).x, -0.05, 1e-12);
}

TEST(TiledGrid, LogOddsAddUpAndAreClamped) {
  TiledGrid grid(Options());
  grid.UpdateCell({3, 4}, 0.9);
  grid.UpdateCell({3, 4}, -0.4);
  EXPECT_NEAR(grid.LogOdds({3, 4}), 0.5, 1e-3);
  for (int i = 0; i < 20; ++i) grid.UpdateCell({3, 4}, 0.9);
  EXPECT_NEAR(grid.LogOdds({3, 4}), Options().max_log_odds, 1e-3);
  for (int i = 0; i < 40; ++i) grid.UpdateCell({3, 4}, -0.4);
  EXPECT_NEAR(grid.LogOdds({3, 4}), Options().min_log_odds, 1e-3);
}

TEST(TiledGrid, ABeamFreesTheCellsItCrossesAndMarksItsEnd) {
  TiledGrid grid(Options());
  grid.IntegrateBeam({0.05, 0.05}, {1.05, 0.05}, true);  // cells 0..10 along x
  for (int x = 0; x < 10; ++x) EXPECT_LT(grid.LogOdds({x, 0}), 0.0) << x;
  EXPECT_GT(grid.LogOdds({10, 0}), 0.0);
  EXPECT_FALSE(grid.Observed({11, 0}));
  grid.IntegrateBeam({0.05, 0.15}, {1.05, 0.15}, false);  // no echo: the end is free too
  EXPECT_LT(grid.LogOdds({10, 1}), 0.0);
}

TEST(TiledGrid, ABeamWithoutEchoStopsBeforeTheFirstObstacleAndLeavesItAlone) {
  TiledGrid grid(Options());
  grid.UpdateCell({5, 0}, 0.9);  // an obstacle 5 cells out
  const double wall = grid.LogOdds({5, 0});
  grid.IntegrateNoReturnBeam({0.05, 0.05}, {1.05, 0.05});
  for (int x = 0; x < 5; ++x) EXPECT_LT(grid.LogOdds({x, 0}), 0.0) << x;
  EXPECT_EQ(grid.LogOdds({5, 0}), wall);
  EXPECT_TRUE(grid.IsObstacle({5, 0}));
  for (int x = 6; x <= 10; ++x) EXPECT_FALSE(grid.Observed({x, 0})) << x;
  grid.IntegrateNoReturnBeam({0.05, 0.15}, {1.05, 0.15});  // nothing known in the way: clears to the end
  for (int x = 0; x <= 10; ++x) EXPECT_LT(grid.LogOdds({x, 1}), 0.0) << x;
}

TEST(TiledGrid, ABeamWithoutEchoDoesNotSlipDiagonallyThroughAStaircaseWall) {
  TiledGrid grid(Options());
  grid.UpdateCell({2, 1}, 0.9);  // a wall along the anti-diagonal: (2, 1) and (1, 2) touch at a corner
  grid.UpdateCell({1, 2}, 0.9);
  grid.IntegrateNoReturnBeam({0.05, 0.05}, {0.55, 0.55});  // the diagonal through cells (k, k)
  EXPECT_LT(grid.LogOdds({1, 1}), 0.0);
  for (int k = 2; k <= 5; ++k) EXPECT_FALSE(grid.Observed({k, k})) << k;
  grid.IntegrateBeam({0.05, 0.05}, {0.55, 0.55}, true);  // an echo beyond it is evidence: it passes
  EXPECT_GT(grid.LogOdds({5, 5}), 0.0);
}

TEST(TiledGrid, DistanceFieldHoldsSquaredCellDistancesToTheNearestObstacle) {
  TiledGrid grid(Options());
  grid.UpdateCell({0, 0}, 0.9);  // above occupied_log_odds (0.5): an obstacle
  EXPECT_TRUE(grid.IsObstacle({0, 0}));
  EXPECT_EQ(grid.Dist2Cells({0, 0}), 0);
  EXPECT_EQ(grid.Dist2Cells({2, 1}), 5);
  EXPECT_EQ(grid.Dist2Cells({-3, 0}), 9);
  EXPECT_EQ(grid.Dist2Cells({3, 1}), TiledGrid::kFar);  // beyond the 3-cell radius
  grid.UpdateCell({2, 0}, 0.9);
  EXPECT_EQ(grid.Dist2Cells({2, 1}), 1);
}

TEST(TiledGrid, ClearedObstaclesLeaveTheFieldWithHysteresis) {
  TiledGrid grid(Options());
  grid.UpdateCell({0, 0}, 0.9);
  grid.UpdateCell({3, 0}, 0.9);
  grid.UpdateCell({0, 0}, -0.4);  // 0.5: no longer above "occupied" but not below "cleared"
  EXPECT_TRUE(grid.IsObstacle({0, 0}));
  grid.UpdateCell({0, 0}, -0.4);
  grid.UpdateCell({0, 0}, -0.4);  // -0.3
  grid.UpdateCell({0, 0}, -0.4);  // -0.7 < cleared_log_odds
  EXPECT_FALSE(grid.IsObstacle({0, 0}));
  EXPECT_EQ(grid.Dist2Cells({0, 0}), 9);    // now nearest to (3, 0)
  EXPECT_EQ(grid.Dist2Cells({-1, 0}), TiledGrid::kFar);
  EXPECT_EQ(grid.Dist2Cells({1, 0}), 4);
}

TEST(TiledGrid, ACopySharesTilesUntilItWritesThenClonesOnlyThatTile) {
  TiledGrid original(Options());
  original.UpdateCell({0, 0}, 0.9);
  original.UpdateCell({100, 0}, 0.9);  // another tile, far away
  TiledGrid copy = original;
  EXPECT_TRUE(copy.SharesTileWith(original, {0, 0}));
  EXPECT_TRUE(copy.SharesTileWith(original, {100, 0}));

  copy.UpdateCell({100, 1}, -0.4);
  EXPECT_FALSE(copy.SharesTileWith(original, {100, 0}));  // cloned on write
  EXPECT_TRUE(copy.SharesTileWith(original, {0, 0}));     // untouched tile still shared
  EXPECT_FALSE(original.Observed({100, 1}));              // the original did not change
  EXPECT_TRUE(copy.Observed({100, 1}));
  EXPECT_NEAR(copy.LogOdds({100, 0}), original.LogOdds({100, 0}), 1e-9);

  std::unordered_set<const TiledGrid::Tile*> tiles;
  original.CollectTiles(&tiles);
  copy.CollectTiles(&tiles);
  EXPECT_EQ(tiles.size(), original.TileCount() + 1);  // one clone
}

TEST(TiledGrid, ExportsObservedCellsAsOccupancyValues) {
  TiledGrid grid(Options());
  grid.IntegrateBeam({0.05, 0.05}, {0.55, 0.05}, true);
  const OccupancyGrid out = grid.ToOccupancyGrid(0.3);
  int x = -1, y = -1;
  ASSERT_TRUE(out.WorldToCell({0.55, 0.05}, &x, &y));
  EXPECT_EQ(out.At(x, y), OccupancyGrid::kOccupied);
  ASSERT_TRUE(out.WorldToCell({0.25, 0.05}, &x, &y));
  EXPECT_EQ(out.At(x, y), OccupancyGrid::kFree);
  ASSERT_TRUE(out.WorldToCell({0.25, 1.05}, &x, &y));
  EXPECT_EQ(out.At(x, y), OccupancyGrid::kUnknown);
  EXPECT_NEAR(out.resolution_m, 0.1, 1e-12);
}

TEST(TiledGrid, RejectsAFieldRadiusItCannotStore) {
  TiledGridOptions o = Options();
  o.distance_field_radius_m = 2.0;  // 20 cells: squared distances would not fit a byte
  EXPECT_THROW(TiledGrid{o}, std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

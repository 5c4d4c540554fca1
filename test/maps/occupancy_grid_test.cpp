#include "doorplate_localization/maps/occupancy_grid.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

TEST(OccupancyGrid, ConstructorFillsEveryCell) {
  const OccupancyGrid grid(4, 3, 0.1, {}, OccupancyGrid::kFree);
  EXPECT_EQ(grid.cells.size(), 12u);
  for (std::int8_t c : grid.cells) EXPECT_EQ(c, OccupancyGrid::kFree);
  EXPECT_NEAR(grid.WidthM(), 0.4, 1e-12);
  EXPECT_NEAR(grid.HeightM(), 0.3, 1e-12);
}

TEST(OccupancyGrid, RowsGoUpInYAndIndexRowMajor) {
  OccupancyGrid grid(4, 3, 0.1, {});
  grid.At(1, 2) = OccupancyGrid::kOccupied;
  EXPECT_EQ(grid.cells[2 * 4 + 1], OccupancyGrid::kOccupied);
  EXPECT_NEAR(grid.CellCenter(1, 2).y, 0.25, 1e-12);
}

TEST(OccupancyGrid, CellCenterIsHalfACellFromTheOriginCorner) {
  const OccupancyGrid grid(10, 10, 0.05, {1.0, -2.0, 0.0});
  const Vec2 c = grid.CellCenter(0, 0);
  EXPECT_NEAR(c.x, 1.025, 1e-12);
  EXPECT_NEAR(c.y, -1.975, 1e-12);
}

TEST(OccupancyGrid, WorldToCellInvertsCellCenterWithARotatedOrigin) {
  const OccupancyGrid grid(20, 10, 0.1, {2.0, 1.0, 0.7});
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      int cx = -1, cy = -1;
      ASSERT_TRUE(grid.WorldToCell(grid.CellCenter(x, y), &cx, &cy));
      EXPECT_EQ(cx, x);
      EXPECT_EQ(cy, y);
    }
  }
}

TEST(OccupancyGrid, WorldToCellRejectsOutsidePointsAndNanWithoutTouchingOutputs) {
  const OccupancyGrid grid(10, 10, 0.1, {});
  int x = 7, y = 8;
  EXPECT_FALSE(grid.WorldToCell({-0.01, 0.5}, &x, &y));
  EXPECT_FALSE(grid.WorldToCell({0.5, 1.0}, &x, &y));  // the upper edge belongs to no cell
  EXPECT_FALSE(grid.WorldToCell({std::numeric_limits<double>::quiet_NaN(), 0.5}, &x, &y));
  EXPECT_EQ(x, 7);
  EXPECT_EQ(y, 8);
  EXPECT_TRUE(grid.WorldToCell({0.0, 0.99}, &x, &y));
  EXPECT_EQ(x, 0);
  EXPECT_EQ(y, 9);
}

TEST(OccupancyGrid, ConstructorRejectsNonPositiveResolutionAndNegativeSize) {
  EXPECT_THROW(OccupancyGrid(2, 2, 0.0, {}), std::invalid_argument);
  EXPECT_THROW(OccupancyGrid(2, 2, std::nan(""), {}), std::invalid_argument);
  EXPECT_THROW(OccupancyGrid(-1, 2, 0.1, {}), std::invalid_argument);
}

// Issue 18: more cells than limits::kMaxMapCells is refused before the 400 MB are allocated, naming the limit.
TEST(OccupancyGrid, ConstructorRefusesMoreCellsThanTheLimitBeforeAllocating) {
  try {
    OccupancyGrid(20000, 20000, 0.05, {});
    FAIL() << "a 20000 x 20000 grid was made";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("20000 x 20000 = 4e+08 cells, more than the limit of 100000000 "
                                         "(limits::kMaxMapCells)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(OccupancyGrid(10000, 1, 0.05, {}).cells.size(), 10000u);
}

}  // namespace
}  // namespace doorplate_localization

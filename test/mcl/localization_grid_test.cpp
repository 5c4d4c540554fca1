#include "doorplate_localization/mcl/localization_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "mcl_fixtures.h"

namespace doorplate_localization {
namespace {

TEST(LocalizationGrid, ReadsCellsLikeAmclByDefault) {
  OccupancyGrid g = test::MakeGrid(0, 0, 0.2, 0.05);  // 4 × 1 cells
  g.cells = {0, 100, 50, -1};
  const LocalizationGrid grid(g);
  EXPECT_EQ(grid.State(0, 0), CellState::kFree);
  EXPECT_EQ(grid.State(1, 0), CellState::kOccupied);
  EXPECT_EQ(grid.State(2, 0), CellState::kUnknown);  // amcl: anything but 0/100 is unknown
  EXPECT_EQ(grid.State(3, 0), CellState::kUnknown);
  EXPECT_EQ(grid.free_cells(), std::vector<int>{0});
}

TEST(LocalizationGrid, ThresholdsCanAcceptProbabilisticMaps) {
  OccupancyGrid g = test::MakeGrid(0, 0, 0.2, 0.05);
  g.cells = {10, 70, 50, -1};
  LocalizationGridOptions o;
  o.free_max_value = 19;
  o.occupied_min_value = 65;
  const LocalizationGrid grid(g, o);
  EXPECT_EQ(grid.State(0, 0), CellState::kFree);
  EXPECT_EQ(grid.State(1, 0), CellState::kOccupied);
  EXPECT_EQ(grid.State(2, 0), CellState::kUnknown);
}

TEST(LocalizationGrid, CellTransformsHonourARotatedOrigin) {
  OccupancyGrid g = test::MakeGrid(0, 0, 1.0, 1.0, 0.1, 0);
  g.origin = {2.0, 1.0, M_PI / 2};  // grid x axis points along map +y
  const LocalizationGrid grid(g);
  const Vec2 c = grid.ToCellCoords({1.45, 1.35});  // 0.35 m along grid x, 0.55 m along grid y
  EXPECT_NEAR(c.x, 3.5, 1e-9);
  EXPECT_NEAR(c.y, 5.5, 1e-9);
  const Vec2 back = grid.FromCellCoords(c);
  EXPECT_NEAR(back.x, 1.45, 1e-9);
  EXPECT_NEAR(back.y, 1.35, 1e-9);
  int x = -1, y = -1;
  EXPECT_TRUE(grid.PointToCell({1.45, 1.35}, &x, &y));
  EXPECT_EQ(x, 3);
  EXPECT_EQ(y, 5);
  EXPECT_FALSE(grid.PointToCell({2.5, 1.3}, &x, &y));  // behind the origin along grid y
}

TEST(LocalizationGrid, FreePosesAreUniformOverFreeCellsOnly) {
  OccupancyGrid g = test::MakeGrid(0, 0, 4.0, 1.0, 0.1, OccupancyGrid::kOccupied);
  test::FillRect(&g, 0.0, 0.0, 1.0, 1.0, 0);  // 1 m² on the left
  test::FillRect(&g, 2.0, 0.0, 4.0, 1.0, 0);  // 2 m² on the right
  const LocalizationGrid grid(g);
  std::mt19937_64 rng(3);
  int left = 0;
  const int n = 6000;
  for (int i = 0; i < n; ++i) {
    const Pose2D p = grid.SampleFreePose(rng);
    ASSERT_TRUE(grid.IsFree(p.Position()));
    ASSERT_GT(p.theta_rad, -M_PI);
    ASSERT_LE(p.theta_rad, M_PI);
    left += p.x_m < 1.5;
  }
  EXPECT_NEAR(left / static_cast<double>(n), 1.0 / 3.0, 0.03);  // in proportion to the free area
}

TEST(LocalizationGrid, RejectsInconsistentGridsNamingTheField) {
  OccupancyGrid g = test::MakeGrid(0, 0, 1.0, 1.0);
  g.cells.pop_back();
  try {
    LocalizationGrid grid(g);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("OccupancyGrid.cells"), std::string::npos) << e.what();
  }
  g = test::MakeGrid(0, 0, 1.0, 1.0);
  g.resolution_m = 0.0;
  EXPECT_THROW(LocalizationGrid{g}, std::invalid_argument);
  const LocalizationGrid no_free(test::MakeGrid(0, 0, 1.0, 1.0, 0.1, OccupancyGrid::kOccupied));
  std::mt19937_64 rng(1);
  EXPECT_THROW(no_free.SampleFreePose(rng), std::logic_error);
  EXPECT_EQ(NoFreeCellProblem(no_free), "no free cell: all 100 cells are occupied or unknown");
  EXPECT_EQ(NoFreeCellProblem(LocalizationGrid(test::MakeGrid(0, 0, 1.0, 1.0, 0.1, OccupancyGrid::kFree))), "");
}

// What the error says, or "" when the grid is accepted.
std::string ProblemOf(const OccupancyGrid& g) {
  try {
    LocalizationGrid grid(g);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// Issue 18: common/limits.h's bounds on resolution and origin, naming the field and the limit.
TEST(LocalizationGrid, RejectsAResolutionOrOriginOutsideTheLimits) {
  OccupancyGrid g = test::MakeGrid(0, 0, 1.0, 1.0);
  g.resolution_m = 1e-5;
  EXPECT_NE(ProblemOf(g).find("OccupancyGrid.resolution_m: must be finite and in [0.001, 100] m"), std::string::npos)
      << ProblemOf(g);
  g = test::MakeGrid(0, 0, 1.0, 1.0);
  g.origin.x_m = 1e300;
  EXPECT_NE(ProblemOf(g).find("OccupancyGrid.origin.x_m: must be finite and within +-1e+06 m (limits::kMaxCoordinateM)"),
            std::string::npos)
      << ProblemOf(g);
  g.origin.x_m = -9e5;  // far, but within the bound
  EXPECT_EQ(ProblemOf(g), "");
  g.origin.theta_rad = std::nan("");
  EXPECT_NE(ProblemOf(g).find("OccupancyGrid.origin.theta_rad: must be finite"), std::string::npos);
  // A grid claiming more cells than the limit (its cells are never allocated: they do not match anyway).
  g = test::MakeGrid(0, 0, 1.0, 1.0);
  g.width = g.height = 20000;
  EXPECT_NE(ProblemOf(g).find("OccupancyGrid.width/height: 20000 x 20000 = 4e+08 cells, more than the limit"),
            std::string::npos)
      << ProblemOf(g);
}

}  // namespace
}  // namespace doorplate_localization

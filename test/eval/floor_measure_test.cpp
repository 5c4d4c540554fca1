// Per-corridor length and width on hand-drawn grids, in rotated and shifted frames, and on the ring world.
#include "floor_measure.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/world_loader.h"
#include "eval_test_worlds.h"

namespace doorplate_localization {
namespace {

constexpr double kRes = 0.05;

// A grid covering [x0, x1] × [y0, y1] in its own axes, placed in its map frame by `frame`: cell (i, j) has its
// centre at frame ⊕ (x0 + i·5 cm, y0 + j·5 cm), so walls drawn at multiples of 5 cm are cell centres and a ray
// from inside stops half a cell (2.5 cm) before them.
struct DrawnGrid {
  OccupancyGrid grid;
  DrawnGrid(double x0, double y0, double x1, double y1, Pose2D frame = {}, std::int8_t fill = OccupancyGrid::kFree)
      : grid(static_cast<int>(std::lround((x1 - x0) / kRes)) + 1, static_cast<int>(std::lround((y1 - y0) / kRes)) + 1,
             kRes, frame.Compose({x0 - kRes / 2, y0 - kRes / 2, 0.0}), fill),
        x0_(x0), y0_(y0) {}
  // Sets the cells of the box from (ax, ay) to (bx, by) in the grid's own axes (a line when it is flat).
  void Line(double ax, double ay, double bx, double by, std::int8_t value = OccupancyGrid::kOccupied) {
    const int i0 = Cell(std::min(ax, bx), x0_), i1 = Cell(std::max(ax, bx), x0_);
    const int j0 = Cell(std::min(ay, by), y0_), j1 = Cell(std::max(ay, by), y0_);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) grid.At(i, j) = value;
    }
  }
  // A closed corridor x in [0, length], y in [0, width] (walls on those lines).
  void Corridor(double length_m, double width_m) {
    Line(0, 0, length_m, 0), Line(0, width_m, length_m, width_m);
    Line(0, 0, 0, width_m), Line(length_m, 0, length_m, width_m);
  }

 private:
  static int Cell(double v, double v0) { return static_cast<int>(std::lround((v - v0) / kRes)); }
  double x0_, y0_;
};

CorridorSpec Spec(const std::string& id, Vec2 a, Vec2 b, double width_m) { return {id, {a, b}, width_m}; }

TEST(MeasureCorridors, ReadsLengthAndWidthBetweenTheWallsNearFaces) {
  DrawnGrid g(-1, -1, 11, 3);
  g.Corridor(10.0, 2.0);
  const auto m = MeasureCorridors(g.grid, {Spec("c", {1, 1}, {9, 1}, 2.0)}, Pose2D{});
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].id, "c");
  EXPECT_TRUE(m[0].ok);
  EXPECT_NEAR(m[0].length_m, 10.0 - kRes, 1e-9);
  EXPECT_NEAR(m[0].width_m, 2.0 - kRes, 1e-9);
  EXPECT_EQ(m[0].cross_sections, 32);  // 8 m in 0.25 m pieces
  EXPECT_EQ(m[0].cross_sections_used, 32);
}

// An open door with a room behind it and a side corridor: their cross-sections run on and are skipped.
TEST(MeasureCorridors, SkipsCrossSectionsThroughOpenDoorsAndJunctions) {
  DrawnGrid g(-1, -7, 11, 6);
  g.Corridor(10.0, 2.0);
  g.Line(3, 2, 4, 2, OccupancyGrid::kFree);  // a door gap into a 3 m deep room
  g.Line(2, 2, 2, 5), g.Line(2, 5, 5, 5), g.Line(5, 5, 5, 2);
  g.Line(6, 0, 8, 0, OccupancyGrid::kFree);  // a side corridor 2 m wide running 6 m south
  g.Line(6, 0, 6, -6), g.Line(8, 0, 8, -6), g.Line(6, -6, 8, -6);
  const auto m = MeasureCorridors(g.grid, {Spec("c", {0, 1}, {10, 1}, 2.0)}, Pose2D{});
  ASSERT_TRUE(m[0].ok);
  EXPECT_NEAR(m[0].width_m, 2.0 - kRes, 1e-9);
  EXPECT_NEAR(m[0].length_m, 10.0 - kRes, 1e-9);
  EXPECT_EQ(m[0].cross_sections, 40);
  EXPECT_EQ(m[0].cross_sections_used, 40 - 4 - 8);  // 1 m of door, 2 m of junction
}

// The corridor drawn in grid axes; the world sees the grid rotated and shifted (world_from_grid), or the
// grid's own origin is rotated: either way the centreline given in the world frame is measured the same.
TEST(MeasureCorridors, MeasuresInTheWorldFrameThroughWorldFromGridAndARotatedOrigin) {
  DrawnGrid shifted(-1, -1, 11, 3);
  shifted.Corridor(10.0, 2.0);
  const Pose2D world_from_grid{5.0, -3.0, 0.7};
  const CorridorSpec spec =
      Spec("c", world_from_grid.TransformPoint({1, 1}), world_from_grid.TransformPoint({9, 1}), 2.0);
  const auto a = MeasureCorridors(shifted.grid, {spec}, world_from_grid);
  ASSERT_TRUE(a[0].ok);
  EXPECT_NEAR(a[0].length_m, 10.0 - kRes, 1e-6);
  EXPECT_NEAR(a[0].width_m, 2.0 - kRes, 1e-6);
  EXPECT_GT(std::abs(MeasureCorridors(shifted.grid, {spec}, Pose2D{})[0].length_m - 10.0), 1.0);  // unaligned

  const Pose2D origin_yaw{-2.0, 4.0, -1.1};
  DrawnGrid rotated(-1, -1, 11, 3, origin_yaw);
  rotated.Corridor(10.0, 2.0);
  const auto b = MeasureCorridors(
      rotated.grid, {Spec("c", origin_yaw.TransformPoint({9, 1}), origin_yaw.TransformPoint({1, 1}), 2.0)}, Pose2D{});
  ASSERT_TRUE(b[0].ok);
  EXPECT_NEAR(b[0].length_m, 10.0 - kRes, 1e-6);
  EXPECT_NEAR(b[0].width_m, 2.0 - kRes, 1e-6);
}

// Without an end wall the ray runs through unknown cells out of the grid: no length unless unknown blocks.
TEST(MeasureCorridors, AnOpenEndIsNotALengthUnlessUnknownCellsBlock) {
  DrawnGrid g(-1, -1, 14, 3, Pose2D{}, OccupancyGrid::kUnknown);
  g.Line(0, 0, 10, 2, OccupancyGrid::kFree);
  g.Line(0, 0, 10, 0), g.Line(0, 2, 10, 2), g.Line(0, 0, 0, 2);
  const auto m = MeasureCorridors(g.grid, {Spec("c", {1, 1}, {9, 1}, 2.0)}, Pose2D{});
  EXPECT_FALSE(m[0].ok);
  EXPECT_DOUBLE_EQ(m[0].length_m, 0.0);
  EXPECT_NEAR(m[0].width_m, 2.0 - kRes, 1e-9);  // the walls are still there
  CorridorMeasureOptions blocking;
  blocking.unknown_blocks = true;
  const auto b = MeasureCorridors(g.grid, {Spec("c", {1, 1}, {9, 1}, 2.0)}, Pose2D{}, blocking);
  EXPECT_TRUE(b[0].ok);
  EXPECT_NEAR(b[0].length_m, 10.0, 1e-9);  // to the first unknown cell, x = 10.05 (near face 10.025)
}

TEST(MeasureCorridors, ALengthRayThroughAnUnmappedGapIsNotMeasured) {
  // A closed 10 m corridor whose east end wall has a 0.3 m unknown gap on the centreline, with a wall
  // 20 m further east behind it: the ray would reach that wall through the gap. The length is not measured
  // rather than measured as 30 m; an unknown cell just before a wall's face is tolerated.
  DrawnGrid g(-1, -1, 32, 3, Pose2D{}, OccupancyGrid::kUnknown);
  g.Line(0, 0, 10, 2, OccupancyGrid::kFree);
  g.Corridor(10.0, 2.0);
  g.Line(10, 0.85, 10, 1.15, OccupancyGrid::kUnknown);
  g.Line(30, 0, 30, 2);
  const auto m = MeasureCorridors(g.grid, {Spec("c", {1, 1}, {9, 1}, 2.0)}, Pose2D{});
  EXPECT_FALSE(m[0].ok);
  EXPECT_DOUBLE_EQ(m[0].length_m, 0.0);
  g.Line(10, 0.85, 10, 1.15);  // the wall mapped, an unobserved cell at its face: measured again
  g.Line(9.95, 1.0, 9.95, 1.0, OccupancyGrid::kUnknown);
  const auto closed = MeasureCorridors(g.grid, {Spec("c", {1, 1}, {9, 1}, 2.0)}, Pose2D{});
  EXPECT_TRUE(closed[0].ok);
  EXPECT_NEAR(closed[0].length_m, 10.0 - kRes, 1e-9);
}

TEST(MeasureCorridors, RejectsBadOptions) {
  DrawnGrid g(-1, -1, 11, 3);
  CorridorMeasureOptions bad;
  bad.section_step_m = 0.0;
  EXPECT_THROW(MeasureCorridors(g.grid, {}, Pose2D{}, bad), std::invalid_argument);
  EXPECT_THROW(MeasureCorridors(OccupancyGrid(), {}, Pose2D{}), std::invalid_argument);
}

TEST(CompareCorridors, GivesAccuraciesAgainstTheTruthGrid) {
  DrawnGrid truth(-1, -1, 12, 3), mapped(-1, -1, 12, 3);
  truth.Corridor(10.0, 2.0);
  mapped.Corridor(10.5, 2.2);  // 5 % long, 10 % wide
  const std::vector<CorridorSpec> specs = {Spec("c", {1, 1}, {9, 1}, 2.0)};
  const auto acc = CompareCorridors(mapped.grid, Pose2D{}, truth.grid, specs);
  ASSERT_EQ(acc.size(), 1u);
  ASSERT_TRUE(acc[0].ok);
  EXPECT_NEAR(acc[0].length_accuracy, 1.0 - 0.5 / (10.0 - kRes), 1e-9);
  EXPECT_NEAR(acc[0].width_accuracy, 1.0 - 0.2 / (2.0 - kRes), 1e-9);
  EXPECT_NEAR(acc[0].truth.length_m, 10.0 - kRes, 1e-9);
}

TEST(CompareCorridorsWithWorld, RasterizesTheWorldAtTheMapsResolution) {
  World world = test::RectangleCorridor(10.0, 2.0);
  world.corridors = {Spec("main", {0, 1}, {10, 1}, 2.0)};
  const OccupancyGrid truth = RasterizeWorld(world, kRes, world.sensors.laser.mount_height_m);
  const auto acc = CompareCorridorsWithWorld(truth, Pose2D{}, world);
  ASSERT_EQ(acc.size(), 1u);
  EXPECT_TRUE(acc[0].ok);
  EXPECT_DOUBLE_EQ(acc[0].length_accuracy, 1.0);
  EXPECT_DOUBLE_EQ(acc[0].width_accuracy, 1.0);
  world.corridors.clear();
  EXPECT_TRUE(CompareCorridorsWithWorld(truth, Pose2D{}, world).empty());
}

// Issue 17's floor on its own ground truth: every corridor measured, the walls' near faces 2.5 cm inside.
TEST(MeasureCorridors, TheHospitalFloorRingMeasuresAsBuiltOnItsGroundTruth) {
  const World world = LoadWorldFile(std::string(DOORPLATE_SOURCE_DIR) + "/worlds/hospital_floor_ring.yaml");
  const OccupancyGrid grid = RasterizeWorld(world, kRes, world.sensors.laser.mount_height_m);
  const auto m = MeasureCorridors(grid, world.corridors, Pose2D{});
  ASSERT_EQ(m.size(), world.corridors.size());
  for (std::size_t i = 0; i < m.size(); ++i) {
    std::cout << m[i].id << ": length " << m[i].length_m << " m, width " << m[i].width_m << " m, "
              << m[i].cross_sections_used << "/" << m[i].cross_sections << " cross-sections\n";
    EXPECT_TRUE(m[i].ok) << m[i].id;
    EXPECT_NEAR(m[i].width_m, world.corridors[i].width_m - kRes, 1e-6) << m[i].id;
    EXPECT_GE(m[i].cross_sections_used, m[i].cross_sections / 2) << m[i].id;
  }
  EXPECT_NEAR(m[0].length_m, 42.0 - kRes, 1e-6);  // south: west to east outer wall
  EXPECT_NEAR(m[1].length_m, 26.0 - kRes, 1e-6);  // east: south to north outer wall
  EXPECT_NEAR(m[4].length_m, 14.0 - kRes, 1e-6);  // south branch: dead end to the courtyard wall
  EXPECT_NEAR(m[5].length_m, 14.0 - kRes, 1e-6);  // east branch, likewise
}

}  // namespace
}  // namespace doorplate_localization

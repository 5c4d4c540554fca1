#include "report_layout.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

TEST(KnownExtent, BoundsTheKnownCellsOnly) {
  OccupancyGrid grid(100, 40, 0.1, Pose2D{-2.0, 1.0, 0.0});
  grid.At(10, 5) = OccupancyGrid::kFree;
  grid.At(29, 14) = OccupancyGrid::kOccupied;
  const MapWindow w = KnownExtent(grid);
  EXPECT_NEAR(w.x0_m, -2.0 + 1.0, 1e-9);
  EXPECT_NEAR(w.x1_m, -2.0 + 3.0, 1e-9);
  EXPECT_NEAR(w.y0_m, 1.0 + 0.5, 1e-9);
  EXPECT_NEAR(w.y1_m, 1.0 + 1.5, 1e-9);
}

TEST(KnownExtent, IsTheWholeGridWhenNothingIsKnownAndThrowsForAnEmptyOne) {
  const MapWindow w = KnownExtent(OccupancyGrid(20, 10, 0.5, Pose2D{}));
  EXPECT_NEAR(w.WidthM(), 10.0, 1e-9);
  EXPECT_NEAR(w.HeightM(), 5.0, 1e-9);
  EXPECT_THROW(KnownExtent(OccupancyGrid()), std::invalid_argument);
}

TEST(FoldExtent, FoldsALongCorridorIntoStackedOverlappingSegments) {
  FoldOptions options;  // 1 m margin, 1 m overlap, aspect 1.5, 1600 px
  const FoldedLayout layout = FoldExtent({0.0, 0.0, 45.0, 2.0}, options);
  // 47 m x 4 m: 1 segment is 11.8:1, 2 are 24 m x 8 m = 3:1, 3 are 16.3 m x 12 m = 1.36:1 (nearest 1.5).
  ASSERT_EQ(layout.windows.size(), 3u);
  const double segment = (47.0 + 2.0) / 3.0;
  EXPECT_NEAR(layout.px_per_m, 1600.0 / segment, 1e-9);
  EXPECT_NEAR(layout.windows.front().x0_m, -1.0, 1e-9);
  EXPECT_NEAR(layout.windows.back().x1_m, 46.0, 1e-9);
  EXPECT_NEAR(layout.windows[0].x1_m - layout.windows[1].x0_m, 1.0, 1e-9);  // the overlap
  for (const MapWindow& w : layout.windows) {
    EXPECT_NEAR(w.y0_m, -1.0, 1e-9);
    EXPECT_NEAR(w.y1_m, 3.0, 1e-9);
  }
}

TEST(FoldExtent, KeepsAFloorInOneWindowAndCapsTheZoom) {
  const FoldedLayout floor = FoldExtent({0.0, 0.0, 40.0, 30.0});
  ASSERT_EQ(floor.windows.size(), 1u);
  EXPECT_NEAR(floor.px_per_m, 1600.0 / 42.0, 1e-9);
  const FoldedLayout room = FoldExtent({0.0, 0.0, 3.0, 2.0});
  ASSERT_EQ(room.windows.size(), 1u);
  EXPECT_DOUBLE_EQ(room.px_per_m, 120.0);
}

TEST(FoldExtent, RejectsBadOptionsNamingTheField) {
  FoldOptions options;
  options.max_segments = 0;
  try {
    FoldExtent({0.0, 0.0, 10.0, 1.0}, options);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_segments"), std::string::npos) << e.what();
  }
  EXPECT_THROW(FoldExtent({0.0, 0.0, 0.0, 1.0}), std::invalid_argument);
}

TEST(NiceTicks, StepsByOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_EQ(NiceTicks(-1.0, 16.3, 5), (std::vector<double>{0.0, 5.0, 10.0, 15.0}));
  EXPECT_EQ(NiceTicks(0.0, 0.9, 6), (std::vector<double>{0.0, 0.2, 0.4, 0.6000000000000001, 0.8}));
  EXPECT_EQ(NiceTicks(12.0, 31.0, 3), (std::vector<double>{20.0, 30.0}));
  EXPECT_TRUE(NiceTicks(1.0, 1.0, 5).empty());
}

TEST(ArrowMagnification, IsTheLargestRoundFactorThatFits) {
  EXPECT_DOUBLE_EQ(ArrowMagnification(0.098, 1.2), 10.0);  // x10: 0.98 m; x20 would be 1.96 m
  EXPECT_DOUBLE_EQ(ArrowMagnification(0.02, 1.2), 50.0);
  EXPECT_DOUBLE_EQ(ArrowMagnification(3.0, 1.2), 1.0);
  EXPECT_DOUBLE_EQ(ArrowMagnification(1e-9, 1.2), 1000.0);
  EXPECT_DOUBLE_EQ(ArrowMagnification(0.0, 1.2), 1.0);
}

TextLandmark Plate(const std::string& text, double x, double y) {
  TextLandmark l;
  l.text = text;
  l.pose = {x, y, 0.0};
  return l;
}

TEST(PairPlates, MatchesTheNearestSameRoomWithinTheRadiusEachOnce) {
  TextMap truth, mapped;
  truth.landmarks = {Plate("201", 10.0, 0.0), Plate("203", 15.0, 0.0), Plate("205", 20.0, 0.0)};
  // The map frame is the world shifted by (-10, 0): true 201 is at map (0, 0).
  mapped.landmarks = {Plate("203", 5.1, 0.0), Plate("201", 0.0, 0.3), Plate("201", 0.0, 0.1),
                      Plate("205", 13.0, 0.0)};  // 205 too far (3 m)
  const std::vector<PlateErrorRow> rows = PairPlates(mapped, truth, Pose2D{-10.0, 0.0, 0.0});
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].text, "201");
  EXPECT_TRUE(rows[0].mapped);
  EXPECT_NEAR(rows[0].error_m, 0.1, 1e-9);  // the nearer of the two 201s
  EXPECT_NEAR(rows[0].truth.x, 0.0, 1e-9);
  EXPECT_NEAR(rows[0].estimate.y, 0.1, 1e-9);
  EXPECT_TRUE(rows[1].mapped);
  EXPECT_NEAR(rows[1].error_m, 0.1, 1e-9);
  EXPECT_FALSE(rows[2].mapped);
  EXPECT_EQ(rows[2].error_m, -1.0);
}

std::string WriteFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(ReadSpreadLog, ReadsRowsSortedByTimeAndInterpolatesTheDistance) {
  const std::string path = WriteFile("spread.csv",
                                     "sim_time_s,driven_m,spread_m,particles,plates_read\n"
                                     "12.0,4.0,0.2,500,1\n10.0,2.0,11.5,5000,0\n");
  const std::vector<SpreadSample> s = ReadSpreadLog(path);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s[0].sim_time_s, 10.0);
  EXPECT_DOUBLE_EQ(s[0].spread_m, 11.5);
  EXPECT_EQ(s[0].particles, 5000);
  EXPECT_EQ(s[1].plates_read, 1);
  EXPECT_DOUBLE_EQ(DrivenAt(s, 11.0), 3.0);
  EXPECT_DOUBLE_EQ(DrivenAt(s, 5.0), 2.0);
  EXPECT_DOUBLE_EQ(DrivenAt(s, 20.0), 4.0);
}

TEST(ReadSpreadLog, NamesTheFileAndLineOfABadRow) {
  const std::string path = WriteFile("bad_spread.csv",
                                     "sim_time_s,driven_m,spread_m,particles,plates_read\n1,2,3,4,5\n1,2,x,4,5\n");
  try {
    ReadSpreadLog(path);
    FAIL() << "no throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": line 3"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ReadSpreadLog(WriteFile("no_header.csv", "1,2,3,4,5\n")), std::runtime_error);
  EXPECT_THROW(ReadSpreadLog(::testing::TempDir() + "/missing.csv"), std::runtime_error);
}

}  // namespace
}  // namespace doorplate_localization

#include "map_overlay.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace doorplate_localization {
namespace {

// A 4 m x 2 m grid at 0.1 m, free inside, occupied on its border row/column.
OccupancyGrid SmallGrid() {
  OccupancyGrid g;
  g.resolution_m = 0.1;
  g.origin = {-1.0, -1.0, 0.0};
  g.width = 40;
  g.height = 20;
  g.cells.assign(static_cast<size_t>(g.width) * g.height, OccupancyGrid::kFree);
  for (int x = 0; x < g.width; ++x) g.cells[x] = OccupancyGrid::kOccupied;  // row y = 0: the bottom edge
  g.cells[static_cast<size_t>(g.height - 1) * g.width] = OccupancyGrid::kUnknown;  // top-left cell
  return g;
}

TEST(DrawMapOverlayTest, DrawsCellsWithYUpAndScalesThem) {
  const cv::Mat image = DrawMapOverlay(SmallGrid(), MapOverlay(), 3);
  ASSERT_EQ(image.cols, 120);
  ASSERT_EQ(image.rows, 60);
  EXPECT_EQ(image.at<cv::Vec3b>(59, 10), cv::Vec3b(0, 0, 0));        // occupied bottom row, at the bottom
  EXPECT_EQ(image.at<cv::Vec3b>(1, 1), cv::Vec3b(205, 205, 205));   // unknown top-left cell
  EXPECT_EQ(image.at<cv::Vec3b>(30, 60), cv::Vec3b(254, 254, 254)); // free
}

TEST(DrawMapOverlayTest, DrawsPathsAndMarksAtTheirMapPositions) {
  MapOverlay overlay;
  overlay.paths.push_back({{{-0.5, 0.0}, {2.5, 0.0}}, cv::Scalar(255, 0, 0), 1});  // y = 0: pixel row 30 at scale 3
  overlay.marks.push_back({{2.0, 0.5}, "", cv::Scalar(0, 0, 255), false, false});
  const cv::Mat image = DrawMapOverlay(SmallGrid(), overlay, 3);
  const cv::Vec3b on_path = image.at<cv::Vec3b>(30, 45);
  EXPECT_GT(on_path[0], 200);
  EXPECT_LT(on_path[2], 100);
  EXPECT_EQ(image.at<cv::Vec3b>(36, 45), cv::Vec3b(254, 254, 254));  // two cells off the path: still free
  // The circle of radius 5 px around (2.0, 0.5) m -> pixel (90, 15): its rightmost point is red.
  const cv::Vec3b right = image.at<cv::Vec3b>(15, 95);
  EXPECT_GT(right[2], 150);
  EXPECT_LT(right[0], 100);
}

TEST(DrawMapOverlayTest, RejectsAnEmptyGridAndABadScale) {
  EXPECT_THROW(DrawMapOverlay(OccupancyGrid(), MapOverlay()), std::invalid_argument);
  EXPECT_THROW(DrawMapOverlay(SmallGrid(), MapOverlay(), 0), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

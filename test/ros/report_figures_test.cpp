#include "report_figures.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace doorplate_localization {
namespace {

// A 40 m x 2 m corridor: free inside, walls along both sides, unknown round it.
OccupancyGrid Corridor() {
  OccupancyGrid grid(440, 60, 0.1, Pose2D{-2.0, -1.0, 0.0});
  for (int x = 20; x < 420; ++x) {
    for (int y = 20; y <= 40; ++y) grid.At(x, y) = (y == 20 || y == 40) ? OccupancyGrid::kOccupied : OccupancyGrid::kFree;
  }
  return grid;
}

int CountColour(const cv::Mat& image, const cv::Vec3b& colour) {
  int n = 0;
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) n += image.at<cv::Vec3b>(y, x) == colour;
  }
  return n;
}

TEST(DrawMapFigure, FoldsALongCorridorIntoSegmentsOfTheRequestedWidth) {
  MapFigure figure;
  figure.title = "test";
  const cv::Mat image = DrawMapFigure(Corridor(), figure);
  EXPECT_EQ(image.cols, 1600);
  // 42 m x 4 m folds into 3 segments of ~14.7 m x 4 m at ~109 px/m: ~436 px each, plus title and legend.
  EXPECT_GT(image.rows, 3 * 400);
  EXPECT_LT(image.rows, 3 * 480 + 200);
}

TEST(DrawMapFigure, DrawsAPlateErrorAsAMagnifiedArrow) {
  MapFigure figure;
  PlateErrorRow row;
  row.text = "207";
  row.truth = {10.0, 1.0};
  row.mapped = true;
  row.estimate = {10.1, 1.0};  // 10 cm: drawn x10 = 1 m = ~109 px long
  row.error_m = 0.1;
  figure.plates = {row};
  const cv::Mat with = DrawMapFigure(Corridor(), figure);
  figure.plates[0].estimate = figure.plates[0].truth;
  figure.plates[0].error_m = 0.0;
  const cv::Mat without = DrawMapFigure(Corridor(), figure);
  const cv::Vec3b arrow(0, 110, 255);
  EXPECT_GT(CountColour(with, arrow), CountColour(without, arrow) + 150);  // a ~109 px shaft, 2 px wide
}

TEST(DrawPlateErrorChart, HasOneSlotPerPlateAndRejectsNoPlates) {
  std::vector<PlateErrorRow> rows(30);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].text = std::to_string(200 + i);
    rows[i].mapped = i != 3;
    rows[i].error_m = rows[i].mapped ? 0.01 * i : -1.0;
  }
  const cv::Mat image = DrawPlateErrorChart(rows, "errors");
  EXPECT_GE(image.cols, 70 + 48 * 30);
  EXPECT_THROW(DrawPlateErrorChart({}, "none"), std::invalid_argument);
}

TEST(DrawSpreadPlot, DrawsTheCurveAndRejectsNoSamples) {
  const std::vector<SpreadSample> samples = {{0.0, 0.0, 12.0, 5000, 0}, {10.0, 4.0, 3.0, 5000, 1},
                                             {20.0, 8.0, 0.05, 300, 2}};
  const cv::Mat image = DrawSpreadPlot(samples, {{10.0, "214"}}, 20.0, "spread");
  EXPECT_GT(CountColour(image, cv::Vec3b(160, 60, 0)), 500);
  EXPECT_THROW(DrawSpreadPlot({}, {}, -1.0, "none"), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

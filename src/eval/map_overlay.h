// A picture of an occupancy grid with things drawn over it: paths, plates with their text, poses. Used by
// `doorplate_eval map` (map.png) and doorplate_mission_report. Colours are OpenCV BGR.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"

namespace doorplate_localization {

struct OverlayPath {
  std::vector<Vec2> points;      // map frame, metres
  cv::Scalar color;
  int thickness_px = 2;
};

struct OverlayMark {
  Vec2 position;                 // map frame, metres
  std::string label;             // drawn beside the mark ("" for none)
  cv::Scalar color;
  bool cross = false;            // a cross (e.g. true plates) instead of a circle (e.g. mapped plates)
  bool label_below = false;      // label under the mark (plates on the upper wall) instead of above it
};

struct MapOverlay {
  std::vector<OverlayPath> paths;
  std::vector<OverlayMark> marks;
  std::vector<Pose2D> robots;    // drawn as arrows
  std::string legend;            // one line at the top left
};

// The grid (unknown grey, free white, occupied black) scaled by `scale` (pixels per cell, >= 1), y up,
// with the overlay drawn on it. Throws std::invalid_argument for an empty grid or scale < 1.
cv::Mat DrawMapOverlay(const OccupancyGrid& grid, const MapOverlay& overlay, int scale = 4);

}  // namespace doorplate_localization

// The mission report's pictures (doorplate_mission_report, scripts/demo.sh), drawn with OpenCV:
//   DrawMapFigure     the saved map, a long corridor folded into stacked segments, with the paths, the true
//                     and mapped plates, each plate's error as a magnified arrow, a metre ruler per segment,
//                     a scale bar and a legend;
//   DrawPlateErrorChart  one bar per true plate: its position error in the text map (a gap: not mapped);
//   DrawSpreadPlot    the particles' spread (log scale) against the distance driven, with the plate readings
//                     and the moment the localizer said converged.
// Frames: map frame (the saved map's), metres. Colours are OpenCV BGR. The arithmetic is report_layout.h.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "report_layout.h"

namespace doorplate_localization {

struct FigurePath {
  std::vector<Vec2> points;  // map frame
  cv::Scalar color;
  int thickness_px = 2;
  std::string label;         // legend text
};

struct FigurePose {
  Pose2D pose;               // map frame
  cv::Scalar color;
  std::string label;         // legend text
};

struct MapFigure {
  std::string title;
  std::vector<FigurePath> paths;
  std::vector<FigurePose> poses;      // drawn as arrows
  std::vector<PlateErrorRow> plates;  // true plates (crosses), mapped ones (circles + text), error arrows
  double arrow_target_px = 110.0;     // the largest plate error is drawn at most this long (pixels)
};

// Throws std::invalid_argument for an empty grid (KnownExtent) or bad options (FoldExtent).
cv::Mat DrawMapFigure(const OccupancyGrid& grid, const MapFigure& figure, const FoldOptions& options = {});

// Throws std::invalid_argument if there are no rows.
cv::Mat DrawPlateErrorChart(const std::vector<PlateErrorRow>& rows, const std::string& title);

struct SpreadEvent {
  double sim_time_s = 0.0;
  std::string label;         // e.g. a plate's text, "converged"
};
// Throws std::invalid_argument if there are no samples.
cv::Mat DrawSpreadPlot(const std::vector<SpreadSample>& samples, const std::vector<SpreadEvent>& plates,
                       double converged_time_s, const std::string& title);

}  // namespace doorplate_localization

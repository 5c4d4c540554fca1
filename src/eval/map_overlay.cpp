#include "map_overlay.h"

#include <cmath>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

namespace doorplate_localization {
namespace {

class Projector {
 public:
  Projector(const OccupancyGrid& grid, int scale) : grid_(grid), scale_(scale), grid_from_map_(grid.origin.Inverse()) {}
  cv::Point operator()(Vec2 p) const {
    const Vec2 local = grid_from_map_.TransformPoint(p);
    return {static_cast<int>(std::lround(scale_ * local.x / grid_.resolution_m)),
            static_cast<int>(std::lround(scale_ * (grid_.height - local.y / grid_.resolution_m)))};
  }

 private:
  const OccupancyGrid& grid_;
  const int scale_;
  const Pose2D grid_from_map_;
};

}  // namespace

cv::Mat DrawMapOverlay(const OccupancyGrid& grid, const MapOverlay& overlay, int scale) {
  if (grid.width <= 0 || grid.height <= 0) throw std::invalid_argument("DrawMapOverlay: empty grid");
  if (scale < 1) throw std::invalid_argument("DrawMapOverlay: scale must be >= 1, got " + std::to_string(scale));
  cv::Mat cells(grid.height, grid.width, CV_8UC3);
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      const int v = grid.At(x, y);
      const unsigned char c = v < 0 ? 205 : v >= 65 ? 0 : v <= 20 ? 254 : 128;  // map_server's trinary reading
      cells.at<cv::Vec3b>(grid.height - 1 - y, x) = {c, c, c};
    }
  }
  cv::Mat image;
  cv::resize(cells, image, {}, scale, scale, cv::INTER_NEAREST);
  const Projector to_pixel(grid, scale);
  for (const OverlayPath& path : overlay.paths) {
    for (std::size_t i = 1; i < path.points.size(); ++i) {
      cv::line(image, to_pixel(path.points[i - 1]), to_pixel(path.points[i]), path.color, path.thickness_px,
               cv::LINE_AA);
    }
  }
  for (const OverlayMark& mark : overlay.marks) {
    const cv::Point p = to_pixel(mark.position);
    if (mark.cross) {
      cv::drawMarker(image, p, mark.color, cv::MARKER_CROSS, 14, 2);
    } else {
      cv::circle(image, p, 5, mark.color, 2, cv::LINE_AA);
    }
    if (!mark.label.empty()) {
      cv::putText(image, mark.label, p + cv::Point(6, mark.label_below ? 16 : -8), cv::FONT_HERSHEY_PLAIN, 1.0,
                  mark.color, 1, cv::LINE_AA);
    }
  }
  for (const Pose2D& robot : overlay.robots) {
    const Vec2 tip = robot.TransformPoint({0.6, 0.0});
    cv::arrowedLine(image, to_pixel(robot.Position()), to_pixel(tip), {0, 0, 0}, 2, cv::LINE_AA, 0, 0.4);
  }
  if (!overlay.legend.empty()) {
    cv::putText(image, overlay.legend, {8, 16}, cv::FONT_HERSHEY_PLAIN, 1.0, {60, 60, 60}, 1, cv::LINE_AA);
  }
  return image;
}

}  // namespace doorplate_localization

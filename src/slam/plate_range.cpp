#include "doorplate_localization/slam/plate_range.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace doorplate_localization {
namespace {
constexpr int kHoughLines = 16;              // candidates taken from the transform
constexpr double kHoughAngleStepRad = 0.005;
}  // namespace

void ValidateWallRangeOptions(const WallRangeOptions& o) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("WallRangeOptions." + what); };
  if (!(o.window_rad > 0 && o.window_rad < M_PI)) fail("window_rad: must be in (0, pi)");
  if (!(o.inlier_m > 0 && std::isfinite(o.inlier_m))) fail("inlier_m: must be finite and > 0");
  if (o.min_inliers < 3) fail("min_inliers: must be >= 3");
  if (!(o.min_span_m >= 0 && std::isfinite(o.min_span_m))) fail("min_span_m: must be finite and >= 0");
  if (!(o.max_incidence_rad > 0 && o.max_incidence_rad < M_PI / 2)) fail("max_incidence_rad: must be in (0, pi/2)");
}

std::optional<double> WallRangeAlongBearing(const RangeScan& scan, double bearing_rad, const WallRangeOptions& options) {
  // Echoes in a frame turned so that the bearing is +y: a wall across it has a normal near +y, i.e. Hough
  // angles near pi/2, inside the (0, pi) range the transform expects, and a positive rho = its range.
  const double turn = M_PI / 2 - bearing_rad;
  const double c = std::cos(turn), s = std::sin(turn);
  std::vector<cv::Point2f> points;
  double farthest_m = 0.0;
  for (int i = 0; i < static_cast<int>(scan.ranges_m.size()); ++i) {
    const double r = scan.ranges_m[i];
    if (!std::isfinite(r) || r < scan.min_range_m) continue;
    const double a = scan.BeamAngle(i);
    const Vec2 end = scan.laser_pose.TransformPoint({r * std::cos(a), r * std::sin(a)});
    if (std::abs(NormalizeAngle(std::atan2(end.y, end.x) - bearing_rad)) > options.window_rad) continue;
    points.emplace_back(static_cast<float>(c * end.x - s * end.y), static_cast<float>(s * end.x + c * end.y));
    farthest_m = std::max(farthest_m, Norm(end));
  }
  if (static_cast<int>(points.size()) < options.min_inliers) return std::nullopt;
  cv::Mat lines;  // rows of (votes, rho, theta), most votes first
  cv::HoughLinesPointSet(points, lines, kHoughLines, options.min_inliers - 1, 0.0, farthest_m + options.inlier_m,
                         options.inlier_m, M_PI / 2 - options.max_incidence_rad, M_PI / 2 + options.max_incidence_rad,
                         kHoughAngleStepRad);
  // Votes count echoes, and something near the robot (a person before the plate) gets more echoes per
  // metre than the wall behind it: the wall is the candidate whose echoes span the longest stretch.
  std::vector<cv::Point2f> inliers;
  double longest_m = options.min_span_m;
  for (int row = 0; row < lines.rows; ++row) {
    const cv::Vec3d line = lines.at<cv::Vec3d>(row);
    const double rho = line[1], cos_t = std::cos(line[2]), sin_t = std::sin(line[2]);
    std::vector<cv::Point2f> support;
    double lo = 0.0, hi = 0.0;
    for (const cv::Point2f& p : points) {
      if (std::abs(p.x * cos_t + p.y * sin_t - rho) > options.inlier_m) continue;
      const double along = -p.x * sin_t + p.y * cos_t;
      lo = support.empty() ? along : std::min(lo, along);
      hi = support.empty() ? along : std::max(hi, along);
      support.push_back(p);
    }
    if (static_cast<int>(support.size()) >= options.min_inliers && hi - lo >= longest_m) {
      longest_m = hi - lo;
      inliers = std::move(support);
    }
  }
  if (inliers.empty()) return std::nullopt;
  cv::Vec4f fit;  // direction (vx, vy), a point (x0, y0)
  cv::fitLine(inliers, fit, cv::DIST_L2, 0, 0.01, 0.01);
  // The ray is the +y axis: it meets the line where x = 0. |vx| = cos(incidence) for a unit direction.
  if (std::abs(fit[0]) < std::cos(options.max_incidence_rad)) return std::nullopt;
  const double range_m = fit[3] - fit[2] * fit[1] / fit[0];
  if (!(range_m > 0) || !std::isfinite(range_m)) return std::nullopt;
  return range_m;
}

}  // namespace doorplate_localization

#include "doorplate_localization/sensors/plate_range.h"

#include <algorithm>
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
constexpr double kMaxCoverGapM = 0.25;       // a longer gap between a line's echoes counts this much

bool Usable(const std::vector<float>& ranges_m, const BeamGeometry& g, double bearing_rad) {
  return !ranges_m.empty() && std::fabs(g.angle_increment_rad) > 0.0 && std::isfinite(bearing_rad);
}

// Calls f(end point in base_link) for every echo whose end point lies within ± window_rad of the bearing.
template <typename F>
void ForEchoesNear(const std::vector<float>& ranges_m, const BeamGeometry& g, double bearing_rad, double window_rad,
                   F f) {
  for (std::size_t i = 0; i < ranges_m.size(); ++i) {
    const double r = ranges_m[i];
    if (!std::isfinite(r) || r < g.min_range_m || r >= g.max_range_m) continue;
    const double a = g.angle_min_rad + static_cast<double>(i) * g.angle_increment_rad;
    const Vec2 end = g.laser_pose.TransformPoint({r * std::cos(a), r * std::sin(a)});
    if (std::fabs(NormalizeAngle(std::atan2(end.y, end.x) - bearing_rad)) <= window_rad) f(end);
  }
}

}  // namespace

void ValidateWallRangeOptions(const WallRangeOptions& o) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("WallRangeOptions." + what); };
  if (!(o.window_rad > 0 && o.window_rad < M_PI)) fail("window_rad: must be in (0, pi)");
  if (!(o.inlier_m > 0 && std::isfinite(o.inlier_m))) fail("inlier_m: must be finite and > 0");
  if (o.min_inliers < 3) fail("min_inliers: must be >= 3");
  if (!(o.min_length_m >= 0 && std::isfinite(o.min_length_m))) fail("min_length_m: must be finite and >= 0");
  if (!(o.max_incidence_rad > 0 && o.max_incidence_rad < M_PI / 2)) fail("max_incidence_rad: must be in (0, pi/2)");
}

void ValidatePlateRangeOptions(const PlateRangeOptions& o) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("PlateRangeOptions." + what); };
  if (!(o.beam_window_rad >= 0 && o.beam_window_rad < M_PI)) fail("beam_window_rad: must be in [0, pi)");
  if (!(o.occluded_margin_m >= 0 && std::isfinite(o.occluded_margin_m))) {
    fail("occluded_margin_m: must be finite and >= 0");
  }
  ValidateWallRangeOptions(o.wall);
}

std::optional<double> EchoRangeAlongBearing(const std::vector<float>& ranges_m, const BeamGeometry& geometry,
                                            double bearing_rad, double window_rad) {
  if (!Usable(ranges_m, geometry, bearing_rad)) return std::nullopt;
  std::vector<double> ranges;
  ForEchoesNear(ranges_m, geometry, bearing_rad, window_rad, [&](const Vec2& end) { ranges.push_back(Norm(end)); });
  if (ranges.empty()) return std::nullopt;
  std::nth_element(ranges.begin(), ranges.begin() + ranges.size() / 2, ranges.end());
  return ranges[ranges.size() / 2];
}

std::optional<double> WallRangeAlongBearing(const std::vector<float>& ranges_m, const BeamGeometry& geometry,
                                            double bearing_rad, const WallRangeOptions& options) {
  if (!Usable(ranges_m, geometry, bearing_rad)) return std::nullopt;
  // Echoes in a frame turned so that the bearing is +y: a wall across it has a normal near +y, i.e. Hough
  // angles near pi/2, inside the (0, pi) range the transform expects, and a positive rho = its range.
  const double turn = M_PI / 2 - bearing_rad;
  const double c = std::cos(turn), s = std::sin(turn);
  std::vector<cv::Point2f> points;
  double farthest_m = 0.0;
  ForEchoesNear(ranges_m, geometry, bearing_rad, options.window_rad, [&](const Vec2& end) {
    points.emplace_back(static_cast<float>(c * end.x - s * end.y), static_cast<float>(s * end.x + c * end.y));
    farthest_m = std::max(farthest_m, Norm(end));
  });
  if (static_cast<int>(points.size()) < options.min_inliers) return std::nullopt;
  cv::Mat lines;  // rows of (votes, rho, theta), most votes first
  cv::HoughLinesPointSet(points, lines, kHoughLines, options.min_inliers - 1, 0.0, farthest_m + options.inlier_m,
                         options.inlier_m, M_PI / 2 - options.max_incidence_rad, M_PI / 2 + options.max_incidence_rad,
                         kHoughAngleStepRad);
  // Votes count echoes, and something near the robot (a person before the plate) gets more echoes per
  // metre than the wall behind it: the wall is the candidate whose echoes cover the longest stretch of
  // line, a gap between neighbours counting at most kMaxCoverGapM (a slanted line through a few echoes of
  // several things far apart covers little).
  std::vector<cv::Point2f> inliers;
  double longest_m = options.min_length_m;
  for (int row = 0; row < lines.rows; ++row) {
    const cv::Vec3d line = lines.at<cv::Vec3d>(row);
    const double rho = line[1], cos_t = std::cos(line[2]), sin_t = std::sin(line[2]);
    std::vector<cv::Point2f> support;
    std::vector<double> along;
    for (const cv::Point2f& p : points) {
      if (std::abs(p.x * cos_t + p.y * sin_t - rho) > options.inlier_m) continue;
      support.push_back(p);
      along.push_back(-p.x * sin_t + p.y * cos_t);
    }
    if (static_cast<int>(support.size()) < options.min_inliers) continue;
    std::sort(along.begin(), along.end());
    double covered_m = 0.0;
    for (std::size_t k = 1; k < along.size(); ++k) covered_m += std::min(along[k] - along[k - 1], kMaxCoverGapM);
    if (covered_m >= longest_m) {
      longest_m = covered_m;
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

std::optional<PlateRange> PlateRangeAlongBearing(const std::vector<float>& ranges_m, const BeamGeometry& geometry,
                                                 double bearing_rad, const PlateRangeOptions& options) {
  const std::optional<double> echo = EchoRangeAlongBearing(ranges_m, geometry, bearing_rad, options.beam_window_rad);
  if (!echo) return std::nullopt;
  if (options.occluded_margin_m > 0) {
    const std::optional<double> wall = WallRangeAlongBearing(ranges_m, geometry, bearing_rad, options.wall);
    if (wall && *wall - *echo >= options.occluded_margin_m) return PlateRange{*wall, true};
  }
  return PlateRange{*echo, false};
}

}  // namespace doorplate_localization

#include "map_measure.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "doorplate_localization/common/room_id.h"

namespace doorplate_localization {
namespace {

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  return v[mid];
}

// A wall's position from its cells' positions across it: the mean of the values within 0.15 m of their
// median. The median alone jumps by a whole cell when a wall is mapped two cells thick (the wall surface
// lies between them); the mean of the wall's own cells finds it, and the band keeps stray cells out.
double WallPosition(const std::vector<double>& v) {
  const double median = Median(v);
  double sum = 0.0;
  int count = 0;
  for (double value : v) {
    if (std::abs(value - median) <= 0.15) sum += value, ++count;
  }
  return count > 0 ? sum / count : median;
}

// A side wall as the line v = offset + slope · (u - mid_u) through its cells: least squares on the cells
// within 0.15 m of their median, then once more on those within 0.15 m of that line.
struct WallLine {
  double offset = 0.0;
  double slope = 0.0;
};
WallLine FitWallLine(const std::vector<std::pair<double, double>>& cells, double mid_u) {
  WallLine line;
  std::vector<double> v;
  for (const auto& c : cells) v.push_back(c.second);
  line.offset = Median(v);
  for (int pass = 0; pass < 2; ++pass) {
    double su = 0, sv = 0, suu = 0, suv = 0;
    int count = 0;
    for (const auto& [cu, cv] : cells) {
      const double du = cu - mid_u;
      if (std::abs(cv - (line.offset + line.slope * du)) > 0.15) continue;
      su += du, sv += cv, suu += du * du, suv += du * cv, ++count;
    }
    if (count < 2) break;
    const double det = count * suu - su * su;
    if (std::abs(det) < 1e-12) {
      line.offset = sv / count;
      continue;
    }
    line.slope = (count * suv - su * sv) / det;
    line.offset = (sv - line.slope * su) / count;
  }
  return line;
}

// Unit principal axis of a point set (eigenvector of the larger eigenvalue of the 2×2 covariance).
Vec2 PrincipalAxis(const std::vector<Vec2>& points) {
  Vec2 mean;
  for (const Vec2& p : points) mean = mean + (1.0 / points.size()) * p;
  double sxx = 0, sxy = 0, syy = 0;
  for (const Vec2& p : points) {
    const Vec2 d = p - mean;
    sxx += d.x * d.x, sxy += d.x * d.y, syy += d.y * d.y;
  }
  const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  return {std::cos(angle), std::sin(angle)};
}

}  // namespace

CorridorExtent MeasureCorridor(const OccupancyGrid& grid, double end_band_m) {
  CorridorExtent extent;
  std::vector<Vec2> occupied;
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      if (grid.At(x, y) == OccupancyGrid::kOccupied) occupied.push_back(grid.CellCenter(x, y));
    }
  }
  if (occupied.size() < 20) return extent;
  extent.axis = PrincipalAxis(occupied);
  const Vec2 normal{-extent.axis.y, extent.axis.x};
  std::vector<double> u, v;
  for (const Vec2& p : occupied) u.push_back(Dot(p, extent.axis)), v.push_back(Dot(p, normal));
  std::vector<double> sorted_u = u;
  std::sort(sorted_u.begin(), sorted_u.end());
  const std::size_t n = sorted_u.size();
  const double low = sorted_u[n / 200], high = sorted_u[n - 1 - n / 200];
  std::vector<double> low_end, high_end, inner_v;
  for (std::size_t i = 0; i < n; ++i) {
    if (u[i] <= low + end_band_m) low_end.push_back(u[i]);
    if (u[i] >= high - end_band_m) high_end.push_back(u[i]);
    if (u[i] > low + end_band_m && u[i] < high - end_band_m) inner_v.push_back(v[i]);
  }
  extent.length_m = WallPosition(high_end) - WallPosition(low_end);
  // The centre line halfway between the outermost cells (a median of all cells would sit on whichever
  // wall has more cells); each side wall a line fitted to its cells, so that a wall mapped thicker at one
  // end than at the other neither tilts nor shifts it.
  std::vector<double> sorted_v = inner_v;
  std::sort(sorted_v.begin(), sorted_v.end());
  const double centre = sorted_v.empty() ? 0.0
                                         : 0.5 * (sorted_v[sorted_v.size() / 20] + sorted_v[sorted_v.size() - 1 - sorted_v.size() / 20]);
  std::vector<std::pair<double, double>> below, above;  // (u, v)
  for (std::size_t i = 0; i < n; ++i) {
    if (u[i] > low + end_band_m && u[i] < high - end_band_m) (v[i] < centre ? below : above).emplace_back(u[i], v[i]);
  }
  const double mid_u = 0.5 * (low + high);
  const WallLine lower = FitWallLine(below, mid_u), upper = FitWallLine(above, mid_u);
  extent.width_m = (upper.offset - lower.offset) * std::cos(std::atan(0.5 * (upper.slope + lower.slope)));
  extent.ok = !below.empty() && !above.empty();
  return extent;
}

CorridorExtent MeasureSegments(const std::vector<Segment>& walls) {
  CorridorExtent extent;
  std::vector<Vec2> points;
  for (const Segment& s : walls) points.push_back(s.a), points.push_back(s.b);
  if (points.size() < 4) return extent;
  extent.axis = PrincipalAxis(points);
  const Vec2 normal{-extent.axis.y, extent.axis.x};
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  for (const Vec2& p : points) {
    u0 = std::min(u0, Dot(p, extent.axis)), u1 = std::max(u1, Dot(p, extent.axis));
    v0 = std::min(v0, Dot(p, normal)), v1 = std::max(v1, Dot(p, normal));
  }
  extent.length_m = u1 - u0;
  extent.width_m = v1 - v0;
  extent.ok = true;
  return extent;
}

OutLeg MeasureOutLeg(const std::vector<Pose2D>& estimated, const std::vector<Pose2D>& truth) {
  OutLeg leg;
  const std::size_t n = std::min(estimated.size(), truth.size());
  if (n < 2) return leg;
  for (std::size_t i = 1; i < n; ++i) {
    const double d = Norm(truth[i].Position() - truth[0].Position());
    if (d > leg.true_m) leg.true_m = d, leg.turn_index = static_cast<int>(i);
  }
  if (leg.turn_index < 0) return leg;
  leg.estimated_m = Norm(estimated[leg.turn_index].Position() - estimated[0].Position());
  leg.accuracy = ExtentAccuracy(leg.estimated_m, leg.true_m);
  return leg;
}

double ExtentAccuracy(double estimate_m, double truth_m) {
  return truth_m > 0 ? 1.0 - std::abs(estimate_m - truth_m) / truth_m : 0.0;
}

PlateScore ScorePlates(const TextMap& mapped, const TextMap& truth, const Pose2D& world_from_map,
                       double match_radius_m) {
  PlateScore score;
  score.plates_true = static_cast<int>(truth.landmarks.size());
  score.plates_in_map = static_cast<int>(mapped.landmarks.size());
  score.errors_m.assign(mapped.landmarks.size(), -1.0);
  std::vector<std::tuple<double, int, int>> pairs;  // distance, mapped, true
  for (std::size_t i = 0; i < mapped.landmarks.size(); ++i) {
    const Vec2 p = world_from_map.TransformPoint(mapped.landmarks[i].pose.Position());
    for (std::size_t j = 0; j < truth.landmarks.size(); ++j) {
      if (!SameRoom(truth.landmarks[j].text, mapped.landmarks[i].text)) continue;
      const double d = Norm(p - truth.landmarks[j].pose.Position());
      if (d <= match_radius_m) pairs.emplace_back(d, static_cast<int>(i), static_cast<int>(j));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> used(truth.landmarks.size(), false);
  double sum2 = 0.0;
  for (const auto& [d, i, j] : pairs) {
    if (used[j] || score.errors_m[i] >= 0) continue;
    used[j] = true;
    score.errors_m[i] = d;
    ++score.plates_mapped;
    sum2 += d * d;
    score.max_error_m = std::max(score.max_error_m, d);
  }
  if (score.plates_mapped > 0) score.rmse_m = std::sqrt(sum2 / score.plates_mapped);
  return score;
}

}  // namespace doorplate_localization

#include "doorplate_localization/behaviour/grid_path_planner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>

#include <opencv2/imgproc.hpp>

namespace doorplate_localization {
namespace {

void Require(bool ok, const char* field, const char* rule) {
  if (!ok) throw std::invalid_argument(std::string("GridPathPlannerOptions.") + field + ": " + rule);
}

const GridPathPlannerOptions& Validated(const GridPathPlannerOptions& o) {
  Require(o.robot_radius_m >= 0 && std::isfinite(o.robot_radius_m), "robot_radius_m", "must be finite and >= 0");
  Require(o.clearance_m >= o.robot_radius_m && std::isfinite(o.clearance_m), "clearance_m",
          "must be finite and >= robot_radius_m");
  Require(o.preferred_clearance_m > o.clearance_m && std::isfinite(o.preferred_clearance_m), "preferred_clearance_m",
          "must be finite and > clearance_m");
  Require(o.wall_cost_weight >= 0 && std::isfinite(o.wall_cost_weight), "wall_cost_weight", "must be finite and >= 0");
  Require(o.occupied_threshold >= 1 && o.occupied_threshold <= 100, "occupied_threshold", "must be in [1, 100]");
  Require(o.waypoint_spacing_m > 0 && std::isfinite(o.waypoint_spacing_m), "waypoint_spacing_m",
          "must be finite and > 0");
  return o;
}

const OccupancyGrid& CheckedGrid(const OccupancyGrid& grid) {
  if (grid.width <= 0 || grid.height <= 0 || grid.resolution_m <= 0 ||
      grid.cells.size() != static_cast<size_t>(grid.width) * grid.height) {
    throw std::invalid_argument("GridPathPlanner: grid: empty, or cells do not match width x height");
  }
  return grid;
}

std::string Point(Vec2 p) {
  char text[64];
  std::snprintf(text, sizeof(text), "(%.2f, %.2f)", p.x, p.y);
  return text;
}

// Three passes of a 5-point moving average (ends fixed) take the grid's 45° steps out of the path.
std::vector<Vec2> Smoothed(std::vector<Vec2> points) {
  for (int pass = 0; pass < 3 && points.size() > 4; ++pass) {
    std::vector<Vec2> out = points;
    for (size_t i = 2; i + 2 < points.size(); ++i) {
      out[i] = 0.2 * (points[i - 2] + points[i - 1] + points[i] + points[i + 1] + points[i + 2]);
    }
    points.swap(out);
  }
  return points;
}

// Points every `spacing` metres along the polyline, its two ends included.
std::vector<Vec2> Resampled(const std::vector<Vec2>& points, double spacing, double* length_m) {
  *length_m = 0.0;
  std::vector<Vec2> out{points.front()};
  double carried = 0.0;  // distance since the last output point
  for (size_t i = 1; i < points.size(); ++i) {
    const Vec2 d = points[i] - points[i - 1];
    const double l = Norm(d);
    *length_m += l;
    double t = spacing - carried;
    while (t < l) {
      out.push_back(points[i - 1] + (t / l) * d);
      t += spacing;
    }
    carried = l - (t - spacing);
  }
  if (Norm(points.back() - out.back()) > 1e-9) {
    if (out.size() > 1 && Norm(points.back() - out.back()) < 0.3 * spacing) out.pop_back();
    out.push_back(points.back());
  }
  return out;
}

}  // namespace

GridPathPlanner::GridPathPlanner(const GridPathPlannerOptions& options, const OccupancyGrid& grid)
    : options_(Validated(options)), grid_(CheckedGrid(grid)) {
  cv::Mat free_mask(grid_.height, grid_.width, CV_8U);
  for (int y = 0; y < grid_.height; ++y) {
    for (int x = 0; x < grid_.width; ++x) {
      const int v = grid_.At(x, y);
      const bool obstacle = v >= options_.occupied_threshold || (v < 0 && !options_.unknown_is_free);
      free_mask.at<unsigned char>(y, x) = obstacle ? 0 : 255;
    }
  }
  cv::Mat distance_px;
  cv::distanceTransform(free_mask, distance_px, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  clearance_m_.resize(grid_.cells.size());
  for (int y = 0; y < grid_.height; ++y) {
    for (int x = 0; x < grid_.width; ++x) {
      clearance_m_[static_cast<size_t>(y) * grid_.width + x] =
          static_cast<float>(distance_px.at<float>(y, x) * grid_.resolution_m);
    }
  }
}

double GridPathPlanner::ClearanceAt(Vec2 p) const {
  int x = 0, y = 0;
  if (!grid_.WorldToCell(p, &x, &y)) return 0.0;
  return clearance_m_[static_cast<size_t>(y) * grid_.width + x];
}

double GridPathPlanner::StepFactor(double clearance_m) const {
  if (clearance_m >= options_.preferred_clearance_m) return 1.0;
  const double u =
      (options_.preferred_clearance_m - clearance_m) / (options_.preferred_clearance_m - options_.clearance_m);
  return 1.0 + options_.wall_cost_weight * u * u;
}

GridPath GridPathPlanner::Plan(Vec2 start, Vec2 goal) const {
  const auto began = std::chrono::steady_clock::now();
  GridPath path;
  auto finish = [&](GridPath& p) -> GridPath {
    p.plan_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    return p;
  };
  int sx = 0, sy = 0, gx = 0, gy = 0;
  char numbers[96];
  if (!grid_.WorldToCell(start, &sx, &sy)) {
    path.failure = "start " + Point(start) + " is outside the map";
    return finish(path);
  }
  if (!grid_.WorldToCell(goal, &gx, &gy)) {
    path.failure = "goal " + Point(goal) + " is outside the map";
    return finish(path);
  }
  const int w = grid_.width;
  const int start_index = sy * w + sx, goal_index = gy * w + gx;
  if (clearance_m_[start_index] < options_.robot_radius_m) {
    std::snprintf(numbers, sizeof(numbers), " is %.2f m from an obstacle (robot radius %.2f m)",
                  clearance_m_[start_index], options_.robot_radius_m);
    path.failure = "start inside an obstacle: " + Point(start) + numbers;
    return finish(path);
  }
  if (clearance_m_[goal_index] < options_.robot_radius_m) {
    std::snprintf(numbers, sizeof(numbers), " is %.2f m from an obstacle (robot radius %.2f m)",
                  clearance_m_[goal_index], options_.robot_radius_m);
    path.failure = "goal inside an obstacle: " + Point(goal) + numbers;
    return finish(path);
  }

  const double res = grid_.resolution_m;
  const double escape2 = options_.clearance_m * options_.clearance_m;
  auto allowed = [&](int x, int y) {
    const float c = clearance_m_[static_cast<size_t>(y) * w + x];
    if (c >= options_.clearance_m) return true;
    if (c < options_.robot_radius_m || c <= 0.0f) return false;
    const Vec2 p = grid_.CellCenter(x, y);
    const Vec2 ds = p - start, dg = p - goal;
    return Dot(ds, ds) <= escape2 || Dot(dg, dg) <= escape2;
  };
  auto heuristic = [&](int x, int y) { return res * std::hypot(x - gx, y - gy); };

  const size_t n = grid_.cells.size();
  std::vector<double> cost(n, std::numeric_limits<double>::infinity());
  std::vector<int> parent(n, -1);
  std::vector<unsigned char> closed(n, 0);
  using Entry = std::pair<double, int>;  // f, cell index
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  cost[start_index] = 0.0;
  open.push({heuristic(sx, sy), start_index});
  static const int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
  static const int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  while (!open.empty()) {
    const int index = open.top().second;
    open.pop();
    if (closed[index]) continue;
    closed[index] = 1;
    ++path.expanded_cells;
    if (index == goal_index) break;
    const int x = index % w, y = index / w;
    for (int k = 0; k < 8; ++k) {
      const int nx = x + kDx[k], ny = y + kDy[k];
      if (!grid_.InBounds(nx, ny)) continue;
      const int next = ny * w + nx;
      if (closed[next] || !allowed(nx, ny)) continue;
      const double step = (k < 4 ? 1.0 : M_SQRT2) * res * StepFactor(clearance_m_[next]);
      const double c = cost[index] + step;
      if (c < cost[next]) {
        cost[next] = c;
        parent[next] = index;
        open.push({c + heuristic(nx, ny), next});
      }
    }
  }
  if (!closed[goal_index]) {
    std::snprintf(numbers, sizeof(numbers), " keeping %.2f m from obstacles", options_.clearance_m);
    path.failure = "no path from " + Point(start) + " to " + Point(goal) + numbers;
    return finish(path);
  }

  std::vector<Vec2> cells;
  double clearance_sum = 0.0;
  path.min_clearance_m = std::numeric_limits<double>::infinity();
  for (int i = goal_index; i >= 0; i = parent[i]) {
    cells.push_back(grid_.CellCenter(i % w, i / w));
    path.min_clearance_m = std::min<double>(path.min_clearance_m, clearance_m_[i]);
    clearance_sum += clearance_m_[i];
  }
  path.mean_clearance_m = clearance_sum / cells.size();
  std::reverse(cells.begin(), cells.end());
  if (cells.size() == 1) cells.push_back(goal);
  cells.front() = start;
  cells.back() = goal;
  path.waypoints = Resampled(Smoothed(cells), options_.waypoint_spacing_m, &path.length_m);
  path.found = true;
  return finish(path);
}

}  // namespace doorplate_localization

#include "doorplate_localization/mcl/grid_ray_caster.h"

#include <cmath>
#include <limits>

namespace doorplate_localization {
namespace {

bool Blocks(const LocalizationGrid& grid, int x, int y, bool unknown_blocks) {
  if (!grid.InBounds(x, y)) return true;
  const CellState s = grid.State(x, y);
  return s == CellState::kOccupied || (unknown_blocks && s == CellState::kUnknown);
}

}  // namespace

double CastRay(const LocalizationGrid& grid, Vec2 origin, double angle_rad, double max_range_m, bool unknown_blocks) {
  const Vec2 o = grid.ToCellCoords(origin);
  if (!(o.x >= 0.0 && o.y >= 0.0 && o.x < grid.width() && o.y < grid.height())) return 0.0;
  int x = static_cast<int>(o.x), y = static_cast<int>(o.y);
  if (Blocks(grid, x, y, unknown_blocks)) return 0.0;
  // Direction in cell coordinates (the grid may be rotated in the map frame).
  const double a = angle_rad - grid.origin().theta_rad;
  const double dx = std::cos(a), dy = std::sin(a);
  const double inf = std::numeric_limits<double>::infinity();
  const int step_x = dx > 0 ? 1 : -1, step_y = dy > 0 ? 1 : -1;
  const double delta_x = dx != 0.0 ? std::fabs(1.0 / dx) : inf;
  const double delta_y = dy != 0.0 ? std::fabs(1.0 / dy) : inf;
  double next_x = dx > 0 ? (x + 1 - o.x) * delta_x : (dx < 0 ? (o.x - x) * delta_x : inf);
  double next_y = dy > 0 ? (y + 1 - o.y) * delta_y : (dy < 0 ? (o.y - y) * delta_y : inf);
  const double max_t = max_range_m / grid.resolution_m();
  for (;;) {
    double t = 0.0;
    if (next_x < next_y) {
      t = next_x;
      next_x += delta_x;
      x += step_x;
    } else {
      t = next_y;
      next_y += delta_y;
      y += step_y;
    }
    if (t >= max_t) return max_range_m;
    if (Blocks(grid, x, y, unknown_blocks)) return t * grid.resolution_m();
  }
}

bool HasLineOfSight(const LocalizationGrid& grid, Vec2 from, Vec2 to, double tolerance_m, bool unknown_blocks) {
  const Vec2 d = to - from;
  const double distance = Norm(d);
  if (distance <= tolerance_m) return true;
  const double free = CastRay(grid, from, std::atan2(d.y, d.x), distance, unknown_blocks);
  return free >= distance - tolerance_m;
}

LaserScan CastScan(const LocalizationGrid& grid, const Pose2D& robot_pose, const LaserScan& scan_geometry,
                   int num_beams, bool unknown_blocks) {
  LaserScan scan = scan_geometry;
  scan.ranges_m.assign(num_beams, std::numeric_limits<float>::infinity());
  const Pose2D laser = robot_pose.Compose(scan_geometry.laser_pose);
  for (int i = 0; i < num_beams; ++i) {
    const double angle = laser.theta_rad + scan.angle_min_rad + i * scan.angle_increment_rad;
    const double r = CastRay(grid, laser.Position(), angle, scan.max_range_m, unknown_blocks);
    if (r < scan.max_range_m) scan.ranges_m[i] = static_cast<float>(r);
  }
  return scan;
}

}  // namespace doorplate_localization

#include "doorplate_localization/maps/occupancy_grid.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "doorplate_localization/common/limits.h"

namespace doorplate_localization {

OccupancyGrid::OccupancyGrid(int width_cells, int height_cells, double resolution, Pose2D origin_pose,
                             std::int8_t fill)
    : resolution_m(resolution), origin(origin_pose), width(width_cells), height(height_cells) {
  if (width_cells < 0 || height_cells < 0) {
    throw std::invalid_argument("OccupancyGrid: negative size " + std::to_string(width_cells) + " x " +
                                std::to_string(height_cells));
  }
  // Before allocating: a grid beyond limits::kMaxMapCells is refused, not attempted (issue 18).
  if (width_cells > 0 && height_cells > 0) {
    const std::string too_big = limits::CheckMapCells(width_cells, height_cells);
    if (!too_big.empty()) throw std::invalid_argument("OccupancyGrid: size " + too_big);
  }
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    throw std::invalid_argument("OccupancyGrid: resolution must be > 0, got " + std::to_string(resolution));
  }
  cells.assign(static_cast<size_t>(width_cells) * static_cast<size_t>(height_cells), fill);
}

Vec2 OccupancyGrid::CellCenter(int x, int y) const {
  return origin.TransformPoint({(x + 0.5) * resolution_m, (y + 0.5) * resolution_m});
}

bool OccupancyGrid::WorldToCell(Vec2 p, int* x, int* y) const {
  const Vec2 local = origin.Inverse().TransformPoint(p);
  const double cx = std::floor(local.x / resolution_m);
  const double cy = std::floor(local.y / resolution_m);
  if (!(cx >= 0 && cy >= 0 && cx < width && cy < height)) return false;  // also rejects NaN
  *x = static_cast<int>(cx);
  *y = static_cast<int>(cy);
  return true;
}

}  // namespace doorplate_localization

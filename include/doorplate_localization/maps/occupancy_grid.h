// A 2D occupancy grid in the map frame, with map_server's conventions: cell (0, 0) is the lower-left
// cell, its lower-left corner is at `origin` (x_m, y_m, yaw rad); rows go up in +y. Values follow
// nav_msgs/OccupancyGrid: -1 unknown, 0 free .. 100 occupied.
#pragma once

#include <cstdint>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct OccupancyGrid {
  static constexpr std::int8_t kUnknown = -1;
  static constexpr std::int8_t kFree = 0;
  static constexpr std::int8_t kOccupied = 100;

  double resolution_m = 0.05;   // cell side
  Pose2D origin;                // pose of cell (0, 0)'s lower-left corner in the map frame
  int width = 0;                // cells along x
  int height = 0;               // cells along y
  std::vector<std::int8_t> cells;  // row-major, index = y * width + x

  OccupancyGrid() = default;
  // A grid of `width` × `height` cells, all `fill`. Throws std::invalid_argument for a negative size, a
  // resolution that is not finite and > 0, or more cells than limits::kMaxMapCells (before allocating).
  OccupancyGrid(int width_cells, int height_cells, double resolution, Pose2D origin_pose,
                std::int8_t fill = kUnknown);

  bool InBounds(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  std::int8_t At(int x, int y) const { return cells[static_cast<size_t>(y) * width + x]; }
  std::int8_t& At(int x, int y) { return cells[static_cast<size_t>(y) * width + x]; }
  // Map-frame position of a cell's centre.
  Vec2 CellCenter(int x, int y) const;
  // The cell containing a map-frame point; false (and unchanged outputs) if it is outside the grid.
  bool WorldToCell(Vec2 p, int* x, int* y) const;
  // Size of the grid along its x and y axes, metres.
  double WidthM() const { return width * resolution_m; }
  double HeightM() const { return height * resolution_m; }
};

}  // namespace doorplate_localization

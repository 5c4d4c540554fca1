// The occupancy grid as the localizer reads it: each cell free, occupied or unknown (amcl's trinary
// reading of nav_msgs/OccupancyGrid values), map <-> cell transforms, and uniform sampling of free poses.
// Frames: map frame in metres/radians; "cell coordinates" are continuous grid units where cell (i, j)
// covers [i, i+1) × [j, j+1) (the grid origin's yaw is honoured).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"

namespace doorplate_localization {

enum class CellState : std::uint8_t { kFree, kOccupied, kUnknown };

struct LocalizationGridOptions {
  // amcl's reading: exactly 0 is free, exactly 100 occupied, everything else (-1, 1..99) unknown.
  // Loosen them for maps with intermediate values (e.g. free_max_value 19, occupied_min_value 65).
  int free_max_value = 0;       // 0 <= value <= this: free
  int occupied_min_value = 100; // value >= this: occupied
};

class LocalizationGrid {
 public:
  // Throws std::invalid_argument naming the field of an unusable grid or options: cells not width x height,
  // more than limits::kMaxMapCells, a resolution or origin outside limits.h's bounds.
  explicit LocalizationGrid(const OccupancyGrid& grid, const LocalizationGridOptions& options = {});

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution_m() const { return resolution_m_; }
  const Pose2D& origin() const { return origin_; }

  bool InBounds(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  // Requires InBounds(x, y).
  CellState State(int x, int y) const { return static_cast<CellState>(states_[Index(x, y)]); }
  size_t Index(int x, int y) const { return static_cast<size_t>(y) * width_ + x; }

  // Map-frame point -> continuous cell coordinates, and back.
  Vec2 ToCellCoords(Vec2 p) const;
  Vec2 FromCellCoords(Vec2 c) const;
  // The cell holding map point p; false (outputs untouched) outside the grid.
  bool PointToCell(Vec2 p, int* x, int* y) const;
  Vec2 CellCenter(int x, int y) const { return FromCellCoords({x + 0.5, y + 0.5}); }
  // True if p lies in the grid on a free cell.
  bool IsFree(Vec2 p) const;

  // Row-major indexes of the free cells, ascending.
  const std::vector<int>& free_cells() const { return free_cells_; }
  // A pose uniform over the free area (uniform inside a uniformly chosen free cell) with a uniform
  // heading in (-pi, pi]. Throws std::logic_error if the grid has no free cell.
  Pose2D SampleFreePose(std::mt19937_64& rng) const;

 private:
  int width_ = 0;
  int height_ = 0;
  double resolution_m_ = 0.0;
  Pose2D origin_;
  double cos_origin_ = 1.0;
  double sin_origin_ = 0.0;
  std::vector<std::uint8_t> states_;  // CellState per cell
  std::vector<int> free_cells_;
};

// "" if `grid` has a free cell, else the problem ("no free cell: all 10000 cells are occupied or unknown"):
// a filter on such a grid cannot place particles by GlobalLocalization or recovery.
std::string NoFreeCellProblem(const LocalizationGrid& grid);

}  // namespace doorplate_localization

#include "doorplate_localization/mcl/localization_grid.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "doorplate_localization/common/limits.h"

namespace doorplate_localization {

LocalizationGrid::LocalizationGrid(const OccupancyGrid& grid, const LocalizationGridOptions& options)
    : width_(grid.width), height_(grid.height), resolution_m_(grid.resolution_m), origin_(grid.origin) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("LocalizationGrid: " + what); };
  if (grid.width <= 0 || grid.height <= 0) {
    fail("OccupancyGrid.width/height: must be > 0, got " + std::to_string(grid.width) + " x " +
         std::to_string(grid.height));
  }
  const std::string too_big = limits::CheckMapCells(grid.width, grid.height);
  if (!too_big.empty()) fail("OccupancyGrid.width/height: " + too_big);
  if (grid.cells.size() != static_cast<size_t>(grid.width) * grid.height) {
    fail("OccupancyGrid.cells: " + std::to_string(grid.cells.size()) + " values for " +
         std::to_string(grid.width) + " x " + std::to_string(grid.height) + " cells");
  }
  const std::string bad_resolution = limits::CheckMapResolution(grid.resolution_m);
  if (!bad_resolution.empty()) fail("OccupancyGrid.resolution_m: " + bad_resolution);
  for (const auto& [name, value] : {std::pair<const char*, double>{"x_m", grid.origin.x_m}, {"y_m", grid.origin.y_m}}) {
    const std::string bad = limits::CheckCoordinate(value);
    if (!bad.empty()) fail(std::string("OccupancyGrid.origin.") + name + ": " + bad);
  }
  if (!std::isfinite(grid.origin.theta_rad)) fail("OccupancyGrid.origin.theta_rad: must be finite");
  if (options.free_max_value < 0 || options.occupied_min_value > 100 ||
      options.free_max_value >= options.occupied_min_value) {
    fail("free_max_value/occupied_min_value: need 0 <= free_max_value < occupied_min_value <= 100, got " +
         std::to_string(options.free_max_value) + " / " + std::to_string(options.occupied_min_value));
  }
  cos_origin_ = std::cos(origin_.theta_rad);
  sin_origin_ = std::sin(origin_.theta_rad);
  states_.resize(grid.cells.size());
  for (size_t i = 0; i < grid.cells.size(); ++i) {
    const int v = grid.cells[i];
    CellState s = CellState::kUnknown;
    if (v >= 0 && v <= options.free_max_value) {
      s = CellState::kFree;
      free_cells_.push_back(static_cast<int>(i));
    } else if (v >= options.occupied_min_value) {
      s = CellState::kOccupied;
    }
    states_[i] = static_cast<std::uint8_t>(s);
  }
}

Vec2 LocalizationGrid::ToCellCoords(Vec2 p) const {
  const double dx = p.x - origin_.x_m, dy = p.y - origin_.y_m;
  return {(cos_origin_ * dx + sin_origin_ * dy) / resolution_m_,
          (-sin_origin_ * dx + cos_origin_ * dy) / resolution_m_};
}

Vec2 LocalizationGrid::FromCellCoords(Vec2 c) const {
  const double lx = c.x * resolution_m_, ly = c.y * resolution_m_;
  return {origin_.x_m + cos_origin_ * lx - sin_origin_ * ly, origin_.y_m + sin_origin_ * lx + cos_origin_ * ly};
}

bool LocalizationGrid::PointToCell(Vec2 p, int* x, int* y) const {
  const Vec2 c = ToCellCoords(p);
  if (!(c.x >= 0.0 && c.y >= 0.0 && c.x < width_ && c.y < height_)) return false;  // also rejects NaN
  *x = static_cast<int>(c.x);
  *y = static_cast<int>(c.y);
  return true;
}

bool LocalizationGrid::IsFree(Vec2 p) const {
  int x = 0, y = 0;
  return PointToCell(p, &x, &y) && State(x, y) == CellState::kFree;
}

Pose2D LocalizationGrid::SampleFreePose(std::mt19937_64& rng) const {
  if (free_cells_.empty()) throw std::logic_error("LocalizationGrid::SampleFreePose: the grid has no free cell");
  std::uniform_int_distribution<size_t> pick(0, free_cells_.size() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int index = free_cells_[pick(rng)];
  const Vec2 c{index % width_ + unit(rng), index / width_ + unit(rng)};
  const Vec2 p = FromCellCoords(c);
  return {p.x, p.y, NormalizeAngle(M_PI * (2.0 * unit(rng) - 1.0))};
}

std::string NoFreeCellProblem(const LocalizationGrid& grid) {
  if (!grid.free_cells().empty()) return "";
  return "no free cell: all " + std::to_string(static_cast<long long>(grid.width()) * grid.height()) +
         " cells are occupied or unknown";
}

}  // namespace doorplate_localization

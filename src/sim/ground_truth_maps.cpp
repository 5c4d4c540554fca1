#include "doorplate_localization/sim/ground_truth_maps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace doorplate_localization {
namespace {

constexpr double kMarginM = 0.5;
constexpr double kMaxCells = 2e8;  // 200 MB of cells: a 700 m x 700 m building at 5 cm

// People are not part of the ground truth (they move); everything else static is, glass included.
bool SpansHeight(const Surface& s, double height_m) {
  return s.kind != SurfaceKind::kPerson && s.z_min_m <= height_m && height_m <= s.z_max_m;
}

// Marks every cell the segment passes through (grid traversal in cell units), stepping one cell in x or
// in y at a time so that consecutive cells share a side. The grid's origin has no rotation.
void DrawSegment(const Segment& segment, OccupancyGrid* grid) {
  const double r = grid->resolution_m;
  const Vec2 a{(segment.a.x - grid->origin.x_m) / r, (segment.a.y - grid->origin.y_m) / r};
  const Vec2 b{(segment.b.x - grid->origin.x_m) / r, (segment.b.y - grid->origin.y_m) / r};
  int x = static_cast<int>(std::floor(a.x)), y = static_cast<int>(std::floor(a.y));
  const int end_x = static_cast<int>(std::floor(b.x)), end_y = static_cast<int>(std::floor(b.y));
  const Vec2 d = b - a;
  const double inf = std::numeric_limits<double>::infinity();
  const int step_x = d.x > 0 ? 1 : -1, step_y = d.y > 0 ? 1 : -1;
  double t_max_x = d.x != 0 ? ((step_x > 0 ? x + 1 : x) - a.x) / d.x : inf;
  double t_max_y = d.y != 0 ? ((step_y > 0 ? y + 1 : y) - a.y) / d.y : inf;
  const double t_delta_x = d.x != 0 ? std::abs(1.0 / d.x) : inf;
  const double t_delta_y = d.y != 0 ? std::abs(1.0 / d.y) : inf;
  grid->At(x, y) = OccupancyGrid::kOccupied;
  while (x != end_x || y != end_y) {
    if (y == end_y || (x != end_x && t_max_x <= t_max_y)) {
      x += step_x;
      t_max_x += t_delta_x;
    } else {
      y += step_y;
      t_max_y += t_delta_y;
    }
    grid->At(x, y) = OccupancyGrid::kOccupied;
  }
}

std::string WorldName(const World& world) {
  return world.source_file.empty() ? "world '" + world.name + "'" : world.source_file;
}

// Sets free every unknown cell 4-connected to (x, y); throws when the fill touches the grid border.
void FloodFree(const World& world, double laser_height_m, int x0, int y0, OccupancyGrid* grid) {
  std::vector<std::pair<int, int>> stack{{x0, y0}};
  grid->At(x0, y0) = OccupancyGrid::kFree;
  while (!stack.empty()) {
    const auto [x, y] = stack.back();
    stack.pop_back();
    if (x == 0 || y == 0 || x == grid->width - 1 || y == grid->height - 1) {
      const Vec2 p = grid->CellCenter(x, y);
      std::ostringstream out;
      out << WorldName(world) << ": the area reachable from the robot start is not closed at laser height "
          << laser_height_m << " m (it leaks out near x = " << p.x << ", y = " << p.y << ")";
      throw std::runtime_error(out.str());
    }
    for (const auto& [nx, ny] : {std::pair{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}}) {
      if (grid->At(nx, ny) == OccupancyGrid::kUnknown) {
        grid->At(nx, ny) = OccupancyGrid::kFree;
        stack.push_back({nx, ny});
      }
    }
  }
}

}  // namespace

OccupancyGrid RasterizeWorld(const World& world, double resolution_m, double laser_height_m) {
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m)) {
    throw std::invalid_argument("RasterizeWorld: resolution must be > 0, got " + std::to_string(resolution_m));
  }
  if (world.surfaces.empty()) {
    throw std::invalid_argument("RasterizeWorld: " + WorldName(world) + " has no surfaces (call BuildSurfaces)");
  }
  Vec2 lo = world.start_pose.Position(), hi = lo;
  for (const Surface& s : world.surfaces) {
    if (s.kind == SurfaceKind::kPerson) continue;
    for (const Vec2& p : {s.segment.a, s.segment.b}) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
  }
  // Cell i's centre is at (first + i) * resolution: round coordinates fall on cell centres.
  // (The 1e-9 keeps bounds that are whole multiples of the resolution from moving by a cell on rounding.)
  const auto cell_floor = [&](double v) { return static_cast<int>(std::floor(v / resolution_m + 1e-9)); };
  const auto cell_ceil = [&](double v) { return static_cast<int>(std::ceil(v / resolution_m - 1e-9)); };
  const int first_x = cell_floor(lo.x - kMarginM), first_y = cell_floor(lo.y - kMarginM);
  const int last_x = cell_ceil(hi.x + kMarginM), last_y = cell_ceil(hi.y + kMarginM);
  const double cells = (last_x - first_x + 1.0) * (last_y - first_y + 1.0);
  if (cells > kMaxCells) {
    throw std::invalid_argument("RasterizeWorld: " + WorldName(world) + " would need " + std::to_string(cells) +
                                " cells at resolution " + std::to_string(resolution_m) + " m (at most " +
                                std::to_string(kMaxCells) + ")");
  }
  OccupancyGrid grid(last_x - first_x + 1, last_y - first_y + 1, resolution_m,
                     {(first_x - 0.5) * resolution_m, (first_y - 0.5) * resolution_m, 0.0});
  for (const Surface& s : world.surfaces) {
    if (SpansHeight(s, laser_height_m)) DrawSegment(s.segment, &grid);
  }
  int start_x = 0, start_y = 0;
  grid.WorldToCell(world.start_pose.Position(), &start_x, &start_y);  // inside: the bounds include it
  if (grid.At(start_x, start_y) != OccupancyGrid::kUnknown) {
    std::ostringstream out;
    out << "RasterizeWorld: " << WorldName(world) << ": the robot start (" << world.start_pose.x_m << ", "
        << world.start_pose.y_m << ") lies on a surface at resolution " << resolution_m << " m";
    throw std::invalid_argument(out.str());
  }
  FloodFree(world, laser_height_m, start_x, start_y, &grid);
  return grid;
}

TextMap GroundTruthTextMap(const World& world) {
  TextMap map;
  for (const TextSign* sign : world.Plates()) {
    TextLandmark landmark;
    landmark.text = sign->text;
    const Vec2 position = world.SignPosition(*sign);
    const Vec2 facing = world.WallNormal(sign->wall_index, sign->corridor_side_left);
    landmark.pose = {position.x, position.y, std::atan2(facing.y, facing.x)};
    landmark.height_m = sign->center_height_m;
    landmark.wall = world.walls.at(sign->wall_index).id;
    landmark.observations = 0;
    map.landmarks.push_back(landmark);
  }
  ComputeAdjacentDistances(&map);
  return map;
}

}  // namespace doorplate_localization

// Tiny worlds built in code for the localizer tests: occupancy grids, text maps, ray-cast scans and a
// robot driving down a corridor reading the plates on its left.
#pragma once

#include <cmath>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/mcl/grid_ray_caster.h"
#include "doorplate_localization/mcl/localization_grid.h"
#include "doorplate_localization/sensors/plate_reading.h"
#include "doorplate_localization/mcl/localization_scan.h"

namespace doorplate_localization::test {

// A grid covering [x0, x0 + width_m] × [y0, y0 + height_m], every cell `fill`. (Built field by field:
// these tests do not need doorplate_maps.)
inline OccupancyGrid MakeGrid(double x0, double y0, double width_m, double height_m, double resolution_m = 0.05,
                              std::int8_t fill = OccupancyGrid::kUnknown) {
  OccupancyGrid g;
  g.resolution_m = resolution_m;
  g.origin = {x0, y0, 0.0};
  g.width = static_cast<int>(std::lround(width_m / resolution_m));
  g.height = static_cast<int>(std::lround(height_m / resolution_m));
  g.cells.assign(static_cast<size_t>(g.width) * g.height, fill);
  return g;
}

// Sets every cell whose centre lies in [x0, x1] × [y0, y1] (map frame, axis-aligned grid).
inline void FillRect(OccupancyGrid* g, double x0, double y0, double x1, double y1, std::int8_t value) {
  for (int y = 0; y < g->height; ++y) {
    for (int x = 0; x < g->width; ++x) {
      const double cx = g->origin.x_m + (x + 0.5) * g->resolution_m, cy = g->origin.y_m + (y + 0.5) * g->resolution_m;
      if (cx >= x0 && cx <= x1 && cy >= y0 && cy <= y1) g->cells[static_cast<size_t>(y) * g->width + x] = value;
    }
  }
}

// A closed room [0, w] × [0, h] with 0.1 m walls and an inner box at (2..2.6, 1..1.4): asymmetric, so a
// scan pins the pose.
inline OccupancyGrid AsymmetricRoom(double w = 6.0, double h = 4.0) {
  OccupancyGrid g = MakeGrid(-0.5, -0.5, w + 1.0, h + 1.0);
  FillRect(&g, -0.1, -0.1, w + 0.1, h + 0.1, OccupancyGrid::kOccupied);
  FillRect(&g, 0.0, 0.0, w, h, OccupancyGrid::kFree);
  FillRect(&g, 2.0, 1.0, 2.6, 1.4, OccupancyGrid::kOccupied);
  FillRect(&g, w - 1.2, h - 0.8, w, h, OccupancyGrid::kOccupied);  // a cupboard in one corner
  return g;
}

// A long corridor [0, length] × [0, width] with thick walls and door recesses (1 m wide, 0.3 m deep)
// at the same x on both walls every `period_m` from 1.5 m: symmetric under a half turn about its centre
// and, away from its ends, periodic — a laser cannot tell where along it the robot is. Plates: on the
// south wall 0.3 m west of each door facing north (texts 101, 103, ...), on the north wall 0.3 m east of
// each door facing south (102, 104, ...); the half turn maps each south plate onto a north plate.
struct SymmetricCorridor {
  double length_m = 40.0;
  double width_m = 2.0;
  double period_m = 4.0;
  std::vector<double> door_x;  // west edge of each door
  OccupancyGrid occupancy;
  std::shared_ptr<LocalizationGrid> grid;
  std::shared_ptr<TextMap> text_map;

  int NorthPlate(int door) const { return 2 * door + 1; }  // landmark index of a door's north plate
  int SouthPlate(int door) const { return 2 * door; }
  // The pose's image under the half turn about the corridor centre.
  Pose2D HalfTurn(const Pose2D& p) const {
    return {length_m - p.x_m, width_m - p.y_m, NormalizeAngle(p.theta_rad + M_PI)};
  }
};

inline SymmetricCorridor MakeSymmetricCorridor(double length_m = 40.0, double width_m = 2.0, double period_m = 4.0) {
  SymmetricCorridor c;
  c.length_m = length_m;
  c.width_m = width_m;
  c.period_m = period_m;
  const double depth = 0.3, door_w = 1.0;
  OccupancyGrid g = MakeGrid(-0.6, -0.6, length_m + 1.2, width_m + 1.2);
  FillRect(&g, -0.1, -depth - 0.1, length_m + 0.1, width_m + depth + 0.1, OccupancyGrid::kOccupied);
  FillRect(&g, 0.0, 0.0, length_m, width_m, OccupancyGrid::kFree);
  auto map = std::make_shared<TextMap>();
  for (double a = 1.5; a + door_w <= length_m - 1.0 + 1e-9; a += period_m) {
    const int k = static_cast<int>(c.door_x.size());
    c.door_x.push_back(a);
    FillRect(&g, a, -depth, a + door_w, 0.0, OccupancyGrid::kFree);
    FillRect(&g, a, width_m, a + door_w, width_m + depth, OccupancyGrid::kFree);
    TextLandmark south, north;
    south.text = std::to_string(101 + 2 * k);
    south.pose = {a - 0.3, 0.0, M_PI / 2};
    south.wall = "south";
    north.text = std::to_string(102 + 2 * k);
    north.pose = {a + door_w + 0.3, width_m, -M_PI / 2};
    north.wall = "north";
    map->landmarks.push_back(south);
    map->landmarks.push_back(north);
  }
  c.grid = std::make_shared<LocalizationGrid>(g);
  c.occupancy = std::move(g);
  c.text_map = map;
  return c;
}

// 360 beams over the full circle, 0.1 .. 8 m, laser 0.1 m ahead of base_link.
inline LaserScan ScanGeometry(double max_range_m = 8.0) {
  LaserScan s;
  s.angle_min_rad = -M_PI;
  s.angle_increment_rad = 2.0 * M_PI / 360.0;
  s.min_range_m = 0.1;
  s.max_range_m = max_range_m;
  s.laser_pose = {0.1, 0.0, 0.0};
  return s;
}

// A ray-cast scan from `robot`, with Gaussian range noise when `rng` is given.
inline LaserScan SyntheticScan(const LocalizationGrid& grid, const Pose2D& robot, std::mt19937_64* rng = nullptr,
                               double noise_m = 0.01, double max_range_m = 8.0) {
  LaserScan scan = CastScan(grid, robot, ScanGeometry(max_range_m), 360);
  if (rng != nullptr) {
    std::normal_distribution<double> noise(0.0, noise_m);
    for (float& r : scan.ranges_m) {
      if (std::isfinite(r)) r = static_cast<float>(std::max(0.11, r + noise(*rng)));
    }
  }
  return scan;
}

// The reading a left-looking camera makes of `plate` from `robot` (bearing and range exact).
inline PlateReading ReadingOf(const TextLandmark& plate, const Pose2D& robot, double confidence = 0.9,
                              bool with_range = true) {
  const Pose2D rel = robot.Between(plate.pose);
  PlateReading r;
  r.text = plate.text;
  r.confidence = confidence;
  r.bearing_rad = std::atan2(rel.y_m, rel.x_m);
  if (with_range) r.range_m = std::hypot(rel.x_m, rel.y_m);
  r.camera_side = CameraSide::kLeft;
  return r;
}

// Index of the plate that comes abeam on the robot's left while it moves from `before` to `after`
// (the plate's x in the robot frame changes sign from > 0 to <= 0, plate on the left within 3 m), or -1.
inline int PlateComingAbeam(const TextMap& map, const Pose2D& before, const Pose2D& after) {
  for (size_t i = 0; i < map.landmarks.size(); ++i) {
    const Pose2D a = before.Between(map.landmarks[i].pose), b = after.Between(map.landmarks[i].pose);
    if (a.x_m > 0.0 && b.x_m <= 0.0 && b.y_m > 0.0 && std::hypot(b.x_m, b.y_m) < 3.0) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace doorplate_localization::test

#include "floor_measure.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "doorplate_localization/mcl/grid_ray_caster.h"
#include "doorplate_localization/mcl/localization_grid.h"
#include "doorplate_localization/sim/ground_truth_maps.h"
#include "map_measure.h"
#include "stats.h"

namespace doorplate_localization {
namespace {

// Rays in the grid's map frame, from world-frame origins and directions.
class GridRays {
 public:
  GridRays(const OccupancyGrid& grid, const Pose2D& world_from_grid, bool unknown_blocks, double unmapped_run_m)
      : grid_(grid), grid_from_world_(world_from_grid.Inverse()), unknown_blocks_(unknown_blocks),
        unmapped_run_m_(unmapped_run_m) {}

  // Distance from world point `origin` along world direction `angle_rad` to the near face of the first
  // blocking cell; nullopt if the ray runs out of the grid or past `max_range_m`, or starts in a blocking
  // cell, or (`through_known_only`) runs on for more than unmapped_run_m past the first unknown cell: a
  // gap in a wall of the map is not a way through it (an unknown cell at a wall's face is tolerated).
  std::optional<double> Cast(Vec2 origin, double angle_rad, double max_range_m, bool through_known_only = false) const {
    const Vec2 o = grid_from_world_.TransformPoint(origin);
    const double angle = angle_rad + grid_from_world_.theta_rad;
    const double r = CastRay(grid_, o, angle, max_range_m, unknown_blocks_);
    if (through_known_only && !unknown_blocks_ &&
        r - CastRay(grid_, o, angle, max_range_m, true) > unmapped_run_m_) {
      return std::nullopt;
    }
    if (!(r > 0.0) || r >= max_range_m) return std::nullopt;
    // CastRay also stops at the grid's edge: accept only a ray whose next cell is in the grid and blocks.
    const double step = r + 1e-3 * grid_.resolution_m();
    int x = 0, y = 0;
    if (!grid_.PointToCell(o + step * Vec2{std::cos(angle), std::sin(angle)}, &x, &y)) return std::nullopt;
    const CellState state = grid_.State(x, y);
    if (state == CellState::kOccupied || (unknown_blocks_ && state == CellState::kUnknown)) return r;
    return std::nullopt;
  }

  double Diagonal() const { return (grid_.width() + grid_.height()) * grid_.resolution_m(); }

 private:
  LocalizationGrid grid_;
  Pose2D grid_from_world_;
  bool unknown_blocks_;
  double unmapped_run_m_;
};

CorridorMeasure MeasureOne(const GridRays& rays, const CorridorSpec& corridor, const CorridorMeasureOptions& options) {
  CorridorMeasure m;
  m.id = corridor.id;
  const Vec2 a = corridor.centreline.a, d = corridor.centreline.b - a;
  const double length = Norm(d);
  const double heading = std::atan2(d.y, d.x);
  const Vec2 mid = a + 0.5 * d;
  const auto ahead = rays.Cast(mid, heading, rays.Diagonal(), /*through_known_only=*/true);
  const auto behind = rays.Cast(mid, heading + M_PI, rays.Diagonal(), /*through_known_only=*/true);
  if (ahead && behind) m.length_m = *ahead + *behind;

  const double max_section_m = options.max_section_factor * corridor.width_m;
  const int sections = std::max(1, static_cast<int>(std::lround(length / options.section_step_m)));
  std::vector<double> widths;
  for (int k = 0; k < sections; ++k) {
    const Vec2 p = a + ((k + 0.5) / sections) * d;
    const auto left = rays.Cast(p, heading + M_PI / 2, max_section_m);
    const auto right = rays.Cast(p, heading - M_PI / 2, max_section_m);
    if (left && right && *left + *right <= max_section_m) widths.push_back(*left + *right);
  }
  m.cross_sections = sections;
  m.cross_sections_used = static_cast<int>(widths.size());
  if (!widths.empty()) m.width_m = Median(widths);
  m.ok = ahead && behind && !widths.empty();
  return m;
}

}  // namespace

std::vector<CorridorMeasure> MeasureCorridors(const OccupancyGrid& grid, const std::vector<CorridorSpec>& corridors,
                                              const Pose2D& world_from_grid, const CorridorMeasureOptions& options) {
  if (!(options.section_step_m > 0.0)) {
    throw std::invalid_argument("MeasureCorridors: section_step_m must be > 0, got " +
                                std::to_string(options.section_step_m));
  }
  if (!(options.max_section_factor > 0.0)) {
    throw std::invalid_argument("MeasureCorridors: max_section_factor must be > 0, got " +
                                std::to_string(options.max_section_factor));
  }
  const GridRays rays(grid, world_from_grid, options.unknown_blocks, options.max_unmapped_run_m);  // throws for an empty grid
  std::vector<CorridorMeasure> out;
  for (const CorridorSpec& corridor : corridors) out.push_back(MeasureOne(rays, corridor, options));
  return out;
}

std::vector<CorridorAccuracy> CompareCorridors(const OccupancyGrid& mapped, const Pose2D& world_from_map,
                                               const OccupancyGrid& truth,
                                               const std::vector<CorridorSpec>& corridors,
                                               const CorridorMeasureOptions& options) {
  const std::vector<CorridorMeasure> est = MeasureCorridors(mapped, corridors, world_from_map, options);
  const std::vector<CorridorMeasure> ref = MeasureCorridors(truth, corridors, Pose2D{}, options);
  std::vector<CorridorAccuracy> out;
  for (std::size_t i = 0; i < corridors.size(); ++i) {
    CorridorAccuracy acc;
    acc.id = corridors[i].id;
    acc.mapped = est[i];
    acc.truth = ref[i];
    acc.ok = est[i].ok && ref[i].ok;
    if (acc.ok) {
      acc.length_accuracy = ExtentAccuracy(est[i].length_m, ref[i].length_m);
      acc.width_accuracy = ExtentAccuracy(est[i].width_m, ref[i].width_m);
    }
    out.push_back(acc);
  }
  return out;
}

std::vector<CorridorAccuracy> CompareCorridorsWithWorld(const OccupancyGrid& mapped, const Pose2D& world_from_map,
                                                        const World& world, const CorridorMeasureOptions& options) {
  if (world.corridors.empty()) return {};
  const OccupancyGrid truth = RasterizeWorld(world, mapped.resolution_m, world.sensors.laser.mount_height_m);
  return CompareCorridors(mapped, world_from_map, truth, world.corridors, options);
}

}  // namespace doorplate_localization

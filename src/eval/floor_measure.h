// Per-corridor measurements of a floor map (issue 17): each corridor of a world's `corridors` ground truth
// (centreline + nominal width, world frame) measured on an occupancy grid by casting rays through it, and
// the same measurements on the world's ground-truth grid for accuracies. Metres throughout.
#pragma once

#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

struct CorridorMeasureOptions {
  double section_step_m = 0.25;     // spacing of the width cross-sections along the centreline (> 0)
  // A cross-section whose two rays add up to more than this × the nominal width (or whose rays do not both
  // end on an occupied cell within it) looks into an open door, a junction or an unmapped gap: skipped.
  double max_section_factor = 2.0;
  bool unknown_blocks = false;      // true: unknown cells stop rays like occupied ones
  // A length ray that runs on for more than this past an unknown cell passed through a gap in a wall of
  // the map: not measured.
  double max_unmapped_run_m = 0.2;
};

// One corridor measured on one grid. Rays are cast on the grid (src/mcl/grid_ray_caster: cell traversal,
// distances to the near face of the first blocking cell). A ray counts only if it ends on an occupied
// cell (unknown too with unknown_blocks) and its origin cell does not block; rays leaving the grid do not.
//  length: from the centreline's midpoint along +direction and −direction, the sum of the two ray
//    distances (through junctions and corners up to the walls that end the straight line of sight). A
//    length ray that runs on for more than max_unmapped_run_m past an unknown cell is not measured (ok =
//    false): on a SLAM map that is a gap in a wall (seen: one unmapped cell of a courtyard wall), not a
//    corridor's end; an unknown cell at a wall's face is tolerated.
//  width: the median over cross-sections (centres of `section_step_m` pieces of the centreline) of the sum
//    of the two perpendicular ray distances, skipping sections as described above.
struct CorridorMeasure {
  std::string id;
  bool ok = false;                // length measured (both rays hit) and at least one cross-section used
  double length_m = 0.0;          // 0 if a length ray did not hit
  double width_m = 0.0;           // 0 if no cross-section was used
  int cross_sections = 0;         // tried
  int cross_sections_used = 0;
};

// `world_from_grid` maps the grid's map frame (the frame of its origin pose) to the world frame in which
// the corridors are given: identity for a ground-truth grid, the start-pose alignment for a SLAM map.
// One result per corridor, in order. Throws std::invalid_argument for an empty grid or bad options.
std::vector<CorridorMeasure> MeasureCorridors(const OccupancyGrid& grid, const std::vector<CorridorSpec>& corridors,
                                              const Pose2D& world_from_grid,
                                              const CorridorMeasureOptions& options = {});

// A mapped corridor against the same corridor measured on the ground-truth grid.
struct CorridorAccuracy {
  std::string id;
  bool ok = false;                // both measures ok
  CorridorMeasure mapped;
  CorridorMeasure truth;
  double length_accuracy = 0.0;   // 1 − |mapped − truth| / truth (ExtentAccuracy); 0 unless ok
  double width_accuracy = 0.0;
};

// Measures every corridor on `mapped` (placed by `world_from_map`) and on `truth` (a grid in the world
// frame, e.g. RasterizeWorld's), and compares them.
std::vector<CorridorAccuracy> CompareCorridors(const OccupancyGrid& mapped, const Pose2D& world_from_map,
                                               const OccupancyGrid& truth,
                                               const std::vector<CorridorSpec>& corridors,
                                               const CorridorMeasureOptions& options = {});

// The same with the truth rasterized from `world` (RasterizeWorld at the mapped grid's resolution and the
// world's laser mount height). Empty if the world has no `corridors`.
std::vector<CorridorAccuracy> CompareCorridorsWithWorld(const OccupancyGrid& mapped, const Pose2D& world_from_map,
                                                        const World& world,
                                                        const CorridorMeasureOptions& options = {});

}  // namespace doorplate_localization

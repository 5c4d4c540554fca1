// Ground-truth maps of a simulator world, in the world frame (= the map frame): the occupancy grid the
// laser would map, and the text-landmark map of its doorplates. For localization experiments without a
// mapping run, and to score maps built by SLAM.
#pragma once

#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"
#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

// Rasterizes the static surfaces that span `laser_height_m` (z_min <= h <= z_max; clutter and glass
// included, people left out) as occupied cells: each surface
// is every cell it passes through (a 4-connected line), so a closed outline stays closed both for flood
// fills and for rays stepping diagonally from cell to cell (Bresenham) on the grid. Cells
// reachable from the robot start without crossing an occupied cell are free; everything else is unknown.
// The grid covers the surfaces plus a 0.5 m margin; its origin is offset by half a cell so that points on
// multiples of `resolution_m` (walls at round coordinates) are cell centres. Throws std::invalid_argument
// for a resolution <= 0, a world without surfaces (BuildSurfaces not called) or a start on a surface, and
// std::runtime_error when the reachable area is not closed (it reaches the grid border).
OccupancyGrid RasterizeWorld(const World& world, double resolution_m, double laser_height_m);

// The text map of every doorplate (TextKind::kPlate; distractors are not landmarks): text, position =
// World::SignPosition, yaw = the direction the plate faces (its wall's normal on the plate's side), plate
// centre height, wall = the wall's id, observations 0; `adjacent` from ComputeAdjacentDistances.
// occupancy_map is left empty for the caller.
TextMap GroundTruthTextMap(const World& world);

}  // namespace doorplate_localization

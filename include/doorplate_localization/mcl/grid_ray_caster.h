// Ray casting on a LocalizationGrid (Amanatides–Woo cell traversal): the beam model's expected ranges,
// line-of-sight checks for doorplates, and synthetic scans in tests.
#pragma once

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/mcl/localization_grid.h"
#include "doorplate_localization/mcl/localization_scan.h"

namespace doorplate_localization {

// Distance in metres from map point `origin` along heading `angle_rad` to the boundary of the first
// cell that blocks the ray: an occupied cell, an unknown one when `unknown_blocks` (amcl's rule), or
// the edge of the grid (amcl stops rays there too). Returns max_range_m if nothing blocks within it,
// and 0 if the origin's own cell blocks or lies outside the grid.
double CastRay(const LocalizationGrid& grid, Vec2 origin, double angle_rad, double max_range_m,
               bool unknown_blocks = true);

// True if the straight segment from `from` to `to` crosses no blocking cell before reaching within
// `tolerance_m` of `to` (so a target standing on a wall surface is visible).
bool HasLineOfSight(const LocalizationGrid& grid, Vec2 from, Vec2 to, double tolerance_m,
                    bool unknown_blocks = true);

// Noise-free scan of the grid seen by a laser mounted at `scan_geometry.laser_pose` on a robot at
// `robot_pose` (map frame): one beam per `num_beams` from the geometry's angle_min/increment, +inf
// where nothing blocks within max_range_m (REP-117). Ranges/laser pose are copied from the template.
LaserScan CastScan(const LocalizationGrid& grid, const Pose2D& robot_pose, const LaserScan& scan_geometry,
                   int num_beams, bool unknown_blocks = true);

}  // namespace doorplate_localization

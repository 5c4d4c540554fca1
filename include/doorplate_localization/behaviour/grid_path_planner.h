// A path over the occupancy grid from the robot to a goal anywhere on the floor (issue 17: go to any room,
// round corners). A* on the grid's cells (8-connected) with a step cost that grows near walls, so paths keep
// a hard clearance from obstacles and run down the corridors' middles and round corners on a wide arc.
//
// Cost: a cell's clearance c is its distance to the nearest obstacle cell (OpenCV's exact Euclidean
// distance transform). Cells with c < clearance_m are forbidden, except within clearance_m of the start and
// of the goal (a robot or a goal close to a wall may leave or reach it); a step of length l into a cell
// costs l · (1 + wall_cost_weight · ((preferred_clearance_m − c) / (preferred_clearance_m − clearance_m))²)
// when c < preferred_clearance_m, else l. The heuristic (straight-line distance) is admissible, so the path
// is the cheapest under that cost. Obstacles: cells >= occupied_threshold, and unknown cells (−1) unless
// unknown_is_free.
//
// Why not MRPT's mrpt::nav::PlannerSimple2D (tried first; bench/planner_bench.cpp, numbers in
// docs/results/floor-goto.md): fast enough on the ring map (0.05–0.41 s per query on the loaded 2-core
// machine, 0.02 s for the grid conversion), but it is a wavefront for the SHORTEST path with obstacles grown
// by robotRadius, so its paths hug the grown obstacles on the inside of every bend and along the courtyard
// walls: on four long queries, minimum clearance = robotRadius (+ up to 0.1 m) and mean clearance
// 0.46–0.88 m for robotRadius 0.3–0.6 m, in 2 m corridors whose middle is 1.0 m from the walls. A
// robotRadius big enough to centre it (0.8 m) refuses the door goals, 0.6 m from their wall ("no path" for 2
// of the 4 queries). This planner takes 0.02–0.09 s per query on the same map and machine (1161 × 861 cells;
// 0.07 s for the clearance image) and keeps the middle: mean clearance 1.00 m, minimum 0.60 m (the door
// goals' own distance from their wall).
//
// Frames and units: the grid's map frame (maps/occupancy_grid.h), metres. The grid is copied into the
// clearance image once, at construction; Plan may then be called any number of times.
#pragma once

#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"

namespace doorplate_localization {

struct GridPathPlannerOptions {
  double robot_radius_m = 0.2;          // a start or goal closer than this to an obstacle is refused
  double clearance_m = 0.4;             // the path keeps at least this (start and goal neighbourhoods aside)
  double preferred_clearance_m = 1.0;   // no extra cost beyond this distance from obstacles (a 2 m corridor's middle)
  double wall_cost_weight = 8.0;        // extra cost factor at clearance_m (quadratic down to 0 at preferred)
  int occupied_threshold = 50;          // cells with value >= this are obstacles (0 free .. 100 occupied)
  bool unknown_is_free = false;         // unknown cells (−1): obstacles unless set
  double waypoint_spacing_m = 0.1;      // the returned path is resampled to about this spacing
};

struct GridPath {
  bool found = false;
  std::string failure;                 // set when !found: "start ...", "goal inside an obstacle ...", "no path ..."
  std::vector<Vec2> waypoints;         // map frame, from the start position to the goal position (both exact)
  double length_m = 0.0;
  double min_clearance_m = 0.0;        // smallest obstacle distance of the path's cells
  double mean_clearance_m = 0.0;
  long long expanded_cells = 0;
  double plan_seconds = 0.0;           // wall clock of Plan
};

class GridPathPlanner {
 public:
  // Throws std::invalid_argument naming the field of an invalid option, or "grid" for an empty grid or a
  // cell count that does not match width × height.
  GridPathPlanner(const GridPathPlannerOptions& options, const OccupancyGrid& grid);

  // The path from `start` to `goal` (map frame). Refused (found = false) when either lies outside the grid
  // or closer than robot_radius_m to an obstacle, or when no cell chain with the clearance links them.
  GridPath Plan(Vec2 start, Vec2 goal) const;

  // Distance from the cell containing `p` to the nearest obstacle, metres (0 outside the grid).
  double ClearanceAt(Vec2 p) const;

  const GridPathPlannerOptions& options() const { return options_; }
  const OccupancyGrid& grid() const { return grid_; }

 private:
  double StepFactor(double clearance_m) const;

  const GridPathPlannerOptions options_;
  const OccupancyGrid grid_;
  std::vector<float> clearance_m_;  // per cell, row-major as the grid
};

}  // namespace doorplate_localization

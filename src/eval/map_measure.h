// Measurements of a SLAM result for `doorplate_eval map` (paper Table II): the corridor's length and width
// read off an occupancy grid, and the mapped plates against the world's plates.
#pragma once

#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"

namespace doorplate_localization {

// Length and width of a straight corridor in its own grid, without ground truth. The corridor axis is the
// principal axis of the occupied cells (u along it, v across). Length: between the two end walls, each
// the median u of the occupied cells within `end_band_m` of that end (the end is the 0.5 % / 99.5 %
// quantile of u, so a few stray cells do not move it), refined to the mean of its cells within 0.15 m of
// that median (a wall mapped two cells thick has its surface between them; the median alone jumps by a
// cell). Width: the centre line lies halfway between the 5 % and 95 % quantiles of v (cells within
// `end_band_m` of either end left out); each side wall is a line v = a + b·u fitted to the cells on its side
// (least squares on the cells within 0.15 m of their median, then of that line), and the width is the
// distance between the two lines at the corridor's middle. So a wall mapped thicker at one end than at the
// other neither tilts nor shifts it. Cell centres are used; metres. ok = false if the grid has fewer than
// 20 occupied cells. Rooms behind open doors lie beyond the side walls and swamp those fits: the width is
// then meaningless (docs/results/table2-map.md).
struct CorridorExtent {
  bool ok = false;
  double length_m = 0.0;
  double width_m = 0.0;
  Vec2 axis;                // unit vector along the corridor, grid frame
};
CorridorExtent MeasureCorridor(const OccupancyGrid& grid, double end_band_m = 0.3);

// The same extent of a world's wall segments (surfaces, no cells): the principal axis of their endpoints,
// length and width = the extents along and across it.
CorridorExtent MeasureSegments(const std::vector<Segment>& walls);

// 1 − |estimate − truth| / truth (Table II's "accuracy"); 0 if truth <= 0.
double ExtentAccuracy(double estimate_m, double truth_m);

// The out leg of a drive as the SLAM estimated it: from the first pose to the pose farthest from it in
// truth (the turn at the corridor's far end), the straight-line distance between the two estimated poses
// against that between the true ones. This is the corridor's length as the trajectory has it; the grid's
// extent (MeasureGrid) can hide a shrunk corridor that the out and back legs drew twice, offset (a laser-only
// filter that lost metres along a featureless corridor maps its start wall again where it believes it came
// back). `estimated` and `truth`: the same poses (e.g. per processed scan), any common frame for each.
struct OutLeg {
  int turn_index = -1;      // index of the farthest true pose (-1: fewer than two poses)
  double true_m = 0.0;
  double estimated_m = 0.0;
  double accuracy = 0.0;    // ExtentAccuracy(estimated_m, true_m)
};
OutLeg MeasureOutLeg(const std::vector<Pose2D>& estimated, const std::vector<Pose2D>& truth);

// Mapped plates against the true ones. `world_from_map` takes map-frame positions into the world frame.
// A mapped plate matches the nearest true plate with the same text within `match_radius_m` (each true
// plate at most once, nearest pairs first). Errors are world-frame distances.
struct PlateScore {
  int plates_true = 0;
  int plates_in_map = 0;
  int plates_mapped = 0;            // matched
  double rmse_m = 0.0;              // over matched plates (0 if none)
  double max_error_m = 0.0;
  std::vector<double> errors_m;     // per mapped plate in map order; -1 if unmatched
};
PlateScore ScorePlates(const TextMap& mapped, const TextMap& truth, const Pose2D& world_from_map,
                       double match_radius_m = 1.0);

}  // namespace doorplate_localization

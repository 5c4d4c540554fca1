// The arithmetic behind the mission report's pictures (report_figures.h), kept apart from the drawing so it
// can be tested: which map-frame windows the map is shown in (a long corridor folded into stacked
// segments), axis ticks, the magnification of plate-error arrows, the per-plate errors, and the particle
// spread log written by scripts/mission_progress.py. ROS-free; map frame = the saved map's frame, metres.
#pragma once

#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"

namespace doorplate_localization {

// An axis-aligned rectangle of the map frame, metres (x0 < x1, y0 < y1).
struct MapWindow {
  double x0_m = 0.0, y0_m = 0.0, x1_m = 0.0, y1_m = 0.0;
  double WidthM() const { return x1_m - x0_m; }
  double HeightM() const { return y1_m - y0_m; }
};

// The bounding box of the grid's known cells (free or occupied) in the map frame, or the whole grid if
// none is known. Throws std::invalid_argument for an empty grid.
MapWindow KnownExtent(const OccupancyGrid& grid);

struct FoldOptions {
  double width_px = 1600.0;      // each panel's width
  double margin_m = 1.0;         // added round the extent
  double overlap_m = 1.0;        // shared by neighbouring segments (a plate on a cut shows in both)
  double target_aspect = 1.5;    // width / height of the stacked panels the number of segments aims at
  int max_segments = 6;
  double max_px_per_m = 120.0;   // a small map is not blown up beyond this
};

// Windows drawn one above the other, all at px_per_m. A long extent (along x) is cut into equal segments
// so that the stack's width / height is nearest target_aspect (in log ratio); a 2-D floor stays one window.
struct FoldedLayout {
  std::vector<MapWindow> windows;   // first = leftmost part of the map, drawn at the top
  double px_per_m = 0.0;
};
// Throws std::invalid_argument for an empty extent or options out of range (naming the field).
FoldedLayout FoldExtent(const MapWindow& extent, const FoldOptions& options = {});

// Tick values in [lo, hi] at a step of 1, 2 or 5 times a power of ten, at most max_count of them (>= 2).
std::vector<double> NiceTicks(double lo, double hi, int max_count);

// The largest of 1, 2, 5, 10, 20, 50, ... (at most 1000) by which an error of max_error_m draws at most
// target_length_m long; 1 when max_error_m <= 0.
double ArrowMagnification(double max_error_m, double target_length_m);

// One true plate and the mapped plate matched to it (map frame).
struct PlateErrorRow {
  std::string text;          // as in the true map
  Vec2 truth;                // the true plate, taken into the map frame
  bool mapped = false;       // a mapped plate with the same room id within the match radius
  Vec2 estimate;             // the mapped plate (when mapped)
  double error_m = -1.0;     // |estimate - truth| (when mapped), else -1
};
// Pairs mapped and true plates as ScorePlates does (same canonical room id, within match_radius_m, nearest
// pairs first, each plate once). Rows in the true map's order.
std::vector<PlateErrorRow> PairPlates(const TextMap& mapped, const TextMap& truth, const Pose2D& map_from_world,
                                      double match_radius_m = 1.0);

// One row of the localization progress log (scripts/mission_progress.py --csv).
struct SpreadSample {
  double sim_time_s = 0.0;
  double driven_m = 0.0;     // odometry path length since the localization run started
  double spread_m = 0.0;     // RMS distance of the particles from their mean
  int particles = 0;
  int plates_read = 0;
};
// Reads the log; throws std::runtime_error naming the file and line for a bad header or row.
std::vector<SpreadSample> ReadSpreadLog(const std::string& path);
// Distance driven at sim time t, linearly interpolated (held at the ends); samples sorted by time, not empty.
double DrivenAt(const std::vector<SpreadSample>& samples, double sim_time_s);

}  // namespace doorplate_localization

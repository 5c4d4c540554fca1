// The reference a real laser's readings are judged against (issue 20): an occupancy grid rendered from
// scans at known (SLAM-corrected) poses, plus the scan end points that made its occupied cells. A beam's
// expected range is the grid's ray cast, refined below the cell size by a line fitted (PCA) to the end
// points around the hit, whose normal also gives the beam's incidence angle.
// Frames and units: map frame, metres, radians; beam angles are map-frame headings.
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/mcl/localization_grid.h"
#include "doorplate_localization/sensors/laser_scan.h"
#include "doorplate_localization/slam/tiled_grid.h"

namespace doorplate_localization {

struct ReferenceMapOptions {
  double resolution_m = 0.05;
  double max_range_m = 40.0;          // longer readings (and no-returns) are not drawn into the grid
  double surface_radius_m = 0.15;     // end points this close to the grid hit fit the surface line
  int min_surface_points = 6;         // fewer: no surface fit
  double max_surface_rms_m = 0.03;    // points farther off their line on average: no surface fit (a corner)
  double max_refine_shift_m = 0.15;   // a line hit this far from the grid hit is not trusted
};

enum class ExpectedKind : std::uint8_t {
  kHit,      // the ray stops on an occupied cell within max range
  kNothing,  // the ray crosses only free cells up to max range
  kUnknown,  // the ray reaches an unknown cell or the grid's edge first, or starts outside free space
};

struct ExpectedBeam {
  ExpectedKind kind = ExpectedKind::kUnknown;
  double range_m = 0.0;        // kHit: distance to the surface (line fit if surface_fit, else the grid cell edge)
  double incidence_rad = 0.0;  // kHit with surface_fit: beam vs surface normal, [0, pi/2]
  bool surface_fit = false;    // kHit: a surface line was fitted at the hit
};

class ReferenceMap {
 public:
  // Throws std::invalid_argument naming the field of bad options.
  explicit ReferenceMap(const ReferenceMapOptions& options);

  // Draws one scan taken by a laser at `laser_in_map` (scan.laser_pose is ignored: the pose given is the
  // laser's own). Non-finite readings, readings below scan.min_range_m or beyond max_range_m are skipped.
  void AddScan(const Pose2D& laser_in_map, const LaserScan& scan);
  // Freezes the grid for Expect(); AddScan after this throws std::logic_error.
  void Finish();

  // What a beam from `origin` along map heading `angle_rad` should read, up to `max_range_m`.
  // Requires Finish().
  ExpectedBeam Expect(Vec2 origin, double angle_rad, double max_range_m) const;

  const OccupancyGrid& grid() const { return grid_; }
  const ReferenceMapOptions& options() const { return options_; }

 private:
  static std::int64_t Key(CellIndex c) { return (static_cast<std::int64_t>(c.x) << 32) ^ static_cast<std::uint32_t>(c.y); }
  // Fits a line to the end points near `p`; false if there are too few or they do not lie on a line.
  bool FitSurface(Vec2 p, Vec2* centroid, Vec2* normal) const;

  ReferenceMapOptions options_;
  TiledGrid tiled_;
  std::unordered_map<std::int64_t, std::vector<Vec2>> end_points_;  // per cell of the tiled grid
  OccupancyGrid grid_;
  std::unique_ptr<LocalizationGrid> cells_;
};

}  // namespace doorplate_localization

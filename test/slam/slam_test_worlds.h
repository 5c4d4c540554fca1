// Tiny synthetic worlds for the SLAM tests: walls as segments, an exact 2D laser, and maps built from
// known poses.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/sensors/laser_scan.h"
#include "doorplate_localization/slam/tiled_grid.h"

namespace doorplate_localization {
namespace test {

// A 6 m × 4 m room with a 0.5 m box off-centre (no symmetry), origin near the room's centre. Walls
// run through the centres of 5 cm cells, so the map holds them without quantization error.
inline std::vector<Segment> Room() {
  return {{{-3.025, -2.025}, {3.025, -2.025}}, {{3.025, -2.025}, {3.025, 2.025}},
          {{3.025, 2.025}, {-3.025, 2.025}}, {{-3.025, 2.025}, {-3.025, -2.025}},
          {{1.025, 0.525}, {1.525, 0.525}}, {{1.525, 0.525}, {1.525, 1.025}},
          {{1.525, 1.025}, {1.025, 1.025}}, {{1.025, 1.025}, {1.025, 0.525}}};
}

// A featureless corridor 2 m wide along x, far longer than the laser's range.
inline std::vector<Segment> Corridor() { return {{{-100, -1.025}, {100, -1.025}}, {{-100, 1.025}, {100, 1.025}}}; }

// A 40 m corridor 2 m wide along x from x = 0, with end walls.
inline std::vector<Segment> ClosedCorridor() {
  return {{{-0.525, -1.025}, {40.525, -1.025}}, {{-0.525, 1.025}, {40.525, 1.025}},
          {{-0.525, -1.025}, {-0.525, 1.025}}, {{40.525, -1.025}, {40.525, 1.025}}};
}

// Poses every `step_m` along x from `from_m` to `to_m`, heading 0: enough views that a map of a
// corridor holds its walls as continuous lines.
inline std::vector<Pose2D> PosesAlongX(double from_m, double to_m, double step_m) {
  std::vector<Pose2D> poses;
  for (double x = from_m; x <= to_m + 1e-9; x += step_m) poses.push_back({x, 0, 0});
  return poses;
}

// A 360° scan of `beams` beams from `pose`: +inf where nothing is within `max_range_m`.
inline LaserScan Scan(const std::vector<Segment>& walls, const Pose2D& pose, int beams = 360,
                      double max_range_m = 20.0) {
  LaserScan scan;
  scan.angle_min_rad = -M_PI;
  scan.angle_increment_rad = 2 * M_PI / beams;
  scan.min_range_m = 0.05;
  for (int i = 0; i < beams; ++i) {
    const double a = pose.theta_rad + scan.BeamAngle(i);
    double best = std::numeric_limits<double>::infinity();
    for (const Segment& s : walls) {
      if (const auto d = RaySegmentDistance(pose.Position(), {std::cos(a), std::sin(a)}, s)) {
        best = std::min(best, *d);
      }
    }
    scan.ranges_m.push_back(best <= max_range_m ? static_cast<float>(best)
                                                : std::numeric_limits<float>::infinity());
  }
  return scan;
}

// The scan's echoes as points in the laser (= base_link) frame.
inline std::vector<Vec2> Points(const LaserScan& scan) {
  std::vector<Vec2> points;
  for (int i = 0; i < static_cast<int>(scan.ranges_m.size()); ++i) {
    const double r = scan.ranges_m[i];
    if (std::isfinite(r)) points.push_back({r * std::cos(scan.BeamAngle(i)), r * std::sin(scan.BeamAngle(i))});
  }
  return points;
}

// A map of `walls` seen from `poses` (every echo integrated as a beam).
inline TiledGrid MapFrom(const std::vector<Segment>& walls, const std::vector<Pose2D>& poses,
                         const TiledGridOptions& options = {}) {
  TiledGrid map(options);
  for (const Pose2D& pose : poses) {
    for (const Vec2& p : Points(Scan(walls, pose))) {
      for (int k = 0; k < 2; ++k) map.IntegrateBeam(pose.Position(), pose.TransformPoint(p), true);
    }
  }
  return map;
}

}  // namespace test
}  // namespace doorplate_localization

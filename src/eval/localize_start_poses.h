// Random robot poses for the localization trials (start poses and kidnap targets): uniform over the main
// corridor, heading along it. The main corridor is the axis-aligned band through the world's start pose
// (worlds run their main corridor along x, docs/world-format.md) bounded by the nearest walls seen from
// the start pose straight ahead/behind (its ends) and left/right (its sides); alcoves, side rooms and
// open doors beyond those walls are not part of it.
// Frame: the world (= ground-truth map) frame. Units: metres, radians.
#pragma once

#include <random>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

struct CorridorBand {
  double x_min_m = 0.0, x_max_m = 0.0;  // end walls
  double y_min_m = 0.0, y_max_m = 0.0;  // side walls
};

// The band through world.start_pose, from rays cast along ±x and ±y against the world's surfaces at the
// laser's mounting height (surfaces must be built). Throws std::runtime_error naming the world when a
// ray hits nothing (an open-ended world has no band).
CorridorBand FindCorridorBand(const World& world);

struct StartPoseSamplerOptions {
  double end_margin_m = 0.6;        // keep this far from the end walls
  double wall_margin_m = 0.45;      // keep this far from the side walls (robot radius + slack)
  double heading_noise_rad = 0.35;  // heading = along the corridor (+x or -x, equal odds) + U(-this, this)
  double clearance_m = 0.3;         // every grid cell within this of the pose must be free
  double min_kidnap_distance_m = 3.0;  // a kidnap target is at least this far from the robot
  int max_attempts = 10000;
};

class StartPoseSampler {
 public:
  // `grid` is the ground-truth occupancy grid (0 free .. 100 occupied, -1 unknown), used to reject poses
  // near obstacles; it must outlive the sampler. Throws std::invalid_argument naming a bad option field,
  // or when the band left by the margins is empty.
  StartPoseSampler(const CorridorBand& band, const OccupancyGrid& grid, const StartPoseSamplerOptions& options);

  // A pose uniform over the band shrunk by the margins with free clearance. Throws std::runtime_error
  // after max_attempts rejected draws.
  Pose2D Sample(std::mt19937_64& rng) const;
  // As Sample, at least min_kidnap_distance_m from `current`.
  Pose2D SampleAwayFrom(const Pose2D& current, std::mt19937_64& rng) const;

  // Whether every grid cell within clearance_m of `p` is inside the grid and free (value 0..49).
  bool HasClearance(Vec2 p) const;

 private:
  const CorridorBand band_;
  const OccupancyGrid& grid_;
  const StartPoseSamplerOptions options_;
};

}  // namespace doorplate_localization

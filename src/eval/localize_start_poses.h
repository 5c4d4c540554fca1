// Random robot poses for the localization trials (start poses and kidnap targets), heading along a corridor.
// Two kinds of region:
//  - A floor (the world lists `corridors`, docs/world-format.md): a corridor is drawn with probability
//    proportional to its centreline's length, then a point uniform along its centreline (end_margin_m
//    from each end) and across its width (wall_margin_m from each side), heading along the centreline
//    either way. Corridors may overlap (a ring's corner squares); rooms behind open doors are never drawn.
//  - Otherwise the main corridor: the axis-aligned band through the world's start pose (worlds run their
//    main corridor along x) bounded by the nearest walls seen from the start pose straight ahead/behind
//    (its ends) and left/right (its sides); alcoves, side rooms and open doors beyond those walls are not
//    part of it. (The paper's Table III setting; its draws are unchanged since before floors existed.)
// Either way the heading gets uniform noise and every grid cell within clearance_m must be free.
// Frame: the world (= ground-truth map) frame. Units: metres, radians.
#pragma once

#include <random>
#include <string>
#include <vector>

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
  // A floor of corridors (at least one). Throws std::invalid_argument naming a bad option field, or the
  // corridor whose centreline is shorter than 2·end_margin_m or whose width is at most 2·wall_margin_m.
  StartPoseSampler(const std::vector<CorridorSpec>& corridors, const OccupancyGrid& grid,
                   const StartPoseSamplerOptions& options);

  // A pose uniform over the band (or, on a floor, over a length-weighted corridor) shrunk by the margins
  // with free clearance. Throws std::runtime_error after max_attempts rejected draws.
  Pose2D Sample(std::mt19937_64& rng) const;
  // As Sample, at least min_kidnap_distance_m from `current`.
  Pose2D SampleAwayFrom(const Pose2D& current, std::mt19937_64& rng) const;

  // Whether every grid cell within clearance_m of `p` is inside the grid and free (value 0..49).
  bool HasClearance(Vec2 p) const;

  // Whether poses are drawn over the floor's corridors (else over the band).
  bool on_floor() const { return !corridors_.empty(); }

 private:
  Pose2D SampleInBand(std::mt19937_64& rng) const;
  Pose2D SampleOnFloor(std::mt19937_64& rng) const;

  const CorridorBand band_;
  const OccupancyGrid& grid_;
  const StartPoseSamplerOptions options_;
  const std::vector<CorridorSpec> corridors_;  // empty: the band
  std::vector<double> cumulative_length_m_;    // lengths of corridors_[0..i], metres
};

// The sampler for `world`: over its `corridors` when it lists any, else over the band FindCorridorBand
// finds (world's surfaces must be built). Throws as the constructors and FindCorridorBand.
StartPoseSampler MakeStartPoseSampler(const World& world, const OccupancyGrid& grid,
                                      const StartPoseSamplerOptions& options);

}  // namespace doorplate_localization

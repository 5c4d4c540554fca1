// Correlative scan matching (Olson, "Real-time correlative scan matching", ICRA 2009) on a TiledGrid's
// distance field: the scan's points are scored at every pose of a window (translations on the cell
// lattice, rotations at a fixed step), minus a pose prior's penalty. Small windows are searched
// exhaustively; large ones coarse-to-fine (every second cell, a four times coarser angle step and half
// the points first, then the best few candidates at full resolution), which keeps a search over
// a whole turn affordable when odometry is very uncertain.
#pragma once

#include <array>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/slam/tiled_grid.h"

namespace doorplate_localization {

// Gaussian pose prior as a penalty in score units: ½ m² / κ with m² the Mahalanobis distance
// (isotropic position and heading variances), growing linearly instead of quadratically beyond
// `huber_sigmas` so that a scan that clearly disagrees with odometry can still win.
struct PosePrior {
  Pose2D mean;
  double inv_var_linear = 0.0;    // 1/m²
  double inv_var_angular = 0.0;   // 1/rad²
  double huber_sigmas = 2.0;
  double score_per_log_likelihood = 5.0;  // 1/κ
  double Penalty(double x_m, double y_m, double theta_rad) const;
};

// Half-widths of a correlative search window.
struct SearchWindow {
  double linear_m = 0.0;
  double angular_rad = 0.0;
};

class CorrelativeSearch {
 public:
  // `field` maps a cell's squared distance (TiledGrid::Dist2Cells) to its score in [0, 1].
  // Windows needing more than `exhaustive_budget` point lookups are searched coarse-to-fine.
  CorrelativeSearch(const std::array<float, 256>& field, double resolution_m, double angular_step_rad,
                    long exhaustive_budget = 400000);

  // The pose of the window around `centre` with the highest score − prior penalty.
  Pose2D Search(const TiledGrid& map, const std::vector<Vec2>& points, const Pose2D& centre,
                const SearchWindow& window, const PosePrior& prior) const;

 private:
  struct Candidate {
    Pose2D pose;
    double objective;
  };
  // Scores every translation (kx, ky) ∈ [-n, n]², stride `stride` cells, at heading `theta`, and
  // offers each to `best` (kept sorted, at most `keep`, near-duplicates merged).
  void ScoreHeading(const TiledGrid& map, const std::vector<Vec2>& points, const Vec2& centre,
                    double theta, int n, int stride, const PosePrior& prior, std::size_t keep,
                    std::vector<Candidate>* best) const;

  const std::array<float, 256>& field_;
  const double resolution_m_;
  const double angular_step_rad_;
  const long exhaustive_budget_;
};

}  // namespace doorplate_localization

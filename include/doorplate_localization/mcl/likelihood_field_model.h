// amcl's likelihood-field laser model (Thrun et al., Probabilistic Robotics, table 6.3): each beam end
// point is scored by its distance to the nearest occupied cell, pz = z_hit·exp(-d²/2σ²) + z_rand/max_range.
// The distance field comes from one OpenCV distance transform (cv::distanceTransform, exact Euclidean)
// at construction, stored as 16-bit fixed point (2 bytes per cell): a 4000 × 4000 map (200 m square at
// 5 cm) built in 0.4-0.8 s on one core of the shared development machine (bench/mcl_bench.cpp). Per scan,
// a table maps each distance step to the beam's contribution: a beam costs a transform and one lookup.
// Unknown cells are treated as amcl does: only occupied cells attract end points, and an end point
// outside the grid gets the maximum distance laser_likelihood_max_dist_m.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "doorplate_localization/mcl/laser_model.h"
#include "doorplate_localization/mcl/localization_grid.h"

namespace doorplate_localization {

struct LikelihoodFieldModelOptions {
  double z_hit = 0.95;                        // weight of the Gaussian around the nearest obstacle
  double z_rand = 0.05;                       // weight of uniform random readings (divided by max range)
  double sigma_hit_m = 0.2;                   // std dev of the end point's distance to the obstacle
  double laser_likelihood_max_dist_m = 2.0;   // distances are clamped here (amcl's default)
  BeamSelectionOptions beams;                 // laser_max_beams (60), laser_min/max_range_m overrides
  BeamCombination combination = BeamCombination::kAmclCubeSum;
  // Beam skipping (amcl's do_beamskip, meant for dynamic obstacles): a beam is used only if, for more
  // than beam_skip_threshold of the particles, its end point lies within beam_skip_distance_m of an
  // obstacle; if that leaves fewer than (1 - beam_skip_error_threshold) of the beams, every beam is used
  // (the filter has probably converged to a wrong pose). Unconverged particle sets hit that fallback.
  bool do_beamskip = false;
  double beam_skip_distance_m = 0.5;
  double beam_skip_threshold = 0.3;
  double beam_skip_error_threshold = 0.9;
};

class LikelihoodFieldModel : public LaserModel {
 public:
  // Builds the distance field. Throws std::invalid_argument naming the field of a bad option.
  LikelihoodFieldModel(std::shared_ptr<const LocalizationGrid> grid, const LikelihoodFieldModelOptions& options);

  void LogLikelihoods(const LaserScan& scan, const std::vector<Particle>& particles,
                      std::vector<double>* log_likelihoods) override;

  // Distance (m) from map point p to the nearest occupied cell's centre, clamped at
  // laser_likelihood_max_dist_m (also outside the grid); quantized to 1/16 of a cell.
  double ObstacleDistance(Vec2 p) const;
  // Beams that the last LogLikelihoods call used (after beam skipping), and how many it skipped.
  int last_used_beams() const { return last_used_beams_; }
  int last_skipped_beams() const { return last_skipped_beams_; }
  const LikelihoodFieldModelOptions& options() const { return options_; }

 private:
  static constexpr int kStepsPerCell = 16;  // fixed-point steps of the stored distances

  // Distance steps of every selected beam for one particle, into `steps` (size = beams).
  void EndPointSteps(const Pose2D& robot, const std::vector<double>& beam_x, const std::vector<double>& beam_y,
                     std::uint16_t* steps) const;

  const std::shared_ptr<const LocalizationGrid> grid_;
  const LikelihoodFieldModelOptions options_;
  std::uint16_t max_steps_ = 0;            // laser_likelihood_max_dist_m in steps
  std::vector<std::uint16_t> distance_steps_;  // per cell, min(distance, max) in 1/kStepsPerCell cells
  std::vector<std::uint16_t> scratch_steps_;   // particles × beams, for beam skipping
  int last_used_beams_ = 0;
  int last_skipped_beams_ = 0;
};

}  // namespace doorplate_localization

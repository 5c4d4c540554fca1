// amcl's beam range-finder model (Thrun et al., Probabilistic Robotics, table 6.1): each beam's reading
// is compared with the range ray-cast on the grid from the particle's laser pose, as a mixture of a
// Gaussian hit, an exponential short reading (unexpected obstacle), a max-range reading and a uniform
// random reading. Rays stop at occupied cells and, as in amcl, at unknown cells and the grid's edge.
#pragma once

#include <memory>
#include <vector>

#include "doorplate_localization/mcl/laser_model.h"
#include "doorplate_localization/mcl/localization_grid.h"

namespace doorplate_localization {

struct BeamModelOptions {
  double z_hit = 0.95;               // weights of the mixture's four parts (amcl defaults)
  double z_short = 0.1;
  double z_max = 0.05;
  double z_rand = 0.05;
  double sigma_hit_m = 0.2;          // std dev of a hit around the expected range
  double lambda_short_per_m = 0.1;   // rate of the exponential short-reading part
  BeamSelectionOptions beams;        // laser_max_beams (60), laser_min/max_range_m overrides
  BeamCombination combination = BeamCombination::kAmclCubeSum;
  bool unknown_blocks_rays = true;   // amcl: unknown cells stop the expected-range ray
};

class BeamModel : public LaserModel {
 public:
  // Throws std::invalid_argument naming the field of a bad option.
  BeamModel(std::shared_ptr<const LocalizationGrid> grid, const BeamModelOptions& options);

  // Max-range readings (+inf or >= max range, REP-117) are used: they score z_max where the ray cast
  // also reaches max range. NaN, -inf and below-min readings are skipped.
  void LogLikelihoods(const LaserScan& scan, const std::vector<Particle>& particles,
                      std::vector<double>* log_likelihoods) override;

  // The probability density of one reading given the expected range (amcl's pz, before combining).
  double BeamProbability(double measured_m, double expected_m, double max_range_m) const;

 private:
  const std::shared_ptr<const LocalizationGrid> grid_;
  const BeamModelOptions options_;
};

}  // namespace doorplate_localization

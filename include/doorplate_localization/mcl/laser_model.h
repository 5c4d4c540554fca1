// The laser measurement model interface: how likely a scan is from each particle's pose.
#pragma once

#include <string>
#include <vector>

#include "doorplate_localization/mcl/particle.h"
#include "doorplate_localization/mcl/localization_scan.h"

namespace doorplate_localization {

// How per-beam probabilities pz combine into the scan likelihood (amcl's laser_model_type variants).
enum class BeamCombination {
  // amcl's "beam" / "likelihood_field": p = 1 + Σ pz³, an ad-hoc score that keeps weights flat enough
  // for global localization with few particles (amcl's comment: "works well, though...").
  kAmclCubeSum,
  // amcl's "likelihood_field_prob": p = Π pz, the textbook independent-beam product (sharper).
  kProduct,
};

// "cube_sum" or "product". Throws std::invalid_argument naming beam_combination otherwise.
BeamCombination ParseBeamCombination(const std::string& name);

class LaserModel {
 public:
  virtual ~LaserModel() = default;

  // Fills `log_likelihoods` (resized to particles.size()) with log p(scan | particle pose) for every
  // particle, up to one additive constant that depends only on the model and the scan, so the values
  // compare across particles and, for the same model, across scans (Augmented MCL averages them).
  // Throws std::invalid_argument naming the field if the scan is unusable (ValidateLocalizationScan).
  virtual void LogLikelihoods(const LaserScan& scan, const std::vector<Particle>& particles,
                              std::vector<double>* log_likelihoods) = 0;
};

}  // namespace doorplate_localization

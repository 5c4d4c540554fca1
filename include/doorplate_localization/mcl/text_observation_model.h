// The text (doorplate) measurement model interface: how likely a plate reading is from each particle.
#pragma once

#include <vector>

#include "doorplate_localization/mcl/particle.h"
#include "doorplate_localization/sensors/plate_reading.h"

namespace doorplate_localization {

class TextObservationModel {
 public:
  virtual ~TextObservationModel() = default;

  // Fills `log_likelihoods` (resized to particles.size()) with log p(reading | particle pose), up to a
  // constant shared by all particles. Throws std::invalid_argument for an invalid reading.
  virtual void LogLikelihoods(const PlateReading& reading, const std::vector<Particle>& particles,
                              std::vector<double>* log_likelihoods) const = 0;

  // The log-likelihood (same constant) of a pose from which no compatible plate is visible: the
  // reading's "unexplained" level. A particle scoring well above it explains the reading.
  virtual double UnexplainedLogLikelihood(const PlateReading& reading) const = 0;
};

}  // namespace doorplate_localization

// Test fixture: FittedLaserErrorOptions with every effect off and 1 cm of noise; each test turns on what it
// looks at.
#pragma once

#include "doorplate_localization/sim/sensor_options.h"

namespace doorplate_localization::test {

inline FittedLaserErrorOptions QuietLaserErrors() {
  FittedLaserErrorOptions o;
  o.noise_base_m = 0.01, o.noise_fraction = 0.0, o.noise_grazing_gain = 0.0;
  o.dropout_probability = 0.0, o.dropout_per_m = 0.0, o.dropout_near_probability = 0.0;
  o.dropout_grazing_probability = 0.0, o.mixed_pixel_probability = 0.0, o.short_probability = 0.0;
  return o;
}

}  // namespace doorplate_localization::test

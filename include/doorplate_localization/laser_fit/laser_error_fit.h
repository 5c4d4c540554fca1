// Fits FittedLaserErrorOptions (the simulator's "fitted" laser error model) to a BeamTally of real scans
// (issue 20), and the robust statistics it rests on. Units: metres, degrees for incidence.
#pragma once

#include <vector>

#include "doorplate_localization/laser_fit/beam_tally.h"
#include "doorplate_localization/sim/sensor_options.h"

namespace doorplate_localization {

// Median and MAD-based sigma (1.4826 × median absolute deviation: the Gaussian sigma of the core, blind
// to a tail of outliers). Zeros for an empty input.
struct RobustSpread {
  double median = 0.0;
  double sigma = 0.0;
  long count = 0;
};
RobustSpread RobustSpreadOf(std::vector<float> values);

// Robust spread of the core errors per range bin and per incidence bin.
std::vector<RobustSpread> SpreadByRange(const BeamTally& tally, const std::vector<double>& edges_m);
std::vector<RobustSpread> SpreadByIncidence(const BeamTally& tally, const std::vector<double>& edges_deg);

struct LaserErrorFitOptions {
  long min_bin_samples = 100;                // range / incidence bins with fewer core returns are not fitted
  std::vector<double> noise_range_bins_m = {0, 1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 40};
  std::vector<double> noise_incidence_bins_deg = {0, 15, 30, 45, 55, 65, 75, 85};
  std::vector<double> grazing_onsets_deg = {30, 40, 50, 60, 65, 70, 75, 80};  // candidates for dropout_grazing_from_deg
  std::vector<double> near_ranges_m = {0.5, 0.75, 1.0, 1.5, 2.0};  // candidates for dropout_near_range_m
  double depth_edge_m = 0.3;                 // copied into the model (the tally's depth edge)
};

// The fitted parameters:
//  - noise: sigma(r) = sqrt(base² + (fraction·r)²) by least squares on the per-range-bin MAD sigmas²
//    (weighted by count), alternating with the grazing gain, fitted on per-incidence-bin MAD sigmas of the
//    errors divided by sigma(r);
//  - dropouts: the linear probability model p0 + p_r·r + p_near·[r < near] + p_g·ramp(i) by least squares
//    on every off-edge hit with a surface fit, `near` and the ramp's onset the candidates with the least
//    squared error, every coefficient >= 0;
//  - mixed pixels: mixed / the depth-edge beams' visible fractions (a mixed pixel within a gate of a
//    surface is not seen as one);
//  - short returns: p and the exponential's mean of p·(1 - exp(-cut / mean)), the chance that a beam has a
//    return short of `cut` (its expected range less the gate, `tally_options`), by least squares over
//    every beam that could have one (the mean from log-spaced candidates, 0.1-30 m).
// Throws std::invalid_argument if the tally holds no core return or no hit trial.
FittedLaserErrorOptions FitLaserErrors(const BeamTally& tally, const BeamTallyOptions& tally_options,
                                       const LaserErrorFitOptions& options);

}  // namespace doorplate_localization

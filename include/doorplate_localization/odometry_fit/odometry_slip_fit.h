// Fits the odometry slip model of the simulator (OdometrySlipOptions, sim/sensor_options.h) to segments of
// real odometry against a reference path (odometry_segments.h), issue 20 item 3:
//   scale error    e_k = odometry/reference − 1 = a + b · turn_k      (turn_k = |Δθ_ref| / d_ref, rad/m)
//   rotation error Δθ_odo − Δθ_ref = c · Δθ_ref + h · d_ref                  (c: slip on turns, h: heading drift)
// by least squares, with 95 % bootstrap intervals (segments resampled with replacement); and whether the
// scale error varies along the floor: the residuals of e_k, in path order, as an Ornstein–Uhlenbeck
// process plus white (reference) noise, and the mean scale error per zone of the path.
#pragma once

#include <random>
#include <vector>

#include "doorplate_localization/odometry_fit/odometry_segments.h"

namespace doorplate_localization {

struct OdometrySlipFitOptions {
  int bootstrap_samples = 1000;
  int num_zones = 4;                 // the path cut into this many stretches of equal arc length
  double max_abs_scale_error = 0.3;  // a segment beyond is a failed reference, left out (counted)
};

// A fitted value and its 95 % bootstrap percentile interval.
struct FittedValue {
  double value = 0.0;
  double low = 0.0;
  double high = 0.0;
};

struct ZoneScaleError {
  double start_arc_m = 0.0, end_arc_m = 0.0;  // reference path length at the zone's ends
  int segments = 0;
  double mean = 0.0;            // mean scale error of its segments
  double standard_error = 0.0;  // of the mean (NaN with fewer than two segments)
};

struct OdometrySlipFit {
  int segments_used = 0;
  int segments_rejected = 0;     // |scale error| > max_abs_scale_error
  double mean_scale_error = 0.0;
  double median_scale_error = 0.0;
  FittedValue scale_error;                 // a: at turn rate 0
  FittedValue turn_scale_error_m_per_rad;  // b: per rad/m of turn rate
  FittedValue turn_rotation_error;         // c: rad of rotation error per rad turned
  FittedValue heading_drift_rad_per_m;     // h
  double residual_stddev = 0.0;    // of e_k − a − b·turn_k
  // Autocorrelation of the residuals between contiguous segments (no gap between them), lags 1 and 2
  // in segments, and the number of pairs behind each.
  double lag1_correlation = 0.0, lag2_correlation = 0.0;
  int lag1_pairs = 0, lag2_pairs = 0;
  double mean_segment_length_m = 0.0;
  // Ornstein–Uhlenbeck fit from the lag-1 and lag-2 autocovariances c1 = σ²ρ, c2 = σ²ρ² (ρ = e^(−Δ/L),
  // Δ the mean segment length): σ = stationary standard deviation, L = correlation length. NaN when the
  // autocovariances do not decay (c1 ≤ 0, c2 ≤ 0 or c2 ≥ c1): the data show no slowly varying part.
  double ou_stddev = 0.0;
  double ou_correlation_length_m = 0.0;
  std::vector<ZoneScaleError> zones;
  // Σ ((mean_z − grand mean) / se_z)² over zones with a standard error, and its degrees of freedom
  // (zones − 1): far above the degrees of freedom, the zones differ by more than their noise.
  double zone_chi2 = 0.0;
  int zone_dof = 0;
};

// Throws std::invalid_argument for fewer than three usable segments, bootstrap_samples < 1 or
// num_zones < 1. Deterministic for a given `rng` state.
OdometrySlipFit FitOdometrySlip(const std::vector<OdometrySegment>& segments, const OdometrySlipFitOptions& options,
                                std::mt19937_64& rng);

}  // namespace doorplate_localization

#include "doorplate_localization/odometry_fit/odometry_slip_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>

namespace doorplate_localization {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Least squares: e = a + b·turn, and rotation error = c·Δθ_ref + h·d_ref, over the segments `index` names.
struct Coefficients {
  double a = 0, b = 0, c = 0, h = 0;
};

Coefficients Solve(const std::vector<OdometrySegment>& s, const std::vector<int>& index) {
  const int n = static_cast<int>(index.size());
  Eigen::MatrixXd scale_design(n, 2), rotation_design(n, 2);
  Eigen::VectorXd scale(n), rotation(n);
  for (int k = 0; k < n; ++k) {
    const OdometrySegment& g = s[index[k]];
    scale_design.row(k) << 1.0, g.TurnRateRadPerM();
    scale(k) = g.ScaleError();
    rotation_design.row(k) << g.reference_rotation_rad, g.reference_distance_m;
    rotation(k) = g.odometry_rotation_rad - g.reference_rotation_rad;
  }
  // A resample without any turn (or travel) leaves a column without information: minimum-norm solution.
  const Eigen::Vector2d ab = scale_design.completeOrthogonalDecomposition().solve(scale);
  const Eigen::Vector2d ch = rotation_design.completeOrthogonalDecomposition().solve(rotation);
  return {ab(0), ab(1), ch(0), ch(1)};
}

double Percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double pos = q * (v.size() - 1);
  const size_t lo = static_cast<size_t>(std::floor(pos));
  const size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - lo) * (v[hi] - v[lo]);
}

FittedValue Interval(double value, const std::vector<double>& samples) {
  return {value, Percentile(samples, 0.025), Percentile(samples, 0.975)};
}

// Mean over contiguous pairs (k, k + lag) of r_k · r_{k+lag} (residuals have mean ~0 by the fit's
// intercept), and the pair count.
double Autocovariance(const std::vector<OdometrySegment>& s, const std::vector<int>& used,
                      const std::vector<double>& r, int lag, int* pairs) {
  double sum = 0.0;
  *pairs = 0;
  for (size_t k = 0; k + lag < used.size(); ++k) {
    bool contiguous = true;
    for (int j = 0; j < lag && contiguous; ++j) {
      const OdometrySegment& a = s[used[k + j]];
      contiguous = used[k + j + 1] == used[k + j] + 1 && s[used[k + j + 1]].first_step == a.first_step + a.num_steps;
    }
    if (!contiguous) continue;
    sum += r[k] * r[k + lag];
    ++*pairs;
  }
  return *pairs > 0 ? sum / *pairs : kNaN;
}

}  // namespace

OdometrySlipFit FitOdometrySlip(const std::vector<OdometrySegment>& segments, const OdometrySlipFitOptions& options,
                                std::mt19937_64& rng) {
  if (options.bootstrap_samples < 1) {
    throw std::invalid_argument("OdometrySlipFitOptions.bootstrap_samples must be >= 1");
  }
  if (options.num_zones < 1) throw std::invalid_argument("OdometrySlipFitOptions.num_zones must be >= 1");
  OdometrySlipFit fit;
  std::vector<int> used;
  for (int k = 0; k < static_cast<int>(segments.size()); ++k) {
    const OdometrySegment& g = segments[k];
    if (g.reference_distance_m > 0.0 && std::fabs(g.ScaleError()) <= options.max_abs_scale_error) used.push_back(k);
    else ++fit.segments_rejected;
  }
  const int n = static_cast<int>(used.size());
  if (n < 3) {
    throw std::invalid_argument("FitOdometrySlip: " + std::to_string(n) + " usable segments, need at least 3");
  }
  fit.segments_used = n;

  std::vector<double> errors;
  for (int k : used) {
    errors.push_back(segments[k].ScaleError());
    fit.mean_segment_length_m += segments[k].reference_distance_m / n;
  }
  for (double e : errors) fit.mean_scale_error += e / n;
  fit.median_scale_error = Percentile(errors, 0.5);

  const Coefficients point = Solve(segments, used);
  std::vector<double> a, b, c, h;
  std::uniform_int_distribution<int> pick(0, n - 1);
  std::vector<int> resample(n);
  for (int i = 0; i < options.bootstrap_samples; ++i) {
    for (int& r : resample) r = used[pick(rng)];
    const Coefficients boot = Solve(segments, resample);
    a.push_back(boot.a), b.push_back(boot.b), c.push_back(boot.c), h.push_back(boot.h);
  }
  fit.scale_error = Interval(point.a, a);
  fit.turn_scale_error_m_per_rad = Interval(point.b, b);
  fit.turn_rotation_error = Interval(point.c, c);
  fit.heading_drift_rad_per_m = Interval(point.h, h);

  // Residual scale errors in path order: white part and slowly varying part.
  std::vector<double> residual(n);
  double c0 = 0.0;
  for (int k = 0; k < n; ++k) {
    residual[k] = errors[k] - point.a - point.b * segments[used[k]].TurnRateRadPerM();
    c0 += residual[k] * residual[k] / n;
  }
  fit.residual_stddev = std::sqrt(c0);
  const double c1 = Autocovariance(segments, used, residual, 1, &fit.lag1_pairs);
  const double c2 = Autocovariance(segments, used, residual, 2, &fit.lag2_pairs);
  fit.lag1_correlation = c0 > 0 ? c1 / c0 : kNaN;
  fit.lag2_correlation = c0 > 0 ? c2 / c0 : kNaN;
  if (c1 > 0 && c2 > 0 && c2 < c1) {
    const double rho = c2 / c1;
    fit.ou_stddev = std::sqrt(c1 * c1 / c2);
    fit.ou_correlation_length_m = -fit.mean_segment_length_m / std::log(rho);
  } else {
    fit.ou_stddev = fit.ou_correlation_length_m = kNaN;
  }

  // Zones of equal arc length over the span the segments cover.
  const OdometrySegment& last = segments[used.back()];
  const double start = segments[used.front()].start_arc_m;
  const double end = last.start_arc_m + last.reference_distance_m;
  const double width = (end - start) / options.num_zones;
  fit.zones.resize(options.num_zones);
  std::vector<std::vector<double>> in_zone(options.num_zones);
  for (int k = 0; k < n; ++k) {
    const OdometrySegment& g = segments[used[k]];
    const double middle = g.start_arc_m + 0.5 * g.reference_distance_m;
    const int z = width > 0 ? std::clamp(static_cast<int>((middle - start) / width), 0, options.num_zones - 1) : 0;
    in_zone[z].push_back(errors[k]);
  }
  std::vector<double> weights, means;
  for (int z = 0; z < options.num_zones; ++z) {
    ZoneScaleError& zone = fit.zones[z];
    zone.start_arc_m = start + z * width;
    zone.end_arc_m = start + (z + 1) * width;
    zone.segments = static_cast<int>(in_zone[z].size());
    zone.mean = zone.standard_error = kNaN;
    if (zone.segments == 0) continue;
    zone.mean = 0.0;
    for (double e : in_zone[z]) zone.mean += e / zone.segments;
    if (zone.segments < 2) continue;
    double var = 0.0;
    for (double e : in_zone[z]) var += (e - zone.mean) * (e - zone.mean) / (zone.segments - 1);
    zone.standard_error = std::sqrt(var / zone.segments);
    if (zone.standard_error > 0) {
      weights.push_back(1.0 / (zone.standard_error * zone.standard_error));
      means.push_back(zone.mean);
    }
  }
  if (means.size() >= 2) {
    double wsum = 0.0, grand = 0.0;
    for (size_t z = 0; z < means.size(); ++z) wsum += weights[z], grand += weights[z] * means[z];
    grand /= wsum;
    for (size_t z = 0; z < means.size(); ++z) fit.zone_chi2 += weights[z] * (means[z] - grand) * (means[z] - grand);
    fit.zone_dof = static_cast<int>(means.size()) - 1;
  }
  return fit;
}

}  // namespace doorplate_localization

#include "doorplate_localization/laser_fit/laser_error_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Dense>

namespace doorplate_localization {
namespace {

constexpr double kMaxIncidenceDeg = 80.0;  // as FittedLaserErrorModel: 1/cos is capped here

double Secant(double incidence_deg) {
  return 1.0 / std::cos(std::min(incidence_deg, kMaxIncidenceDeg) * M_PI / 180.0);
}

struct Fraction {
  double base2 = 0.0, fraction2 = 0.0;
};

// Least squares of sigma² = base² + fraction²·r² over bins (weights: counts), both terms >= 0.
Fraction FitRangeNoise(const std::vector<double>& r, const std::vector<double>& sigma, const std::vector<double>& n) {
  double s1 = 0, sr2 = 0, sr4 = 0, sy = 0, syr2 = 0;
  for (size_t k = 0; k < r.size(); ++k) {
    const double r2 = r[k] * r[k], y = sigma[k] * sigma[k];
    s1 += n[k], sr2 += n[k] * r2, sr4 += n[k] * r2 * r2, sy += n[k] * y, syr2 += n[k] * y * r2;
  }
  Fraction f;
  if (s1 <= 0) return f;
  const double det = s1 * sr4 - sr2 * sr2;
  if (det > 1e-12 * s1 * sr4) {
    f.base2 = (sy * sr4 - sr2 * syr2) / det;
    f.fraction2 = (s1 * syr2 - sr2 * sy) / det;
  } else {
    f.base2 = -1.0;  // one range only: a constant
  }
  if (f.base2 < 0.0) f = {0.0, sr4 > 0 ? syr2 / sr4 : 0.0};
  if (f.fraction2 < 0.0) f = {sy / s1, 0.0};
  return f;
}

// Dropouts: least squares of the linear probability model [1, r, r < near, ramp(i)] with non-negative
// coefficients (an active set: a negative coefficient's feature is dropped and the rest refitted).
// Returns the squared error.
double FitDropouts(const BeamTally& tally, double near_m, double onset_deg, Eigen::Vector4d* coefficients) {
  Eigen::Matrix4d xtx = Eigen::Matrix4d::Zero();
  Eigen::Vector4d xty = Eigen::Vector4d::Zero();
  double yy = 0.0;
  for (const HitTrial& h : tally.hits) {
    if (std::isnan(h.incidence_deg)) continue;
    const double ramp = std::clamp((h.incidence_deg - onset_deg) / (90.0 - onset_deg), 0.0, 1.0);
    const Eigen::Vector4d x(1.0, h.range_m, h.range_m < near_m ? 1.0 : 0.0, ramp);
    const double y = h.dropped ? 1.0 : 0.0;
    xtx += x * x.transpose(), xty += x * y, yy += y;
  }
  std::array<bool, 4> active{true, true, true, true};
  Eigen::Vector4d beta = Eigen::Vector4d::Zero();
  for (int round = 0; round < 4; ++round) {
    Eigen::Matrix4d a = xtx;
    Eigen::Vector4d b = xty;
    for (int j = 0; j < 4; ++j) {
      if (active[j] && a(j, j) > 0.0) continue;
      a.row(j).setZero(), a.col(j).setZero(), a(j, j) = 1.0, b(j) = 0.0;
    }
    beta = a.ldlt().solve(b);
    bool changed = false;
    for (int j = 0; j < 4; ++j) {
      if (active[j] && beta(j) < 0.0) active[j] = false, changed = true;
    }
    if (!changed) break;
  }
  for (int j = 0; j < 4; ++j) beta(j) = active[j] ? std::max(0.0, beta(j)) : 0.0;
  *coefficients = beta;
  return yy - 2.0 * beta.dot(xty) + beta.dot(xtx * beta);
}

// Short returns: p·F(cut) with F the exponential CDF of mean `mean_m` is the chance that a beam whose
// return counts as short below `cut` has one. Least squares over every beam that could have one: for a
// given mean the best p is sum_short F / sum_all F², leaving the squared error n_short - (sum_short F)² /
// sum_all F²; the mean is the candidate (log-spaced, 0.1-30 m) with the least error.
void FitShortReturns(const BeamTally& tally, const BeamTallyOptions& gates, FittedLaserErrorOptions* m) {
  const auto cdf = [](double cut_m, double mean_m) { return cut_m <= 0.0 ? 0.0 : -std::expm1(-cut_m / mean_m); };
  double best = -1.0;
  for (int k = 0; k <= 60; ++k) {
    const double mean = 0.1 * std::pow(300.0, k / 60.0);
    double all = tally.free_trials * std::pow(cdf(tally.free_limit_m, mean), 2), shorts = 0.0;
    for (const HitTrial& h : tally.hits) {
      all += std::pow(cdf(h.range_m - gates.gate_m - gates.gate_fraction * h.range_m, mean), 2);
    }
    for (const float cut : tally.short_cuts_m) shorts += cdf(cut, mean);
    if (all > 0.0 && shorts * shorts / all > best) {
      best = shorts * shorts / all;
      m->short_mean_m = mean;
      m->short_probability = std::min(1.0, shorts / all);
    }
  }
}

}  // namespace

RobustSpread RobustSpreadOf(std::vector<float> values) {
  RobustSpread s;
  s.count = static_cast<long>(values.size());
  if (values.empty()) return s;
  const auto median_of = [](std::vector<float>& v) {
    const size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + mid, v.end());
    double m = v[mid];
    if (v.size() % 2 == 0) m = 0.5 * (m + *std::max_element(v.begin(), v.begin() + mid));
    return m;
  };
  s.median = median_of(values);
  for (float& v : values) v = static_cast<float>(std::fabs(v - s.median));
  s.sigma = 1.4826 * median_of(values);
  return s;
}

std::vector<RobustSpread> SpreadByRange(const BeamTally& tally, const std::vector<double>& edges_m) {
  std::vector<std::vector<float>> bins(edges_m.size() - 1);
  for (const CoreReturn& c : tally.core) {
    if (const int b = BeamTallier::Bin(edges_m, c.range_m); b >= 0) bins[b].push_back(c.error_m);
  }
  std::vector<RobustSpread> out;
  for (auto& b : bins) out.push_back(RobustSpreadOf(std::move(b)));
  return out;
}

std::vector<RobustSpread> SpreadByIncidence(const BeamTally& tally, const std::vector<double>& edges_deg) {
  std::vector<std::vector<float>> bins(edges_deg.size() - 1);
  for (const CoreReturn& c : tally.core) {
    if (const int b = BeamTallier::Bin(edges_deg, c.incidence_deg); b >= 0) bins[b].push_back(c.error_m);
  }
  std::vector<RobustSpread> out;
  for (auto& b : bins) out.push_back(RobustSpreadOf(std::move(b)));
  return out;
}

FittedLaserErrorOptions FitLaserErrors(const BeamTally& tally, const BeamTallyOptions& tally_options,
                                       const LaserErrorFitOptions& options) {
  if (tally.core.empty()) throw std::invalid_argument("FitLaserErrors: the tally holds no core return");
  if (tally.hits.empty()) throw std::invalid_argument("FitLaserErrors: the tally holds no hit trial");
  // Start from no effect at all (not the shipped defaults): an effect the data does not show stays 0.
  FittedLaserErrorOptions m;
  m.noise_base_m = m.noise_fraction = m.noise_grazing_gain = 0.0;
  m.dropout_probability = m.dropout_per_m = m.dropout_near_probability = m.dropout_grazing_probability = 0.0;
  m.mixed_pixel_probability = m.short_probability = 0.0;
  m.depth_edge_m = options.depth_edge_m;
  // Noise: alternate the range fit (errors without the grazing factor) and the grazing gain (errors
  // divided by sigma(r)); a few rounds settle both.
  const size_t nr = options.noise_range_bins_m.size() - 1, ni = options.noise_incidence_bins_deg.size() - 1;
  for (int round = 0; round < 5; ++round) {
    std::vector<std::vector<float>> by_range(nr), by_incidence(ni);
    std::vector<double> range_sum(nr, 0.0), incidence_sum(ni, 0.0);
    for (const CoreReturn& c : tally.core) {
      const double grazing = 1.0 + m.noise_grazing_gain * (Secant(c.incidence_deg) - 1.0);
      if (const int b = BeamTallier::Bin(options.noise_range_bins_m, c.range_m); b >= 0) {
        by_range[b].push_back(static_cast<float>(c.error_m / grazing));
        range_sum[b] += c.range_m;
      }
      if (round == 0) continue;  // sigma(r) is not known yet
      const double sigma_r = std::hypot(m.noise_base_m, m.noise_fraction * c.range_m);
      if (const int b = BeamTallier::Bin(options.noise_incidence_bins_deg, c.incidence_deg); b >= 0 && sigma_r > 0) {
        by_incidence[b].push_back(static_cast<float>(c.error_m / sigma_r));
        incidence_sum[b] += std::min<double>(c.incidence_deg, kMaxIncidenceDeg);
      }
    }
    std::vector<double> r, sigma, n;
    for (size_t b = 0; b < nr; ++b) {
      if (static_cast<long>(by_range[b].size()) < options.min_bin_samples) continue;
      r.push_back(range_sum[b] / by_range[b].size());
      n.push_back(static_cast<double>(by_range[b].size()));
      sigma.push_back(RobustSpreadOf(std::move(by_range[b])).sigma);
    }
    const Fraction f = FitRangeNoise(r, sigma, n);
    m.noise_base_m = std::sqrt(f.base2), m.noise_fraction = std::sqrt(f.fraction2);
    double num = 0.0, den = 0.0;
    for (size_t b = 0; b < ni; ++b) {
      const double count = static_cast<double>(by_incidence[b].size());
      if (count < options.min_bin_samples) continue;
      const double s = RobustSpreadOf(std::move(by_incidence[b])).sigma;
      const double sec = Secant(incidence_sum[b] / count) - 1.0;
      // z = error / sigma(r) has the spread 1 + g·(sec - 1) in a bin of mean incidence i.
      num += count * (s - 1.0) * sec, den += count * sec * sec;
    }
    if (round > 0) m.noise_grazing_gain = den > 0 ? std::max(0.0, num / den) : 0.0;
  }
  double best = std::numeric_limits<double>::infinity();
  for (const double near : options.near_ranges_m) {
    for (const double onset : options.grazing_onsets_deg) {
      Eigen::Vector4d beta;
      const double sse = FitDropouts(tally, near, onset, &beta);
      if (sse < best - 1e-9) {
        best = sse;
        m.dropout_probability = std::min(1.0, beta(0));
        m.dropout_per_m = std::min(1.0, beta(1));
        m.dropout_near_probability = std::min(1.0, beta(2));
        m.dropout_near_range_m = near;
        m.dropout_grazing_probability = std::min(1.0, beta(3));
        m.dropout_grazing_from_deg = onset;
      }
    }
  }
  if (tally.edge_mixed_visible > 0.0) {
    m.mixed_pixel_probability = std::min(1.0, tally.Count(BeamOutcome::kMixed) / tally.edge_mixed_visible);
  }
  if (!tally.short_readings_m.empty()) FitShortReturns(tally, tally_options, &m);
  return m;
}

}  // namespace doorplate_localization

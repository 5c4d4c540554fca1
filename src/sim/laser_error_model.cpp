#include "doorplate_localization/sim/laser_error_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

constexpr double kMaxIncidenceRad = 80.0 * M_PI / 180.0;  // 1/cos is capped here (the grazing gain's limit)

void Require(bool ok, const std::string& field, const std::string& rule, double value) {
  if (!ok) throw std::invalid_argument(field + ": must be " + rule + ", got " + std::to_string(value));
}

void RequireProbability(const std::string& field, double value) {
  Require(value >= 0.0 && value <= 1.0, field, "in [0, 1]", value);
}

// The exact range across a depth edge from beam i (the neighbour that differs most, by more than
// `edge_m`); NaN if beam i is not at a depth edge.
double OtherSideOfEdge(const std::vector<float>& exact, size_t i, double edge_m, bool wrap_around) {
  const size_t n = exact.size();
  double other = std::numeric_limits<double>::quiet_NaN();
  for (const int step : {-1, 1}) {
    if (!wrap_around && ((step < 0 && i == 0) || (step > 0 && i + 1 == n))) continue;
    const double r = exact[(i + n + step) % n];
    if (!std::isfinite(r) || r < 0.0) continue;
    const double gap = std::fabs(r - exact[i]);
    if (gap > edge_m && (std::isnan(other) || gap > std::fabs(other - exact[i]))) other = r;
  }
  return other;
}

}  // namespace

GaussianLaserErrorModel::GaussianLaserErrorModel(double range_noise_stddev_m, double dropout_probability)
    : stddev_m_(range_noise_stddev_m), dropout_probability_(dropout_probability) {
  Require(range_noise_stddev_m >= 0.0, "LaserOptions.range_noise_stddev_m", ">= 0", range_noise_stddev_m);
  RequireProbability("LaserOptions.dropout_probability", dropout_probability);
}

void GaussianLaserErrorModel::Apply(std::vector<float>* ranges_m, const std::vector<float>&, double min_range_m,
                                    double max_range_m, bool, std::mt19937_64& rng) const {
  std::normal_distribution<double> noise(0.0, stddev_m_);
  std::bernoulli_distribution dropout(dropout_probability_);
  for (float& r : *ranges_m) {
    // Draw both for every beam so the random stream does not depend on the geometry.
    const double n = noise(rng);
    const bool lost = dropout(rng);
    if (!std::isfinite(r)) continue;
    if (lost) {
      r = std::numeric_limits<float>::infinity();
      continue;
    }
    const double noisy = r + n;
    r = noisy > max_range_m ? std::numeric_limits<float>::infinity()
                            : static_cast<float>(std::max(noisy, min_range_m));
  }
}

FittedLaserErrorModel::FittedLaserErrorModel(const FittedLaserErrorOptions& o) : options_(o) {
  const std::string p = "FittedLaserErrorOptions.";
  Require(o.noise_base_m >= 0.0, p + "noise_base_m", ">= 0", o.noise_base_m);
  Require(o.noise_fraction >= 0.0, p + "noise_fraction", ">= 0", o.noise_fraction);
  Require(o.noise_grazing_gain >= 0.0, p + "noise_grazing_gain", ">= 0", o.noise_grazing_gain);
  RequireProbability(p + "dropout_probability", o.dropout_probability);
  Require(o.dropout_per_m >= 0.0 && o.dropout_per_m <= 1.0, p + "dropout_per_m", "in [0, 1]", o.dropout_per_m);
  RequireProbability(p + "dropout_near_probability", o.dropout_near_probability);
  Require(o.dropout_near_range_m >= 0.0, p + "dropout_near_range_m", ">= 0", o.dropout_near_range_m);
  RequireProbability(p + "dropout_grazing_probability", o.dropout_grazing_probability);
  Require(o.dropout_grazing_from_deg >= 0.0 && o.dropout_grazing_from_deg < 90.0, p + "dropout_grazing_from_deg",
          "in [0, 90)", o.dropout_grazing_from_deg);
  Require(o.depth_edge_m > 0.0, p + "depth_edge_m", "> 0", o.depth_edge_m);
  RequireProbability(p + "mixed_pixel_probability", o.mixed_pixel_probability);
  RequireProbability(p + "short_probability", o.short_probability);
  Require(o.short_mean_m > 0.0, p + "short_mean_m", "> 0", o.short_mean_m);
  Require(o.detection_range_m >= 0.0 && std::isfinite(o.detection_range_m), p + "detection_range_m",
          ">= 0 and finite", o.detection_range_m);
  Require(o.detection_edge_fraction > 0.0 && o.detection_edge_fraction <= 1.0, p + "detection_edge_fraction",
          "in (0, 1]", o.detection_edge_fraction);
}

double FittedLaserErrorModel::NoiseStddev(double range_m, double incidence_rad) const {
  const double i = std::isnan(incidence_rad) ? 0.0 : std::min(std::fabs(incidence_rad), kMaxIncidenceRad);
  return std::hypot(options_.noise_base_m, options_.noise_fraction * range_m) *
         (1.0 + options_.noise_grazing_gain * (1.0 / std::cos(i) - 1.0));
}

double FittedLaserErrorModel::DropoutProbability(double range_m, double incidence_rad) const {
  const double deg = std::isnan(incidence_rad) ? 0.0 : std::fabs(incidence_rad) * 180.0 / M_PI;
  const double from = options_.dropout_grazing_from_deg;
  const double grazing = std::clamp((deg - from) / (90.0 - from), 0.0, 1.0);
  const double near = range_m < options_.dropout_near_range_m ? options_.dropout_near_probability : 0.0;
  const double fitted = std::clamp(options_.dropout_probability + options_.dropout_per_m * range_m + near +
                                       options_.dropout_grazing_probability * grazing,
                                   0.0, 1.0);
  if (options_.detection_range_m <= 0.0) return fitted;
  // Too weak an echo (lidar equation): beyond r_max = detection_range_m · sqrt(cos i).
  const double cos_i = std::cos(std::min(deg, 89.9) * M_PI / 180.0);
  const double r_max = options_.detection_range_m * std::sqrt(cos_i);
  const double weak = std::clamp((range_m / r_max - 1.0) / options_.detection_edge_fraction + 0.5, 0.0, 1.0);
  return 1.0 - (1.0 - fitted) * (1.0 - weak);
}

void FittedLaserErrorModel::Apply(std::vector<float>* ranges_m, const std::vector<float>& incidence_rad,
                                  double min_range_m, double max_range_m, bool wrap_around,
                                  std::mt19937_64& rng) const {
  const std::vector<float> exact = *ranges_m;  // neighbours are read before any beam changes
  const bool has_incidence = incidence_rad.size() == exact.size();
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const float inf = std::numeric_limits<float>::infinity();
  for (size_t i = 0; i < exact.size(); ++i) {
    const double z = gauss(rng), u_mixed = uniform(rng), u_short = uniform(rng), u_drop = uniform(rng),
                 u_where = uniform(rng);
    const double e = exact[i];
    if (std::isnan(e) || e < 0.0) continue;  // unknown, or too close to measure (-inf)
    const bool hit = std::isfinite(e);
    float& out = (*ranges_m)[i];
    if (hit && u_mixed < options_.mixed_pixel_probability) {
      const double other = OtherSideOfEdge(exact, i, options_.depth_edge_m, wrap_around);
      if (!std::isnan(other)) {
        out = static_cast<float>(std::min(e, other) + u_where * std::fabs(other - e));
        continue;
      }
    }
    if (u_short < options_.short_probability) {
      // Something stands an exponential distance beyond the minimum range; it is seen if nearer than
      // the surface (or than max range).
      const double at = min_range_m - options_.short_mean_m * std::log1p(-u_where);
      if (at < (hit ? e : max_range_m)) {
        out = static_cast<float>(at);
        continue;
      }
    }
    if (!hit) continue;
    const double incidence = has_incidence ? incidence_rad[i] : 0.0;
    if (u_drop < DropoutProbability(e, incidence)) {
      out = inf;
      continue;
    }
    const double noisy = e + NoiseStddev(e, incidence) * z;
    out = noisy > max_range_m ? inf : static_cast<float>(std::max(noisy, min_range_m));
  }
}

std::shared_ptr<const LaserErrorModel> MakeLaserErrorModel(const LaserOptions& options) {
  if (options.error_model == "gaussian") {
    return std::make_shared<GaussianLaserErrorModel>(options.range_noise_stddev_m, options.dropout_probability);
  }
  if (options.error_model == "fitted") return std::make_shared<FittedLaserErrorModel>(options.fitted);
  throw std::invalid_argument("LaserOptions.error_model: must be 'gaussian' or 'fitted', got '" +
                              options.error_model + "'");
}

}  // namespace doorplate_localization

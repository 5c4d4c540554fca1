#include "laser_fit_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "doorplate_localization/laser_fit/distribution_distance.h"

namespace doorplate_localization::tools {
namespace {

const char* const kOutcomeNames[kNumBeamOutcomes] = {"core",  "dropout",      "short",      "long",
                                                     "edge_near", "edge_far", "mixed",      "edge_dropout",
                                                     "edge_other", "free_clear", "skipped"};

std::vector<float> CoreErrors(const BeamTally& t) {
  std::vector<float> e;
  e.reserve(t.core.size());
  for (const CoreReturn& c : t.core) e.push_back(c.error_m);
  return e;
}

// Mean |rate difference| over bins, weighted by the real tally's trials.
double RateDistance(const BinnedRate& real, const BinnedRate& sim) {
  double num = 0.0, den = 0.0;
  for (size_t k = 0; k < real.trials.size(); ++k) {
    if (!real.trials[k] || !sim.trials[k]) continue;
    num += real.trials[k] * std::fabs(real.Rate(k) - sim.Rate(k)), den += real.trials[k];
  }
  return den > 0 ? num / den : 0.0;
}

std::string Num(double v) {
  if (!std::isfinite(v)) return "null";
  char b[32];
  std::snprintf(b, sizeof(b), "%.6g", v);
  return b;
}

template <class T, class F>
std::string Array(const std::vector<T>& v, F f) {
  std::string s = "[";
  for (size_t k = 0; k < v.size(); ++k) s += (k ? ", " : "") + f(v[k]);
  return s + "]";
}

std::string Quote(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

std::string FittedJson(const FittedLaserErrorOptions& f) {
  std::ostringstream o;
  o << "{\"noise_base_m\": " << Num(f.noise_base_m) << ", \"noise_fraction\": " << Num(f.noise_fraction)
    << ", \"noise_grazing_gain\": " << Num(f.noise_grazing_gain)
    << ", \"dropout_probability\": " << Num(f.dropout_probability) << ", \"dropout_per_m\": " << Num(f.dropout_per_m)
    << ", \"dropout_near_probability\": " << Num(f.dropout_near_probability)
    << ", \"dropout_near_range_m\": " << Num(f.dropout_near_range_m)
    << ", \"dropout_grazing_probability\": " << Num(f.dropout_grazing_probability)
    << ", \"dropout_grazing_from_deg\": " << Num(f.dropout_grazing_from_deg)
    << ", \"depth_edge_m\": " << Num(f.depth_edge_m) << ", \"mixed_pixel_probability\": "
    << Num(f.mixed_pixel_probability) << ", \"short_probability\": " << Num(f.short_probability)
    << ", \"short_mean_m\": " << Num(f.short_mean_m) << "}";
  return o.str();
}

std::string TallyJson(const BeamTally& t, const BeamTallyOptions& bins) {
  std::ostringstream o;
  o << "{\"outcomes\": {";
  for (int k = 0; k < kNumBeamOutcomes; ++k) o << (k ? ", " : "") << Quote(kOutcomeNames[k]) << ": " << t.outcomes[k];
  const auto spread = [](const RobustSpread& s) {
    return "{\"n\": " + std::to_string(s.count) + ", \"median_m\": " + Num(s.median) + ", \"sigma_m\": " +
           Num(s.sigma) + "}";
  };
  const auto rate = [](const BinnedRate& r) {
    std::string s = "[";
    for (size_t k = 0; k < r.trials.size(); ++k) {
      s += (k ? ", " : "") + std::string("{\"events\": ") + std::to_string(r.events[k]) +
           ", \"trials\": " + std::to_string(r.trials[k]) + ", \"rate\": " + Num(r.Rate(k)) + "}";
    }
    return s + "]";
  };
  std::vector<float> shorts = t.short_readings_m;
  std::sort(shorts.begin(), shorts.end());
  const auto quantile = [&](double q) { return shorts.empty() ? NAN : shorts[size_t(q * (shorts.size() - 1))]; };
  o << "}, \"core_error\": " << spread(RobustSpreadOf(CoreErrors(t)))
    << ", \"core_error_by_range\": " << Array(SpreadByRange(t, bins.range_bins_m), spread)
    << ", \"core_error_by_incidence\": " << Array(SpreadByIncidence(t, bins.incidence_bins_deg), spread)
    << ", \"dropout_by_range\": " << rate(t.dropout_by_range)
    << ", \"dropout_by_incidence\": " << rate(t.dropout_by_incidence)
    << ", \"dropout_rate\": " << Num(double(t.dropout_by_range.Events()) / std::max(1L, t.dropout_by_range.Trials()))
    << ", \"short_by_range\": " << rate(t.short_by_range) << ", \"short_in_free\": " << t.short_in_free
    << ", \"free_trials\": " << t.free_trials << ", \"short_rate\": " << Num(t.ShortRate())
    << ", \"short_reading_quantiles_m\": {\"q10\": " << Num(quantile(0.1)) << ", \"q50\": " << Num(quantile(0.5))
    << ", \"q90\": " << Num(quantile(0.9)) << "}, \"long_rate\": " << Num(t.LongRate())
    << ", \"long_events\": " << t.long_events << ", \"edge_trials\": " << t.edge_trials
    << ", \"mixed_rate\": " << Num(t.MixedRate()) << "}";
  return o.str();
}

std::string DistanceJson(const TallyDistance& d) {
  std::ostringstream o;
  o << "{\"error_jsd\": " << Num(d.error_jsd) << ", \"error_w1_m\": " << Num(d.error_w1_m)
    << ", \"outcome_jsd\": " << Num(d.outcome_jsd) << ", \"dropout_range_mean_abs_diff\": "
    << Num(d.dropout_range_w1) << ", \"dropout_incidence_mean_abs_diff\": " << Num(d.dropout_incidence_w1)
    << ", \"short_rate_real\": " << Num(d.short_rate_real) << ", \"short_rate_sim\": " << Num(d.short_rate_sim)
    << ", \"short_range_w1_m\": " << Num(d.short_range_w1_m) << "}";
  return o.str();
}

}  // namespace

TallyDistance CompareTallies(const BeamTally& real, const BeamTally& sim) {
  TallyDistance d;
  const std::vector<float> er = CoreErrors(real), es = CoreErrors(sim);
  constexpr int kBins = static_cast<int>(2 * kErrorWindowM / 0.005);
  if (!er.empty() && !es.empty()) {
    d.error_jsd = JensenShannonDivergence(Histogram(er, -kErrorWindowM, kErrorWindowM, kBins),
                                          Histogram(es, -kErrorWindowM, kErrorWindowM, kBins));
    d.error_w1_m = Wasserstein1(er, es);
  }
  std::vector<double> pr(real.outcomes.begin(), real.outcomes.end()), ps(sim.outcomes.begin(), sim.outcomes.end());
  pr.pop_back(), ps.pop_back();  // skipped beams are the same in both (the geometry's)
  d.outcome_jsd = JensenShannonDivergence(pr, ps);
  d.dropout_range_w1 = RateDistance(real.dropout_by_range, sim.dropout_by_range);
  d.dropout_incidence_w1 = RateDistance(real.dropout_by_incidence, sim.dropout_by_incidence);
  d.short_rate_real = real.ShortRate(), d.short_rate_sim = sim.ShortRate();
  if (!real.short_readings_m.empty() && !sim.short_readings_m.empty()) {
    d.short_range_w1_m = Wasserstein1(real.short_readings_m, sim.short_readings_m);
  }
  return d;
}

void WriteLaserFitJson(const LaserFitReport& r, const std::string& path) {
  std::ostringstream o;
  const auto num = [](double v) { return Num(v); };
  o << "{\n  \"logs\": " << Array(r.logs, Quote) << ",\n  \"split\": " << Quote(r.split) << ",\n  \"seed\": " << r.seed
    << ",\n  \"range_bins_m\": " << Array(r.bins.range_bins_m, num)
    << ",\n  \"incidence_bins_deg\": " << Array(r.bins.incidence_bins_deg, num)
    << ",\n  \"depth_edge_m\": " << Num(r.bins.depth_edge_m) << ",\n  \"gate\": {\"gate_m\": " << Num(r.bins.gate_m)
    << ", \"gate_fraction\": " << Num(r.bins.gate_fraction) << "},\n  \"fitted\": " << FittedJson(r.fitted)
    << ",\n  \"gaussian\": {\"range_noise_stddev_m\": " << Num(r.gaussian_stddev_m)
    << ", \"dropout_probability\": " << Num(r.gaussian_dropout) << "},\n  \"per_log\": {";
  for (size_t k = 0; k < r.per_log.size(); ++k) {
    o << (k ? ",\n    " : "\n    ") << Quote(r.per_log[k].name) << ": " << TallyJson(*r.per_log[k].tally, r.bins);
  }
  o << "\n  },\n  \"real\": " << TallyJson(*r.real.tally, r.bins)
    << ",\n  \"fitted_sim\": " << TallyJson(*r.fitted_sim.tally, r.bins)
    << ",\n  \"gaussian_sim\": " << TallyJson(*r.gaussian_sim.tally, r.bins)
    << ",\n  \"distance_fitted\": " << DistanceJson(r.fitted_distance)
    << ",\n  \"distance_gaussian\": " << DistanceJson(r.gaussian_distance) << "\n}\n";
  std::ofstream out(path);
  out << o.str();
  if (!out) throw std::runtime_error(path + ": cannot write the JSON report");
}

void PrintLaserFitReport(const LaserFitReport& r) {
  const auto line = [&](const NamedTally& n) {
    const BeamTally& t = *n.tally;
    const RobustSpread core = RobustSpreadOf(CoreErrors(t));
    std::printf("%-60s core %8ld  median %+.4f m  sigma %.4f m  dropout %.4f  short %.4f  long %.4f  mixed %.3f "
                "(%ld edges)\n",
                n.name.c_str(), core.count, core.median, core.sigma,
                double(t.dropout_by_range.Events()) / std::max(1L, t.dropout_by_range.Trials()), t.ShortRate(),
                t.LongRate(), t.MixedRate(), t.edge_trials);
  };
  for (const NamedTally& n : r.per_log) line(n);
  line(r.real), line(r.fitted_sim), line(r.gaussian_sim);
  const BeamTally& t = *r.real.tally;
  std::printf("\nrange bin m        core n  sigma m   median m  dropout  short  (real, all logs)\n");
  const std::vector<RobustSpread> by_range = SpreadByRange(t, r.bins.range_bins_m);
  for (size_t k = 0; k + 1 < r.bins.range_bins_m.size(); ++k) {
    std::printf("[%5.1f, %5.1f)  %9ld  %.4f  %+.4f  %.4f  %.4f\n", r.bins.range_bins_m[k], r.bins.range_bins_m[k + 1],
                by_range[k].count, by_range[k].sigma, by_range[k].median, t.dropout_by_range.Rate(k),
                t.short_by_range.Rate(k));
  }
  std::printf("\nincidence bin deg  core n  sigma m   median m  dropout\n");
  const std::vector<RobustSpread> by_inc = SpreadByIncidence(t, r.bins.incidence_bins_deg);
  for (size_t k = 0; k + 1 < r.bins.incidence_bins_deg.size(); ++k) {
    std::printf("[%4.0f, %4.0f)  %9ld  %.4f  %+.4f  %.4f\n", r.bins.incidence_bins_deg[k],
                r.bins.incidence_bins_deg[k + 1], by_inc[k].count, by_inc[k].sigma, by_inc[k].median,
                t.dropout_by_incidence.Rate(k));
  }
  std::printf("\nfitted: %s\n", FittedJson(r.fitted).c_str());
  std::printf("distance real vs fitted:   %s\n", DistanceJson(r.fitted_distance).c_str());
  std::printf("distance real vs gaussian: %s\n", DistanceJson(r.gaussian_distance).c_str());
}

}  // namespace doorplate_localization::tools

#include "laser_fit_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "doorplate_localization/laser_fit/distribution_distance.h"
#include "result_json.h"

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

Json FittedJson(const FittedLaserErrorOptions& f) {
  return {{"noise_base_m", f.noise_base_m},
          {"noise_fraction", f.noise_fraction},
          {"noise_grazing_gain", f.noise_grazing_gain},
          {"dropout_probability", f.dropout_probability},
          {"dropout_per_m", f.dropout_per_m},
          {"dropout_near_probability", f.dropout_near_probability},
          {"dropout_near_range_m", f.dropout_near_range_m},
          {"dropout_grazing_probability", f.dropout_grazing_probability},
          {"dropout_grazing_from_deg", f.dropout_grazing_from_deg},
          {"depth_edge_m", f.depth_edge_m},
          {"mixed_pixel_probability", f.mixed_pixel_probability},
          {"short_probability", f.short_probability},
          {"short_mean_m", f.short_mean_m}};
}

Json SpreadJson(const RobustSpread& s) { return {{"n", s.count}, {"median_m", s.median}, {"sigma_m", s.sigma}}; }

Json SpreadsJson(const std::vector<RobustSpread>& spreads) {
  Json array = Json::array();
  for (const RobustSpread& s : spreads) array.push_back(SpreadJson(s));
  return array;
}

Json RateJson(const BinnedRate& r) {
  Json array = Json::array();
  for (size_t k = 0; k < r.trials.size(); ++k) {
    array.push_back({{"events", r.events[k]}, {"trials", r.trials[k]}, {"rate", r.Rate(k)}});
  }
  return array;
}

Json TallyJson(const BeamTally& t, const BeamTallyOptions& bins) {
  Json outcomes = Json::object();
  for (int k = 0; k < kNumBeamOutcomes; ++k) outcomes[kOutcomeNames[k]] = t.outcomes[k];
  std::vector<float> shorts = t.short_readings_m;
  std::sort(shorts.begin(), shorts.end());
  const auto quantile = [&](double q) { return shorts.empty() ? NAN : shorts[size_t(q * (shorts.size() - 1))]; };
  Json j;
  j["outcomes"] = outcomes;
  j["core_error"] = SpreadJson(RobustSpreadOf(CoreErrors(t)));
  j["core_error_by_range"] = SpreadsJson(SpreadByRange(t, bins.range_bins_m));
  j["core_error_by_incidence"] = SpreadsJson(SpreadByIncidence(t, bins.incidence_bins_deg));
  j["dropout_by_range"] = RateJson(t.dropout_by_range);
  j["dropout_by_incidence"] = RateJson(t.dropout_by_incidence);
  j["dropout_rate"] = double(t.dropout_by_range.Events()) / std::max(1L, t.dropout_by_range.Trials());
  j["short_by_range"] = RateJson(t.short_by_range);
  j["short_in_free"] = t.short_in_free;
  j["free_trials"] = t.free_trials;
  j["short_rate"] = t.ShortRate();
  j["short_reading_quantiles_m"] = {{"q10", quantile(0.1)}, {"q50", quantile(0.5)}, {"q90", quantile(0.9)}};
  j["long_rate"] = t.LongRate();
  j["long_events"] = t.long_events;
  j["edge_trials"] = t.edge_trials;
  j["mixed_rate"] = t.MixedRate();
  return j;
}

Json DistanceJson(const TallyDistance& d) {
  return {{"error_jsd", d.error_jsd},
          {"error_w1_m", d.error_w1_m},
          {"outcome_jsd", d.outcome_jsd},
          {"dropout_range_mean_abs_diff", d.dropout_range_w1},
          {"dropout_incidence_mean_abs_diff", d.dropout_incidence_w1},
          {"short_rate_real", d.short_rate_real},
          {"short_rate_sim", d.short_rate_sim},
          {"short_range_w1_m", d.short_range_w1_m}};
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
  Json j;
  j["logs"] = r.logs;
  j["split"] = r.split;
  j["seed"] = r.seed;
  j["range_bins_m"] = r.bins.range_bins_m;
  j["incidence_bins_deg"] = r.bins.incidence_bins_deg;
  j["depth_edge_m"] = r.bins.depth_edge_m;
  j["gate"] = {{"gate_m", r.bins.gate_m}, {"gate_fraction", r.bins.gate_fraction}};
  j["fitted"] = FittedJson(r.fitted);
  j["gaussian"] = {{"range_noise_stddev_m", r.gaussian_stddev_m}, {"dropout_probability", r.gaussian_dropout}};
  Json per_log = Json::object();
  for (const NamedTally& n : r.per_log) per_log[n.name] = TallyJson(*n.tally, r.bins);
  j["per_log"] = per_log;
  j["real"] = TallyJson(*r.real.tally, r.bins);
  j["fitted_sim"] = TallyJson(*r.fitted_sim.tally, r.bins);
  j["gaussian_sim"] = TallyJson(*r.gaussian_sim.tally, r.bins);
  j["distance_fitted"] = DistanceJson(r.fitted_distance);
  j["distance_gaussian"] = DistanceJson(r.gaussian_distance);
  std::ofstream out(path);
  out << ResultJsonText(j);
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
  std::printf("\nfitted: %s\n", ResultJsonLine(FittedJson(r.fitted)).c_str());
  std::printf("distance real vs fitted:   %s\n", ResultJsonLine(DistanceJson(r.fitted_distance)).c_str());
  std::printf("distance real vs gaussian: %s\n", ResultJsonLine(DistanceJson(r.gaussian_distance)).c_str());
}

}  // namespace doorplate_localization::tools

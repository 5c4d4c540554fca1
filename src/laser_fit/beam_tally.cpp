#include "doorplate_localization/laser_fit/beam_tally.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

void RequireAscending(const std::vector<double>& edges, const char* field) {
  if (edges.size() < 2 || !std::is_sorted(edges.begin(), edges.end()) ||
      std::adjacent_find(edges.begin(), edges.end()) != edges.end()) {
    throw std::invalid_argument(std::string("BeamTallyOptions.") + field + ": need >= 2 strictly ascending edges");
  }
}

}  // namespace

long BinnedRate::Events() const { return std::accumulate(events.begin(), events.end(), 0L); }
long BinnedRate::Trials() const { return std::accumulate(trials.begin(), trials.end(), 0L); }

double BeamTally::ShortRate() const {
  const long trials = short_by_range.Trials() + free_trials;
  return trials ? static_cast<double>(short_by_range.Events() + short_in_free) / trials : 0.0;
}

double BeamTally::MixedRate() const {
  return edge_trials ? static_cast<double>(Count(BeamOutcome::kMixed)) / edge_trials : 0.0;
}

BeamTallier::BeamTallier(const BeamTallyOptions& options) : options_(options) {
  RequireAscending(options.range_bins_m, "range_bins_m");
  RequireAscending(options.incidence_bins_deg, "incidence_bins_deg");
  if (!(options.depth_edge_m > 0.0)) throw std::invalid_argument("BeamTallyOptions.depth_edge_m: must be > 0");
  if (!(options.gate_m > 0.0)) throw std::invalid_argument("BeamTallyOptions.gate_m: must be > 0");
  if (!(options.gate_fraction >= 0.0)) throw std::invalid_argument("BeamTallyOptions.gate_fraction: must be >= 0");
  const size_t nr = options.range_bins_m.size() - 1, ni = options.incidence_bins_deg.size() - 1;
  tally_.dropout_by_range.Resize(nr);
  tally_.short_by_range.Resize(nr);
  tally_.dropout_by_incidence.Resize(ni);
}

int BeamTallier::Bin(const std::vector<double>& edges, double value) {
  if (!(value >= edges.front()) || value > edges.back()) return -1;
  const auto it = std::upper_bound(edges.begin(), edges.end(), value);
  return std::min(static_cast<int>(it - edges.begin()) - 1, static_cast<int>(edges.size()) - 2);
}

std::vector<BeamOutcome> BeamTallier::AddScan(const std::vector<ExpectedBeam>& expected,
                                              const std::vector<float>& readings_m, double max_range_m) {
  if (expected.size() != readings_m.size()) {
    throw std::invalid_argument("BeamTallier::AddScan: " + std::to_string(expected.size()) + " expected beams but " +
                                std::to_string(readings_m.size()) + " readings");
  }
  std::vector<BeamOutcome> out(expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    out[i] = Classify(expected, i, readings_m[i], max_range_m);
    ++tally_.outcomes[static_cast<int>(out[i])];
  }
  return out;
}

BeamOutcome BeamTallier::Classify(const std::vector<ExpectedBeam>& expected, size_t i, double reading,
                                  double max_range_m) {
  BeamTally& t = tally_;
  const ExpectedBeam& e = expected[i];
  if (std::isnan(reading) || reading < 0.0 || e.kind == ExpectedKind::kUnknown) return BeamOutcome::kSkipped;
  const bool no_return = std::isinf(reading);
  if (e.kind == ExpectedKind::kNothing) {
    ++t.free_trials;
    t.free_limit_m = max_range_m - Gate(max_range_m);
    if (!no_return && reading < max_range_m - Gate(max_range_m)) {
      ++t.short_in_free;
      t.short_readings_m.push_back(static_cast<float>(reading));
      t.short_cuts_m.push_back(static_cast<float>(t.free_limit_m));
      return BeamOutcome::kShort;
    }
    return BeamOutcome::kFreeClear;
  }
  // A hit: is a neighbour's expected surface much nearer or farther (a depth edge)?
  double other = NAN;
  for (const size_t j : {i - 1, i + 1}) {
    if (i == 0 && j == i - 1) continue;
    if (j >= expected.size()) continue;
    const ExpectedBeam& n = expected[j];
    if (n.kind != ExpectedKind::kHit) return BeamOutcome::kSkipped;  // an edge to open or unknown space
    const double step = std::fabs(n.range_m - e.range_m);
    if (step > options_.depth_edge_m && (std::isnan(other) || step > std::fabs(other - e.range_m))) other = n.range_m;
  }
  if (!std::isnan(other)) {
    ++t.edge_trials;
    const double near = std::min(e.range_m, other), far = std::max(e.range_m, other);
    t.edge_mixed_visible += std::max(0.0, far - Gate(far) - near - Gate(near)) / (far - near);
    if (no_return) return BeamOutcome::kEdgeDropout;
    if (std::fabs(reading - near) <= Gate(near)) return BeamOutcome::kEdgeNear;
    if (std::fabs(reading - far) <= Gate(far)) return BeamOutcome::kEdgeFar;
    if (reading > near && reading < far) return BeamOutcome::kMixed;
    return BeamOutcome::kEdgeOther;
  }
  const int rb = Bin(options_.range_bins_m, e.range_m);
  if (rb < 0) return BeamOutcome::kSkipped;
  const float incidence_deg = e.surface_fit ? static_cast<float>(e.incidence_rad * 180.0 / M_PI) : NAN;
  const int ib = e.surface_fit ? Bin(options_.incidence_bins_deg, incidence_deg) : -1;
  t.hits.push_back({static_cast<float>(e.range_m), incidence_deg, no_return});
  ++t.dropout_by_range.trials[rb];
  ++t.short_by_range.trials[rb];
  if (ib >= 0) ++t.dropout_by_incidence.trials[ib];
  if (no_return) {
    ++t.dropout_by_range.events[rb];
    if (ib >= 0) ++t.dropout_by_incidence.events[ib];
    return BeamOutcome::kDropout;
  }
  ++t.long_trials;
  const double error = reading - e.range_m;
  if (error < -Gate(e.range_m)) {
    ++t.short_by_range.events[rb];
    t.short_readings_m.push_back(static_cast<float>(reading));
    t.short_cuts_m.push_back(static_cast<float>(e.range_m - Gate(e.range_m)));
    return BeamOutcome::kShort;
  }
  if (error > Gate(e.range_m)) {
    ++t.long_events;
    return BeamOutcome::kLong;
  }
  if (e.surface_fit) t.core.push_back({static_cast<float>(e.range_m), incidence_deg, static_cast<float>(error)});
  return BeamOutcome::kCore;
}

}  // namespace doorplate_localization

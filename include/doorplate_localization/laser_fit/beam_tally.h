// Sorts the readings of real (or simulated) scans against their expected beams (ReferenceMap::Expect) and
// counts what the laser did (issue 20): range error of the core by range and incidence, dropouts, mixed
// pixels at depth edges, spurious short and long readings. Readings follow REP-117 (+inf: no return);
// NaN and -inf readings (invalid) are skipped. Units: metres; incidence bins in degrees.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "doorplate_localization/laser_fit/reference_map.h"

namespace doorplate_localization {

struct BeamTallyOptions {
  std::vector<double> range_bins_m = {0, 1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 40};  // bin edges, ascending
  std::vector<double> incidence_bins_deg = {0, 15, 30, 45, 60, 70, 80, 90};
  double depth_edge_m = 0.3;   // a hit whose neighbouring beam's expected hit differs by more sits at a depth edge
  double gate_m = 0.15;        // |reading - expected| <= gate_m + gate_fraction * expected: the core
  double gate_fraction = 0.02;
};

enum class BeamOutcome : std::uint8_t {
  kCore,        // a return near the expected surface
  kDropout,     // no return where a surface was expected
  kShort,       // a return well before the expected surface (or in free space)
  kLong,        // a return well behind the expected surface
  kEdgeNear,    // depth edge: the return is on the near surface
  kEdgeFar,     // ... on the far surface
  kMixed,       // ... between the two: a mixed pixel
  kEdgeDropout, // ... no return
  kEdgeOther,   // ... anything else (before the near surface, behind the far one)
  kFreeClear,   // nothing expected, nothing (or something beyond the evaluated range) returned
  kSkipped,     // unknown expectation, an edge to unknown or open space, or an invalid reading
};
constexpr int kNumBeamOutcomes = 11;

// Event counts per bin: events[k] of trials[k].
struct BinnedRate {
  std::vector<long> events, trials;
  void Resize(size_t n) { events.assign(n, 0), trials.assign(n, 0); }
  double Rate(size_t k) const { return trials[k] ? static_cast<double>(events[k]) / trials[k] : 0.0; }
  long Events() const;
  long Trials() const;
};

// A core return on a fitted surface.
struct CoreReturn {
  float range_m;        // expected
  float incidence_deg;
  float error_m;        // reading - expected
};

// An expected hit off any depth edge: did the laser return anything?
struct HitTrial {
  float range_m;        // expected
  float incidence_deg;  // NaN without a surface fit
  bool dropped;
};

struct BeamTally {
  std::array<long, kNumBeamOutcomes> outcomes{};
  std::vector<CoreReturn> core;                        // surface-fit core returns, in scan order
  std::vector<HitTrial> hits;                          // off-edge expected hits
  BinnedRate dropout_by_range, dropout_by_incidence;   // of `hits`, per bin (incidence: surface fits only)
  BinnedRate short_by_range;                           // trials: off-edge hits per range bin
  long short_in_free = 0, free_trials = 0;             // spurious returns where nothing was expected
  std::vector<float> short_readings_m;                 // every short return's reading
  std::vector<float> short_cuts_m;                     // ... and the range below which it counted as short
  long long_events = 0, long_trials = 0;               // long returns among off-edge hits with a return
  long edge_trials = 0;                                // depth-edge beams, both surfaces hits
  // Sum over depth-edge beams of the fraction of the gap between the surfaces that is outside both
  // gates: where a mixed pixel uniform over the gap can be told from a return on either surface.
  double edge_mixed_visible = 0.0;
  double free_limit_m = 0.0;                           // a free-space return is short below this

  long Count(BeamOutcome o) const { return outcomes[static_cast<int>(o)]; }
  // Short returns per beam that could have one (off-edge hits and free beams).
  double ShortRate() const;
  // Mixed pixels per depth-edge beam (as seen: those within a gate of either surface do not count).
  double MixedRate() const;
  double LongRate() const { return long_trials ? static_cast<double>(long_events) / long_trials : 0.0; }
};

class BeamTallier {
 public:
  // Throws std::invalid_argument naming the field of bad options.
  explicit BeamTallier(const BeamTallyOptions& options);

  // One scan: `expected[i]` and `readings_m[i]` are beam i; neighbours are i - 1 and i + 1 (no wrap).
  // `max_range_m`: the range the expectations were cast to (free-space returns beyond max_range_m -
  // gate are not short). Returns each beam's outcome. Throws std::invalid_argument on a size mismatch.
  std::vector<BeamOutcome> AddScan(const std::vector<ExpectedBeam>& expected, const std::vector<float>& readings_m,
                                   double max_range_m);

  const BeamTally& tally() const { return tally_; }
  const BeamTallyOptions& options() const { return options_; }
  double Gate(double expected_m) const { return options_.gate_m + options_.gate_fraction * expected_m; }
  // Bin of a value (edges ascending); -1 outside.
  static int Bin(const std::vector<double>& edges, double value);

 private:
  BeamOutcome Classify(const std::vector<ExpectedBeam>& expected, size_t i, double reading, double max_range_m);

  BeamTallyOptions options_;
  BeamTally tally_;
};

}  // namespace doorplate_localization

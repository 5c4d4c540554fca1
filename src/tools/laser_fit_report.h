// doorplate_laser_fit's outputs: the comparison of real and simulated tallies (distances), the JSON file
// (nlohmann-json, as the results files: result_json.h) and the side-by-side plot (OpenCV). ROS-free.
#pragma once

#include <string>
#include <vector>

#include "doorplate_localization/laser_fit/beam_tally.h"
#include "doorplate_localization/laser_fit/laser_error_fit.h"
#include "doorplate_localization/sim/sensor_options.h"

namespace doorplate_localization::tools {

// One set of scans, tallied: a real log, all logs pooled, or scans simulated at the same poses.
struct NamedTally {
  std::string name;
  const BeamTally* tally;
};

// How far a simulated tally is from the real one.
struct TallyDistance {
  double error_jsd = 0.0;           // core error histograms (±error_window_m, 5 mm bins)
  double error_w1_m = 0.0;          // core errors, 1-D Wasserstein
  double outcome_jsd = 0.0;         // per-beam outcome frequencies (core, dropout, short, long, mixed, ...)
  double dropout_range_w1 = 0.0;    // weighted mean |rate difference| over range bins (trials of the real)
  double dropout_incidence_w1 = 0.0;  // same over incidence bins
  double short_rate_real = 0.0, short_rate_sim = 0.0;
  double short_range_w1_m = 0.0;    // the short readings' ranges, 1-D Wasserstein (0 if either has none)
};
constexpr double kErrorWindowM = 0.15;

TallyDistance CompareTallies(const BeamTally& real, const BeamTally& sim);

struct LaserFitReport {
  std::vector<std::string> logs;
  std::vector<NamedTally> per_log;        // real, one per log
  NamedTally real, fitted_sim, gaussian_sim;
  BeamTallyOptions bins;
  FittedLaserErrorOptions fitted;
  double gaussian_stddev_m = 0.0, gaussian_dropout = 0.0;
  TallyDistance fitted_distance, gaussian_distance;
  std::uint64_t seed = 0;
  std::string split;                      // how map and evaluation scans were chosen
};

// Writes the report as JSON; throws std::runtime_error naming the path if it cannot.
void WriteLaserFitJson(const LaserFitReport& report, const std::string& path);
// Human-readable tables on stdout.
void PrintLaserFitReport(const LaserFitReport& report);
// Four panels: core error histograms, dropout rate vs range, dropout rate vs incidence, short-return rate
// vs range, real beside both models, distances in the legends. Throws std::runtime_error if it cannot write.
void WriteLaserFitPlot(const LaserFitReport& report, const std::string& path);

}  // namespace doorplate_localization::tools

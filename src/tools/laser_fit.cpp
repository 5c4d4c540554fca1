// doorplate_laser_fit: measures a real laser's errors on CARMEN logs whose FLASER poses are SLAM-corrected
// (the truth), fits the simulator's "fitted" laser error model to them, and compares scans simulated with
// that model and with the old gaussian one at the same poses against the same reference grid (issue 20).
// Per log: the even-indexed scans draw the reference map (ReferenceMap), the odd-indexed scans are judged
// against it (BeamTallier), so no scan is judged against a map it drew. Outputs: tables on stdout,
// --json, --plot.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <zlib.h>

#include "cli_app.h"
#include "laser_fit_report.h"
#include "map_tool_output.h"
#include "output_guard.h"
#include "doorplate_localization/laser_fit/beam_tally.h"
#include "doorplate_localization/laser_fit/laser_error_fit.h"
#include "doorplate_localization/laser_fit/reference_map.h"
#include "doorplate_localization/sim/laser_error_model.h"
#include "doorplate_localization/slam/carmen_reader.h"

namespace dl = doorplate_localization;
namespace tools = doorplate_localization::tools;

namespace {

const char kDescription[] =
    "Fits the simulator's laser error model to CARMEN logs with corrected poses and compares it with the gaussian one.";
const char kNotes[] =
    "FILE: a CARMEN log with corrected poses (.log or .log.gz). Even-indexed scans draw the reference\n"
    "grid, odd-indexed scans are judged against it.";

struct Args {
  std::vector<std::string> logs;
  std::uint64_t seed = 1;
  std::string json, plot;
  dl::ReferenceMapOptions map;
  dl::BeamTallyOptions bins;
};

// The last range bin ends at --max-range-m (bins beyond it dropped).
void FitRangeBins(Args* a) {
  std::vector<double>& bins = a->bins.range_bins_m;
  if (bins.back() <= a->map.max_range_m) return;
  while (bins.size() > 2 && bins[bins.size() - 2] >= a->map.max_range_m) bins.pop_back();
  bins.back() = a->map.max_range_m;
}

void AddOptions(CLI::App* app, Args* args) {
  app->footer(kNotes);
  app->add_option("--log", args->logs, "a CARMEN log FILE (repeatable)")->required()->allow_extra_args(false);
  app->add_option("--seed", args->seed, "the simulated scans' random draws")->capture_default_str()
      ->transform(tools::Seed());
  app->add_option("--json", args->json, "write the report as JSON here");
  app->add_option("--plot", args->plot, "draw the distributions into this PNG");
  app->add_option("--max-range-m", args->map.max_range_m, "expected ranges are cast this far")->capture_default_str()
      ->check(tools::PositiveNumber());
  app->add_option("--resolution-m", args->map.resolution_m, "reference grid cell size")->capture_default_str()
      ->check(tools::PositiveNumber());
  app->add_option("--depth-edge-m", args->bins.depth_edge_m, "depth step that makes a beam an edge beam")
      ->capture_default_str()->check(tools::PositiveNumber());
  app->callback([args] { FitRangeBins(args); });
}

// A log, unpacked through zlib (which also reads plain text).
dl::CarmenLog ReadLog(const std::string& path) {
  gzFile file = gzopen(path.c_str(), "rb");
  if (!file) throw std::runtime_error(path + ": cannot open");
  std::string text;
  char buffer[1 << 16];
  int n = 0;
  while ((n = gzread(file, buffer, sizeof(buffer))) > 0) text.append(buffer, n);
  const bool failed = n < 0;
  gzclose(file);
  if (failed) throw std::runtime_error(path + ": cannot unpack (corrupt gzip data)");
  std::istringstream stream(text);
  dl::CarmenLog log = dl::ReadCarmenLog(stream, path);
  if (log.scans.size() < 2) throw std::runtime_error(path + ": fewer than two FLASER lines");
  return log;
}

// One judged scan: what each beam should read, and what it read.
struct JudgedScan {
  std::vector<dl::ExpectedBeam> expected;
  std::vector<float> readings_m;
};

std::vector<JudgedScan> JudgeLog(const dl::CarmenLog& log, const dl::ReferenceMapOptions& map_options) {
  dl::ReferenceMap map(map_options);
  for (size_t k = 0; k < log.scans.size(); k += 2) map.AddScan(log.scans[k].laser_pose, log.scans[k].scan);
  map.Finish();
  std::vector<JudgedScan> judged;
  for (size_t k = 1; k < log.scans.size(); k += 2) {
    const dl::CarmenScan& s = log.scans[k];
    JudgedScan j;
    j.readings_m = s.scan.ranges_m;
    for (size_t i = 0; i < j.readings_m.size(); ++i) {
      float& r = j.readings_m[i];
      if (r < s.scan.min_range_m) r = NAN;  // CARMEN's 0: no reading at all
      j.expected.push_back(map.Expect(s.laser_pose.Position(), s.laser_pose.theta_rad + s.scan.BeamAngle(int(i)),
                                      map_options.max_range_m));
    }
    judged.push_back(std::move(j));
  }
  return judged;
}

// The model applied to the expected ranges: the same geometry as the real scan.
std::vector<float> SimulateReadings(const JudgedScan& j, const dl::LaserErrorModel& model, double max_range_m,
                                    std::mt19937_64& rng) {
  std::vector<float> ranges, incidence;
  for (const dl::ExpectedBeam& e : j.expected) {
    ranges.push_back(e.kind == dl::ExpectedKind::kHit       ? static_cast<float>(e.range_m)
                     : e.kind == dl::ExpectedKind::kNothing ? INFINITY
                                                            : NAN);
    incidence.push_back(e.surface_fit ? static_cast<float>(e.incidence_rad) : NAN);
  }
  constexpr double kCarmenMinRangeM = 0.01;  // CarmenReaderOptions::min_range_m
  model.Apply(&ranges, incidence, kCarmenMinRangeM, max_range_m, false, rng);
  return ranges;
}

int Run(const Args& args) {
  const tools::Stopwatch clock;
  std::vector<tools::NamedPath> inputs;
  for (const std::string& log : args.logs) inputs.push_back({"--log", log});
  tools::RefuseOverwritingInputs(inputs, {{"--json", args.json}, {"--plot", args.plot}});
  const double max_range = args.map.max_range_m;
  dl::BeamTallier pooled(args.bins);
  std::vector<dl::BeamTallier> per_log;
  std::vector<std::vector<JudgedScan>> judged;
  for (const std::string& path : args.logs) {
    const dl::CarmenLog log = ReadLog(path);
    judged.push_back(JudgeLog(log, args.map));
    per_log.emplace_back(args.bins);
    for (const JudgedScan& j : judged.back()) {
      per_log.back().AddScan(j.expected, j.readings_m, max_range);
      pooled.AddScan(j.expected, j.readings_m, max_range);
    }
    std::fprintf(stderr, "doorplate_laser_fit: %s: %zu scans, %zu judged, no-return %.2f m, %.1f s\n", path.c_str(),
                 log.scans.size(), judged.back().size(), log.no_return_range_m, clock.Seconds());
  }
  dl::LaserErrorFitOptions fit_options;
  fit_options.depth_edge_m = args.bins.depth_edge_m;
  const dl::FittedLaserErrorOptions fitted = dl::FitLaserErrors(pooled.tally(), args.bins, fit_options);
  const dl::LaserOptions defaults;
  const dl::FittedLaserErrorModel fitted_model(fitted);
  const dl::GaussianLaserErrorModel gaussian_model(defaults.range_noise_stddev_m, defaults.dropout_probability);
  dl::BeamTallier fitted_sim(args.bins), gaussian_sim(args.bins);
  std::mt19937_64 rng(args.seed);
  for (const auto& scans : judged) {
    for (const JudgedScan& j : scans) {
      fitted_sim.AddScan(j.expected, SimulateReadings(j, fitted_model, max_range, rng), max_range);
      gaussian_sim.AddScan(j.expected, SimulateReadings(j, gaussian_model, max_range, rng), max_range);
    }
  }
  tools::LaserFitReport report;
  report.logs = args.logs;
  for (size_t k = 0; k < args.logs.size(); ++k) report.per_log.push_back({args.logs[k], &per_log[k].tally()});
  report.real = {"real", &pooled.tally()};
  report.fitted_sim = {"fitted model", &fitted_sim.tally()};
  report.gaussian_sim = {"gaussian model", &gaussian_sim.tally()};
  report.bins = args.bins;
  report.fitted = fitted;
  report.gaussian_stddev_m = defaults.range_noise_stddev_m;
  report.gaussian_dropout = defaults.dropout_probability;
  report.fitted_distance = tools::CompareTallies(pooled.tally(), fitted_sim.tally());
  report.gaussian_distance = tools::CompareTallies(pooled.tally(), gaussian_sim.tally());
  report.seed = args.seed;
  report.split = "per log: even-indexed scans draw the reference grid, odd-indexed scans are judged";
  tools::PrintLaserFitReport(report);
  if (!args.json.empty()) tools::WriteLaserFitJson(report, args.json);
  if (!args.plot.empty()) tools::WriteLaserFitPlot(report, args.plot);
  std::fprintf(stderr, "doorplate_laser_fit: done in %.1f s, peak RSS %.0f MB\n", clock.Seconds(), tools::PeakRssMb());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::RunTool("doorplate_laser_fit", kDescription, AddOptions, Run, argc, argv);
}

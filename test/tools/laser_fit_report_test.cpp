// doorplate_laser_fit's JSON report (laser_fit_report.h) on a hand-made tally: members, counts as whole
// numbers, rates, and null where a value does not exist.
#include "laser_fit_report.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace doorplate_localization::tools {
namespace {

// Three core returns, two dropouts (one of four hits in the 1-2 m bin), no short reading.
BeamTally SmallTally(const BeamTallyOptions& bins) {
  BeamTally t;
  t.outcomes[static_cast<int>(BeamOutcome::kCore)] = 3;
  t.outcomes[static_cast<int>(BeamOutcome::kDropout)] = 2;
  t.core = {{1.5f, 10.0f, 0.01f}, {1.6f, 12.0f, -0.01f}, {2.5f, 20.0f, 0.02f}};
  t.dropout_by_range.Resize(bins.range_bins_m.size() - 1);
  t.dropout_by_range.events[1] = 1;
  t.dropout_by_range.trials[1] = 4;
  t.dropout_by_incidence.Resize(bins.incidence_bins_deg.size() - 1);
  t.short_by_range.Resize(bins.range_bins_m.size() - 1);
  return t;
}

nlohmann::ordered_json WriteAndRead(const LaserFitReport& report) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("laser_fit_report_test_" + std::to_string(::getpid()) + ".json")).string();
  WriteLaserFitJson(report, path);
  std::ifstream in(path);
  const nlohmann::ordered_json json = nlohmann::ordered_json::parse(in);
  std::filesystem::remove(path);
  return json;
}

TEST(WriteLaserFitJson, WritesTheTalliesFitAndDistancesAsJson) {
  LaserFitReport report;
  const BeamTally tally = SmallTally(report.bins);
  report.logs = {"a \"quoted\".log"};
  report.per_log = {{"a \"quoted\".log", &tally}};
  report.real = {"real", &tally};
  report.fitted_sim = {"fitted model", &tally};
  report.gaussian_sim = {"gaussian model", &tally};
  report.fitted.noise_base_m = 0.016;
  report.fitted.short_mean_m = NAN;  // not fitted: no number in JSON
  report.gaussian_stddev_m = 0.01;
  report.seed = 7;
  report.split = "even scans draw the grid";
  report.fitted_distance.error_jsd = 0.125;

  const nlohmann::ordered_json j = WriteAndRead(report);
  EXPECT_EQ(j.begin().key(), "logs");  // members in the order of before
  EXPECT_EQ(j["logs"][0], "a \"quoted\".log");
  EXPECT_EQ(j["seed"], 7);
  EXPECT_EQ(j["range_bins_m"].size(), report.bins.range_bins_m.size());
  EXPECT_DOUBLE_EQ(j["fitted"]["noise_base_m"].get<double>(), 0.016);
  EXPECT_TRUE(j["fitted"]["short_mean_m"].is_null());
  EXPECT_DOUBLE_EQ(j["gaussian"]["range_noise_stddev_m"].get<double>(), 0.01);
  const nlohmann::ordered_json& log = j["per_log"]["a \"quoted\".log"];
  EXPECT_TRUE(log["outcomes"]["core"].is_number_integer());
  EXPECT_EQ(log["outcomes"]["core"], 3);
  EXPECT_EQ(log["outcomes"]["dropout"], 2);
  EXPECT_EQ(log["outcomes"].size(), static_cast<size_t>(kNumBeamOutcomes));
  EXPECT_EQ(log["core_error"]["n"], 3);
  EXPECT_EQ(log["dropout_by_range"][1]["events"], 1);
  EXPECT_DOUBLE_EQ(log["dropout_by_range"][1]["rate"].get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(log["dropout_rate"].get<double>(), 0.25);
  EXPECT_TRUE(j["real"]["short_reading_quantiles_m"]["q50"].is_null());  // no short reading
  EXPECT_DOUBLE_EQ(j["distance_fitted"]["error_jsd"].get<double>(), 0.125);
  EXPECT_TRUE(j.contains("distance_gaussian"));
}

TEST(WriteLaserFitJson, ThrowsNamingAPathItCannotWrite) {
  LaserFitReport report;
  const BeamTally tally = SmallTally(report.bins);
  report.real = report.fitted_sim = report.gaussian_sim = {"t", &tally};
  try {
    WriteLaserFitJson(report, "/nonexistent-folder/report.json");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/report.json"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace doorplate_localization::tools

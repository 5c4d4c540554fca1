// JSON of the localization experiment: Table III totals, kidnap totals and per-trial rows.
#include "localize_eval_json.h"

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

LocalizeTrial Trial(int index, bool converged, double error_m, double travel_m) {
  LocalizeTrial t;
  t.index = index;
  t.seed = 100 + index;
  t.converged = converged;
  t.fix.travel_m = travel_m;
  t.fix.error_m = error_m;
  t.fix.error_deg = 2.0;
  t.fix.within_tolerance = converged && error_m <= 0.3;
  t.fix.truth = {1.0, 2.0, 0.5};
  return t;
}

// A success after 4 m, a wrong convergence (5 m off) after 8 m, and a search that never converged.
LocalizeEvalResult ThreeTrials(bool kidnap) {
  LocalizeEvalResult r;
  r.world_name = "w";
  r.method = LocalizeMethod::kAmcl;
  r.kidnap = kidnap;
  r.trials = {Trial(0, true, 0.1, 4.0), Trial(1, true, 5.0, 8.0), Trial(2, false, 9.0, 120.0)};
  if (kidnap) {
    r.trials[0].kidnapped = true;
    r.trials[0].kidnap_pose = {7.0, 1.0, 3.0};
    r.trials[0].recovered = true;
    r.trials[0].recovery.travel_m = 6.5;
    r.trials[0].recovery.within_tolerance = true;
  }
  r.seconds = 12.0;
  return r;
}

std::string JsonText(const LocalizeEvalResult& result) {
  LocalizeEvalRunInfo info;
  info.world_file = "worlds/w.yaml";
  info.map_file = "maps/w.text_map.yaml";
  info.command_line = "doorplate_eval localize --world worlds/w.yaml";
  info.options.seed = 7;
  return ResultJsonText(LocalizeEvalJson(result, info));
}

TEST(LocalizeEvalJson, WritesTheTableThreeTotalsAndTheRun) {
  const std::string json = JsonText(ThreeTrials(false));
  for (const char* expected :
       {"\"method\": \"amcl\"", "\"seed\": 7,", "\"trials\": 3,", "\"successes\": 1,", "\"success_rate\": 0.3333333333,",
        "\"wrong_convergences\": 1,", "\"not_converged\": 1,", "\"median_travel_m\": 6,", "\"longest_travel_m\": 8,",
        "\"median_final_error_m\": 2.55,", "\"median_final_error_deg\": 2,", "\"seconds\": 12,",
        "\"command_line\": \"doorplate_eval localize --world worlds/w.yaml\"", "\"map_file\": \"maps/w.text_map.yaml\""}) {
    EXPECT_NE(json.find(expected), std::string::npos) << expected << "\n" << json;
  }
  EXPECT_EQ(json.find("recoveries"), std::string::npos);  // no kidnap totals without kidnapping
}

TEST(LocalizeEvalJson, WritesOneRowPerTrialNamedByItsOutcome) {
  const std::string json = JsonText(ThreeTrials(false));
  EXPECT_NE(json.find("\"wrong_convergence\": true"), std::string::npos);
  EXPECT_NE(json.find("\"convergence\": {"), std::string::npos);
  EXPECT_NE(json.find("\"end_of_search\": {"), std::string::npos);
  EXPECT_NE(json.find("\"truth\": [\n          1,\n          2,\n          0.5\n        ]"), std::string::npos) << json;
}

TEST(LocalizeEvalJson, RecordsTheDriveAndWhereTheStartPosesCameFrom) {
  LocalizeEvalResult result = ThreeTrials(false);
  EXPECT_NE(JsonText(result).find("\"start_poses\": \"main corridor band\""), std::string::npos);
  EXPECT_NE(JsonText(result).find("\"drive\": \"patrol\""), std::string::npos);
  result.floor_start_poses = true;
  EXPECT_NE(JsonText(result).find("\"start_poses\": \"floor: the world's corridors, length-weighted\""), std::string::npos);
}

TEST(LocalizeEvalJson, AddsTheKidnapTotalsWhenKidnapping) {
  const std::string json = JsonText(ThreeTrials(true));
  EXPECT_NE(json.find("\"kidnaps\": 1,"), std::string::npos) << json;
  EXPECT_NE(json.find("\"recoveries\": 1,"), std::string::npos);
  EXPECT_NE(json.find("\"recovery_rate\": 1,"), std::string::npos);
  EXPECT_NE(json.find("\"median_recovery_travel_m\": 6.5,"), std::string::npos);
  EXPECT_NE(json.find("\"recovery\": {"), std::string::npos);
  EXPECT_NE(json.find("\"kidnapped\": false"), std::string::npos);  // the trials that were not kidnapped
}

}  // namespace
}  // namespace doorplate_localization

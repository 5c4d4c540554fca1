// JSON form of a LocalizeEvalResult (doorplate_eval localize --json): the run's settings and command line,
// the Table III totals (trials, successes, success_rate, wrong_convergences, medians), the kidnap totals
// when kidnapping was on, and one row per trial. Poses are [x_m, y_m, theta_rad] in the map frame.
#pragma once

#include <string>

#include "localize_eval.h"
#include "result_json.h"

namespace doorplate_localization {

struct LocalizeEvalRunInfo {
  std::string world_file;
  std::string map_file;      // the text map (its occupancy_map names the grid)
  std::string command_line;  // how the run was started, for the record
  LocalizeEvalOptions options;
};

Json LocalizeEvalJson(const LocalizeEvalResult& result, const LocalizeEvalRunInfo& info);

}  // namespace doorplate_localization

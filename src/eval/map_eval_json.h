// JSON of one `doorplate_eval map` run (the fields of paper Table II plus run facts); see
// docs/results/table2-map.md for the meaning of each field.
#pragma once

#include <string>

#include "map_eval.h"
#include "result_json.h"

namespace doorplate_localization {

struct MapEvalRunInfo {
  std::string world_path;
  std::string command_line;
  MapMethod method = MapMethod::kRbpfText;
  std::uint64_t seed = 1;
  int particles = 0;
  MapDrive drive = MapDrive::kSweep;
};

// One object: length_true_m, length_est_m, length_accuracy, width_true_m, width_est_m, width_accuracy,
// plates_true, plates_mapped, plate_position_rmse_m, plate_max_error_m, seconds, ... and the per-plate list.
Json MapEvalJson(const MapEvalResult& result, const MapEvalRunInfo& info);

}  // namespace doorplate_localization

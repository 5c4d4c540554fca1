// JSON form of an OcrEvalResult (doorplate_eval ocr --json): totals, Figure 12 detector statistics,
// per-pass and per-plate detail, and every reading error with its frame time and box.
#pragma once

#include <string>

#include "ocr_eval.h"
#include "result_json.h"

namespace doorplate_localization {

struct OcrEvalRunInfo {
  std::string world_file;
  std::string command_line;  // how the run was started, for the record
  OcrEvalOptions options;
};

Json OcrEvalJson(const OcrEvalResult& result, const OcrEvalRunInfo& info);

}  // namespace doorplate_localization

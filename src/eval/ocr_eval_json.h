// JSON form of an OcrEvalResult (doorplate_eval ocr --json): totals, Figure 12 detector statistics,
// per-pass and per-plate detail, and every reading error with its frame time and box.
#pragma once

#include <string>

#include "json_writer.h"
#include "ocr_eval.h"

namespace doorplate_localization {

struct OcrEvalRunInfo {
  std::string world_file;
  std::string command_line;  // how the run was started, for the record
  OcrEvalOptions options;
};

void WriteOcrEvalJson(const OcrEvalResult& result, const OcrEvalRunInfo& info, JsonWriter* json);

}  // namespace doorplate_localization

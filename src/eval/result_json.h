// The JSON of the experiments' results files (doorplate_eval --json, doorplate_read_image --json) on
// nlohmann::json: an ordered_json (members in the order they were set) written as the committed
// docs/results/*.json were: two-space indentation, numbers to 10 significant digits and whole ones without
// a fraction ("6", not "6.0"), NaN and ±inf as null (JSON has no form for them), a final newline.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace doorplate_localization {

using Json = nlohmann::ordered_json;

// The text of `json` as a results file holds it. Strings pass through as UTF-8; a byte sequence that is
// not UTF-8 (a recogniser's output cut short) is replaced by U+FFFD rather than losing the file.
std::string ResultJsonText(const Json& json);
// The same numbers and strings on one line without spaces or a final newline (for a console summary).
std::string ResultJsonLine(const Json& json);

}  // namespace doorplate_localization

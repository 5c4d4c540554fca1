#include "result_json.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace doorplate_localization {
namespace {

// `value` with its floating-point numbers rounded to 10 significant digits, whole ones as integers and
// non-finite ones as null.
Json Rounded(const Json& value) {
  if (value.is_structured()) {
    Json copy = value;
    for (auto& item : copy) item = Rounded(item);
    return copy;
  }
  if (!value.is_number_float()) return value;
  const double number = value.get<double>();
  if (!std::isfinite(number)) return nullptr;
  char text[32];
  std::snprintf(text, sizeof(text), "%.10g", number);
  const double rounded = std::strtod(text, nullptr);
  if (rounded == std::trunc(rounded) && std::fabs(rounded) < 1e15) return static_cast<std::int64_t>(rounded);
  return rounded;
}

}  // namespace

std::string ResultJsonText(const Json& json) {
  return Rounded(json).dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::string ResultJsonLine(const Json& json) {
  return Rounded(json).dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace doorplate_localization

// Decimal text of a number for the YAML writers of src/maps: the value rounded to 1e-9 (nanometres,
// nanoradians), then the shortest text that reads back to that double. Every value a person would type
// survives exactly, and arithmetic noise ("3.999999999999999") does not reach the files.
#pragma once

#include <charconv>
#include <cmath>
#include <string>

namespace doorplate_localization {

inline std::string FormatNumber(double value) {
  double rounded = std::round(value * 1e9) / 1e9 + 0.0;  // + 0.0 turns -0 into 0
  if (!std::isfinite(rounded)) rounded = value;
  char buffer[32];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof(buffer), rounded);
  return std::string(buffer, r.ptr);
}

}  // namespace doorplate_localization

// Command-line helpers shared by the ROS-free tools (doorplate_sim_snapshot, doorplate_world_maps,
// doorplate_map_log): the usage error they exit with, and strict number parsing.
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace doorplate_localization::tools {

// A bad command line; the tools print what() and their usage, and exit with status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The whole of `text` as a finite number; nullopt for "", "1.5x", "nan", "inf" or anything not a number.
inline std::optional<double> ParseFiniteNumber(const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace doorplate_localization::tools

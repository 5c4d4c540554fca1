#include "doorplate_localization/text/plate_reading_validator.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace doorplate_localization {

int EditDistance(const std::string& a, const std::string& b) {
  std::vector<int> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = static_cast<int>(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = static_cast<int>(i);
    for (size_t j = 1; j <= b.size(); ++j) {
      const int substitution = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, substitution});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string PlateReadingValidator::Normalize(const std::string& raw_reading) {
  std::string out;
  for (const char ch : raw_reading) {
    const auto c = static_cast<unsigned char>(ch);
    if (std::isspace(c)) continue;
    out.push_back(static_cast<char>(std::toupper(c)));
  }
  return out;
}

PlateReadingValidator::PlateReadingValidator(const PlateReadingValidatorOptions& options)
    : options_(options) {
  try {
    pattern_ = std::regex(options.pattern, std::regex::ECMAScript);
  } catch (const std::regex_error& e) {
    throw std::invalid_argument("PlateReadingValidatorOptions.pattern \"" + options.pattern +
                                "\" is not a valid regex: " + e.what());
  }
  if (options.max_edit_distance < 0) {
    throw std::invalid_argument("PlateReadingValidatorOptions.max_edit_distance must be >= 0");
  }
  for (const std::string& room : options.known_rooms) {
    const std::string normalized = Normalize(room);
    if (normalized.empty() || !std::regex_match(normalized, pattern_)) {
      throw std::invalid_argument("PlateReadingValidatorOptions.known_rooms entry \"" + room +
                                  "\" does not match pattern \"" + options.pattern + "\"");
    }
    if (std::find(known_rooms_.begin(), known_rooms_.end(), normalized) == known_rooms_.end()) {
      known_rooms_.push_back(normalized);
    }
  }
}

std::optional<std::string> PlateReadingValidator::Validate(const std::string& raw_reading) const {
  const std::string reading = Normalize(raw_reading);
  if (reading.empty()) return std::nullopt;
  if (known_rooms_.empty()) {
    if (std::regex_match(reading, pattern_)) return reading;
    return std::nullopt;
  }
  const std::string* match = nullptr;
  int matches = 0;
  for (const std::string& room : known_rooms_) {
    if (room == reading) return room;
    if (EditDistance(room, reading) <= options_.max_edit_distance) {
      match = &room;
      ++matches;
    }
  }
  if (matches == 1) return *match;
  return std::nullopt;
}

}  // namespace doorplate_localization

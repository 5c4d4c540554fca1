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
  // Whitespace goes (OCR inserts spaces between widely spaced glyphs); '-' '.' '/' '·' stay as printed.
  std::string out;
  for (const char ch : raw_reading) {
    const auto c = static_cast<unsigned char>(ch);
    if (std::isspace(c)) continue;
    out.push_back(c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : ch);
  }
  return out;
}

PlateReadingValidator::PlateReadingValidator(const PlateReadingValidatorOptions& options)
    : options_(options) {
  try {
    grammar_.emplace(options.pattern);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("PlateReadingValidatorOptions.pattern: " + std::string(e.what()));
  }
  if (options.max_edit_distance < 0) {
    throw std::invalid_argument("PlateReadingValidatorOptions.max_edit_distance must be >= 0");
  }
  for (const std::string& room : options.known_rooms) {
    if (!grammar_->Accepts(room)) {
      throw std::invalid_argument("PlateReadingValidatorOptions.known_rooms entry \"" + room +
                                  "\" does not match pattern \"" + options.pattern + "\"");
    }
    const KnownRoom known{Normalize(room), CanonicalRoomId(room)};
    const bool seen = std::any_of(known_rooms_.begin(), known_rooms_.end(),
                                  [&](const KnownRoom& k) { return k.canonical == known.canonical; });
    if (!seen) known_rooms_.push_back(known);
  }
}

std::optional<std::string> PlateReadingValidator::Validate(const std::string& raw_reading) const {
  const std::string canonical = CanonicalRoomId(raw_reading);
  if (canonical.empty()) return std::nullopt;
  if (known_rooms_.empty()) {
    if (grammar_->Accepts(canonical)) return Normalize(raw_reading);
    return std::nullopt;
  }
  const KnownRoom* match = nullptr;
  int matches = 0;
  for (const KnownRoom& room : known_rooms_) {
    if (room.canonical == canonical) return room.printed;
    if (EditDistance(room.canonical, canonical) <= options_.max_edit_distance) {
      match = &room;
      ++matches;
    }
  }
  if (matches == 1) return match->printed;
  return std::nullopt;
}

}  // namespace doorplate_localization

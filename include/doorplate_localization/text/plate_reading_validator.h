// Accepts, corrects or drops raw OCR readings of doorplates.
// Without a known room list a reading is kept iff it matches `pattern`. With a list (from the map or a
// floor plan) the list is the stronger prior: an exact member is kept; otherwise the reading is mapped
// to the known room within `max_edit_distance` (Levenshtein: substitution, insertion, deletion) if
// exactly one room is that close, else dropped. This is how single-character OCR confusions are
// handled — 1/7, 4/1, 8/3, 5/6, 0/8, l/1, a lost or doubled glyph — so "274" becomes "214" when 214 is
// a room and 274, 224, 284... are not; "21" is dropped when both 214 and 215 exist (ambiguous).
#pragma once

#include <optional>
#include <regex>
#include <string>
#include <vector>

namespace doorplate_localization {

struct PlateReadingValidatorOptions {
  // ECMAScript regex matched against the whole normalized reading: 3–4 digits, optional letter.
  std::string pattern = "[0-9]{3,4}[A-Z]?";
  std::vector<std::string> known_rooms;  // empty: no list, the pattern decides alone
  int max_edit_distance = 1;
};

// Levenshtein distance between two byte strings.
int EditDistance(const std::string& a, const std::string& b);

class PlateReadingValidator {
 public:
  // Throws std::invalid_argument naming the field for a bad regex, a negative distance, or a known
  // room that is empty or does not match the pattern after normalization.
  explicit PlateReadingValidator(const PlateReadingValidatorOptions& options);

  // Normalization: whitespace removed, ASCII letters upper-cased. Returns the accepted room text, or
  // nullopt when the reading is dropped.
  std::optional<std::string> Validate(const std::string& raw_reading) const;

  static std::string Normalize(const std::string& raw_reading);

 private:
  const PlateReadingValidatorOptions options_;
  std::regex pattern_;
  std::vector<std::string> known_rooms_;  // normalized, deduplicated
};

}  // namespace doorplate_localization

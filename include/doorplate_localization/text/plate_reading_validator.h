// Accepts, corrects or drops raw OCR readings of doorplates.
// Readings are compared in the canonical room-id form (common/room_id.h: upper-cased, separators
// '-' '.' '·' '/' and whitespace removed), so "E14 295", "E14-295" and "E14295" are one room.
// Without a known room list a reading is kept iff its canonical form matches `pattern`. With a list (from
// the map or a floor plan) the list is the stronger prior: a member (same canonical form) is kept;
// otherwise the reading is mapped to the known room within `max_edit_distance` (Levenshtein between
// canonical forms: substitution, insertion, deletion) if exactly one room is that close, else dropped.
// This is how single-character OCR confusions are handled — 1/7, 4/1, 8/3, 5/6, 0/8, l/1, a lost or
// doubled glyph — so "274" becomes "214" when 214 is a room and 274, 224, 284... are not; "21" is dropped
// when both 214 and 215 exist (ambiguous). Look-alikes stay apart: "312B" is not the room "312A" unless
// the list makes it the only room within the edit distance.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "doorplate_localization/common/room_id.h"

namespace doorplate_localization {

struct PlateReadingValidatorOptions {
  // The building's identifier format: an ECMAScript regex matched against the whole canonical form of a
  // reading (common/room_id.h; the default accepts "16-186", "E14-295", "B/1404", "39.A", "76·100SC",
  // "21/52", "5", "102A", ... and refuses words without digits).
  std::string pattern = kDefaultRoomPattern;
  std::vector<std::string> known_rooms;  // empty: no list, the pattern decides alone
  int max_edit_distance = 1;
};

// Levenshtein distance between two byte strings.
int EditDistance(const std::string& a, const std::string& b);

class PlateReadingValidator {
 public:
  // Throws std::invalid_argument naming the field for an empty or bad regex, a negative distance, or a
  // known room whose canonical form is empty or does not match the pattern.
  explicit PlateReadingValidator(const PlateReadingValidatorOptions& options);

  // Returns the accepted room text in its printed form, or nullopt when the reading is dropped. Without a
  // known list that is the reading normalized (Normalize: "e14-295 " -> "E14-295", separators as read);
  // with one, it is the known room normalized as written in the list (list "E14-295", reading "E14295"
  // -> "E14-295").
  std::optional<std::string> Validate(const std::string& raw_reading) const;

  // The printed form: whitespace removed, ASCII letters upper-cased, other separators kept.
  static std::string Normalize(const std::string& raw_reading);

 private:
  struct KnownRoom {
    std::string printed;    // normalized
    std::string canonical;  // CanonicalRoomId
  };

  const PlateReadingValidatorOptions options_;
  std::optional<RoomIdGrammar> grammar_;  // set by the constructor
  std::vector<KnownRoom> known_rooms_;     // deduplicated by canonical form (the first spelling is kept)
};

}  // namespace doorplate_localization

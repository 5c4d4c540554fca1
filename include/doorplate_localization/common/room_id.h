// Room identifiers as printed on doorplates, and the one canonical form every component compares them in
// (validator, text map, Text AMCL's plate matcher, the SLAM's landmark association, go-to-room).
//
// Real buildings print room numbers in many ways: with a building prefix and a hyphen ("16-186",
// "E14-295", "32-069T"), a letter prefix and a slash ("B/1404"), dotted ("39.A", "3.21", "B2.114"), with a
// raised dot ("76·100SC"), stacked ("21/52"), short ("5", "5D", "20", "2B") or with a letter suffix
// ("102A", "3103B"). Whether the separator is there, and which one the OCR saw, must not matter when
// comparing: "E14-295", "E14 295" and "E14295" are one room. Letters and digits always matter: "312A" and
// "312B", "32-076" and "32-069T" stay apart.
//
// Canonical form (CanonicalRoomId): ASCII letters upper-cased, and every separator removed:
//   printed separators   '-' '.' '/' U+00B7 '·' (raised dot, UTF-8 C2 B7), whitespace (ASCII
//                        space, tab, CR, LF, VT, FF, and U+00A0 no-break space, UTF-8 C2 A0);
//   OCR variants of them ':' ',' (a dot read as a colon or comma), U+2013 '–' en dash, U+2014 '—' em dash,
//                        U+2010 hyphen, U+2011 non-breaking hyphen, U+2212 minus sign (a hyphen read as a
//                        dash), U+2022 '•' bullet, U+2219 bullet operator, U+22C5 dot operator (a raised dot).
// Every other byte is kept as it is (non-ASCII bytes are not upper-cased), so a grammar of ASCII letters
// and digits refuses texts holding anything else.
#pragma once

#include <regex>
#include <string>

namespace doorplate_localization {

// The default building identifier format (ECMAScript, matched against the whole canonical form):
//   [0-9]{1,6}[A-Z]{0,2}|[A-Z]{1,2}[0-9]{2,6}[A-Z]{0,2}
// - 1-6 digits: short numbers ("5", "20") up to building + floor + room run together once the separator is
//   gone ("32-069T" -> 32069T, "76·100SC" -> 76100SC: five digits; six leaves room for a 3-digit building).
// - 0-2 trailing letters: suffixes ("102A", "32-069T", "39.A" -> 39A, "76·100SC").
// - 1-2 leading letters, building or wing codes ("E14-295" -> E14295, "B/1404" -> B1404, "B2.114"), only
//   before at least two digits: a letter and one digit is what OCR makes of fragments of other text
//   ("N5" from "NO 5 PARKING", "NO5PI" from its first letters: measured, docs/results/real-photos.md).
// At least one digit is required: words without digits ("EXIT", "WC", "LOBBY", the commonest text on a
// corridor wall besides room numbers) are refused, and so are letters between digits ("2L4", an OCR
// misreading of 214), which no format above prints. A building whose rooms do not fit sets its own pattern
// (the text map's `room_pattern`, docs/text-map-format.md).
inline constexpr const char* kDefaultRoomPattern = "[0-9]{1,6}[A-Z]{0,2}|[A-Z]{1,2}[0-9]{2,6}[A-Z]{0,2}";

// The canonical form of a printed or read room identifier (above). "" when `text` holds only separators.
std::string CanonicalRoomId(const std::string& text);

// True iff `a` and `b` name the same room: equal, non-empty canonical forms ("E14-295" and "e14 295": true;
// "312A" and "312B": false; "" and "-": false, neither names a room).
bool SameRoom(const std::string& a, const std::string& b);

// A building's identifier format: an ECMAScript regex matched against the whole canonical form.
class RoomIdGrammar {
 public:
  // Throws std::invalid_argument (the message quotes the pattern, not a field: callers prefix their field
  // name) for an empty pattern or one that is not a valid ECMAScript regex.
  explicit RoomIdGrammar(const std::string& pattern = kDefaultRoomPattern);

  // True iff `text`'s canonical form is non-empty and the pattern matches all of it.
  bool Accepts(const std::string& text) const;

  const std::string& pattern() const { return pattern_; }

 private:
  std::string pattern_;
  std::regex regex_;
};

}  // namespace doorplate_localization

#include "doorplate_localization/common/room_id.h"

#include <stdexcept>

namespace doorplate_localization {
namespace {

bool IsAsciiSeparator(char c) {
  switch (c) {
    case '-': case '.': case '/': case ':': case ',':
    case ' ': case '\t': case '\n': case '\r': case '\v': case '\f':
      return true;
    default:
      return false;
  }
}

// UTF-8 separators (room_id.h): their byte sequences.
const char* const kUtf8Separators[] = {
    "\xC2\xB7",      // U+00B7 middle dot (raised dot)
    "\xC2\xA0",      // U+00A0 no-break space
    "\xE2\x80\x93",  // U+2013 en dash
    "\xE2\x80\x94",  // U+2014 em dash
    "\xE2\x80\x90",  // U+2010 hyphen
    "\xE2\x80\x91",  // U+2011 non-breaking hyphen
    "\xE2\x88\x92",  // U+2212 minus sign
    "\xE2\x80\xA2",  // U+2022 bullet
    "\xE2\x88\x99",  // U+2219 bullet operator
    "\xE2\x8B\x85",  // U+22C5 dot operator
};

// Length of the UTF-8 separator starting at text[i], 0 if none.
size_t Utf8SeparatorAt(const std::string& text, size_t i) {
  for (const char* separator : kUtf8Separators) {
    const std::string s(separator);
    if (text.compare(i, s.size(), s) == 0) return s.size();
  }
  return 0;
}

}  // namespace

std::string CanonicalRoomId(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (IsAsciiSeparator(c)) {
      ++i;
      continue;
    }
    if (static_cast<unsigned char>(c) >= 0x80) {
      if (const size_t n = Utf8SeparatorAt(text, i)) {
        i += n;
        continue;
      }
    }
    out.push_back(c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c);
    ++i;
  }
  return out;
}

bool SameRoom(const std::string& a, const std::string& b) {
  const std::string ca = CanonicalRoomId(a);
  return !ca.empty() && ca == CanonicalRoomId(b);
}

RoomIdGrammar::RoomIdGrammar(const std::string& pattern) : pattern_(pattern) {
  if (pattern.empty()) throw std::invalid_argument("room pattern must not be empty");
  try {
    regex_ = std::regex(pattern, std::regex::ECMAScript);
  } catch (const std::regex_error& e) {
    throw std::invalid_argument("room pattern \"" + pattern + "\" is not a valid ECMAScript regex: " + e.what());
  }
}

bool RoomIdGrammar::Accepts(const std::string& text) const {
  const std::string canonical = CanonicalRoomId(text);
  return !canonical.empty() && std::regex_match(canonical, regex_);
}

}  // namespace doorplate_localization

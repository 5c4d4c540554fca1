// libFuzzer target: text-landmark maps (ParseTextMap, docs/text-map-format.md). Any input must either parse
// or throw TextMapError; a parsed map must serialize and parse back. Anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "doorplate_localization/maps/text_map.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace doorplate_localization;
  const std::string text(reinterpret_cast<const char*>(data), size);
  TextMap map;
  try {
    map = ParseTextMap(text, "fuzz.text_map.yaml");
  } catch (const TextMapError&) {
    return 0;  // the documented reaction to bad input
  }
  // What we accepted we must be able to write and read back (a saved map always loads again).
  const TextMap again = ParseTextMap(TextMapToYaml(map), "fuzz.text_map.yaml (written back)");
  if (again.landmarks.size() != map.landmarks.size() || again.adjacent.size() != map.adjacent.size()) {
    std::abort();
  }
  return 0;
}

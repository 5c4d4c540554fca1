// libFuzzer target: the picture of an occupancy map (PGM P5/P2, or whatever OpenCV decodes) read through
// LoadOccupancyMap. The first input byte picks the YAML's mode and negate (so every pixel interpretation
// runs), the rest is the image file. Any input must load or throw MapFileError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "doorplate_localization/maps/map_image.h"
#include "doorplate_localization/maps/map_io.h"
#include "fuzz_temp_dir.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace doorplate_localization;
  if (size < 1) return 0;
  static const char* const kModes[] = {"trinary", "scale", "raw"};
  const std::string yaml = std::string("image: map.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n") +
                           "negate: " + ((data[0] & 4) ? "1" : "0") +
                           "\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: " + kModes[data[0] % 3] + "\n";
  fuzz::WriteTempFile("map.pgm", reinterpret_cast<const char*>(data + 1), size - 1);
  const std::string yaml_path = fuzz::WriteTempFile("map.yaml", yaml.data(), yaml.size());
  try {
    ParsePgm(std::string(reinterpret_cast<const char*>(data + 1), size - 1), "fuzz.pgm");
  } catch (const MapFileError&) {
  }
  try {
    LoadOccupancyMap(yaml_path);
  } catch (const MapFileError&) {
    // The documented reaction to bad input.
  }
  return 0;
}

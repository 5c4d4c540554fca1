// libFuzzer target: the map_server YAML of an occupancy map (LoadOccupancyMap). The input is the YAML text;
// a valid 4 x 3 PGM `map.pgm` lies beside it. Any input must load or throw MapFileError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "doorplate_localization/maps/map_io.h"
#include "fuzz_temp_dir.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace doorplate_localization;
  static const bool image_written = [] {
    const std::string pgm = std::string("P5\n4 3\n255\n") + std::string(4, '\0') + std::string(4, '\xfe') +
                            std::string(4, '\xcd');
    fuzz::WriteTempFile("map.pgm", pgm.data(), pgm.size());
    return true;
  }();
  (void)image_written;
  const std::string yaml = fuzz::WriteTempFile("map.yaml", reinterpret_cast<const char*>(data), size);
  try {
    LoadOccupancyMap(yaml);
  } catch (const MapFileError&) {
    // The documented reaction to bad input.
  }
  return 0;
}

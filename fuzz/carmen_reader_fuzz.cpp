// libFuzzer target: CARMEN laser logs (ReadCarmenLog). Any input must read or throw CarmenLogError; every
// scan read must hold its beam count of ranges that are finite or +inf (no NaN reaches SLAM).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include "doorplate_localization/slam/carmen_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace doorplate_localization;
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const CarmenLog log = ReadCarmenLog(in, "fuzz.log");
    for (const CarmenScan& scan : log.scans) {
      if (scan.scan.ranges_m.size() < 2) std::abort();
      for (float r : scan.scan.ranges_m) {
        if (std::isnan(r)) std::abort();
      }
    }
  } catch (const CarmenLogError&) {
    // The documented reaction to bad input.
  }
  return 0;
}

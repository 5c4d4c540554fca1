// libFuzzer target: world files (ParseWorldYaml, docs/world-format.md). Any input must either parse into a
// World or throw WorldFileError; any other exception, a crash, a leak or a UBSan report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "doorplate_localization/sim/world_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    doorplate_localization::ParseWorldYaml(text, "fuzz_world.yaml");
  } catch (const doorplate_localization::WorldFileError&) {
    // The documented reaction to bad input.
  }
  return 0;
}

// Reads and validates world files (YAML, docs/world-format.md).
#pragma once

#include <stdexcept>
#include <string>

#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

// A world file that cannot be used. what() names the file and the field, e.g.
// "worlds/x.yaml: doors[3].wall: no wall with id 'north2'".
class WorldFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Loads a world file, validates every field and builds its surfaces. Throws WorldFileError.
World LoadWorldFile(const std::string& path);

// Same from YAML text; `source_name` is used in error messages in place of a file name.
World ParseWorldYaml(const std::string& yaml_text, const std::string& source_name);

}  // namespace doorplate_localization

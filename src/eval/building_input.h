// The building an experiment runs in (`doorplate_eval localize|goto --building`): the simulator worlds of
// a building file (docs/building-format.md) and the maps the robot knows, from the maps building file.
#pragma once

#include <string>

#include "localize_eval.h"

namespace doorplate_localization {

// `<building dir>/../maps/<building name>.building.yaml` (where doorplate_world_maps --building writes it).
std::string DefaultBuildingMapPath(const std::string& building_path, const std::string& building_name);

// Loads every floor's world of `building_path` (each floor must name a `world`) and the maps of
// `map_path` ("" = DefaultBuildingMapPath; the path used is stored in *used_map_path), which must list the
// same floors in the same order; each floor's grid is also its ground-truth grid for start poses.
// Throws BuildingFileError / std::runtime_error naming the file and the floor.
LocalizeBuilding LoadLocalizeBuilding(const std::string& building_path, const std::string& map_path,
                                      std::string* used_map_path);

// What `--world` / `--building` and `--map` name, loaded: exactly one of world_path and building_path is
// set (else UsageError "<command>: give --world or --building"). A world is a one-floor
// building whose floor id is the world's name; its map is a text map ("" = DefaultTextMapPath) naming
// its grid. `command` prefixes the errors ("localize: ...").
LocalizeBuilding LoadExperimentBuilding(const std::string& command, const std::string& world_path,
                                        const std::string& building_path, const std::string& map_path,
                                        std::string* used_map_path);

}  // namespace doorplate_localization

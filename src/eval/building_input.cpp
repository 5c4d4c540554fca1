#include "building_input.h"

#include <filesystem>
#include <memory>
#include <stdexcept>

#include "doorplate_localization/maps/building_map.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/maps/text_map.h"
#include "eval_args.h"
#include "doorplate_localization/sim/world_loader.h"

namespace doorplate_localization {

std::string DefaultBuildingMapPath(const std::string& building_path, const std::string& building_name) {
  const std::filesystem::path dir = std::filesystem::path(building_path).parent_path();
  return ((dir.empty() ? std::filesystem::path(".") : dir) / ".." / "maps" / (building_name + ".building.yaml"))
      .lexically_normal()
      .string();
}

LocalizeBuilding LoadLocalizeBuilding(const std::string& building_path, const std::string& map_path,
                                      std::string* used_map_path) {
  const BuildingFile worlds = LoadBuildingFile(building_path);
  const std::string maps_path = map_path.empty() ? DefaultBuildingMapPath(building_path, worlds.name) : map_path;
  if (used_map_path != nullptr) *used_map_path = maps_path;
  const BuildingFile maps_file = LoadBuildingFile(maps_path);
  auto maps = std::make_shared<BuildingMaps>(LoadBuildingMaps(maps_file, maps_path));
  if (maps->floors.size() != worlds.floors.size()) {
    throw std::runtime_error(maps_path + ": has " + std::to_string(maps->floors.size()) + " floors, " +
                             building_path + " has " + std::to_string(worlds.floors.size()));
  }
  LocalizeBuilding building;
  building.name = worlds.name;
  for (size_t f = 0; f < worlds.floors.size(); ++f) {
    const BuildingFloor& floor = worlds.floors[f];
    const std::string where = building_path + ": floors[" + std::to_string(f) + "] (id '" + floor.id + "')";
    if (maps->floors[f].id != floor.id) {
      throw std::runtime_error(where + ": " + maps_path + " lists floor '" + maps->floors[f].id + "' there");
    }
    if (floor.world.empty()) throw std::runtime_error(where + ": names no world");
    try {
      building.worlds.push_back(LoadWorldFile(floor.world));
    } catch (const std::exception& e) {
      throw std::runtime_error(where + ": " + e.what());
    }
    building.ground_truth_grids.push_back(maps->floors[f].grid);
  }
  building.maps = maps;
  return building;
}

LocalizeBuilding LoadExperimentBuilding(const std::string& command, const std::string& world_path,
                                        const std::string& building_path, const std::string& map_path,
                                        std::string* used_map_path) {
  if (world_path.empty() == building_path.empty()) throw UsageError(command + ": give --world or --building (one of them)");
  if (!building_path.empty()) return LoadLocalizeBuilding(building_path, map_path, used_map_path);
  World world = LoadWorldFile(world_path);
  const std::string text_path = map_path.empty() ? DefaultTextMapPath(world_path, world.name) : map_path;
  if (used_map_path != nullptr) *used_map_path = text_path;
  auto text_map = std::make_shared<const TextMap>(LoadTextMap(text_path));
  if (text_map->occupancy_map.empty()) {
    throw std::runtime_error(text_path + ": occupancy_map is empty: the experiment needs the grid it names");
  }
  const std::filesystem::path grid_path = std::filesystem::path(text_path).parent_path() / text_map->occupancy_map;
  OccupancyGrid grid = LoadOccupancyMap(grid_path.string());
  OccupancyGrid ground_truth = grid;
  return OneFloorBuilding(std::move(world), std::move(grid), std::move(text_map), std::move(ground_truth));
}

}  // namespace doorplate_localization

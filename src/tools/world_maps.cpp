// doorplate_world_maps: writes the ground-truth maps of a world file: BASE.pgm + BASE.yaml (map_server
// occupancy map at the laser's mount height) and BASE.text_map.yaml (its doorplates, naming BASE.yaml);
// or those of every floor of a building file (docs/building-format.md) and the building file of the maps.
// The maps of the built-in worlds are in maps/.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_app.h"
#include "map_tool_output.h"
#include "output_guard.h"
#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/maps/building_map.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/world_loader.h"

namespace dl = doorplate_localization;

namespace {

const char kDescription[] = "Writes the ground-truth maps of a world file, or of every floor of a building file.";
const char kNotes[] =
    "--world: writes BASE.pgm, BASE.yaml and BASE.text_map.yaml. --building (docs/building-format.md):\n"
    "writes DIR/<world name>.{pgm,yaml,text_map.yaml} for every floor with a world, then\n"
    "DIR/<building name>.building.yaml naming those maps (floors without a world keep their maps) and\n"
    "the same lifts, each stop checked to be on a free cell.";

struct Args {
  std::string world, building, out;
  double resolution_m = 0.05;
  double laser_height_m = NAN;  // NaN: the world's laser mount height
};

namespace tools = doorplate_localization::tools;
using tools::UsageError;

// A number within the map resolution limits; CLI11 prefixes the option: "--resolution: must be finite and in
// [0.001, 100] m (limits::kMinMapResolutionM, kMaxMapResolutionM), got 1e-09".
CLI::Validator MapResolution() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const auto value = tools::ParseFiniteNumber(text);
        return value ? dl::limits::CheckMapResolution(*value) : "'" + text + "' is not a number";
      },
      "in [" + tools::FormatNumber(dl::limits::kMinMapResolutionM) + ", " +
          tools::FormatNumber(dl::limits::kMaxMapResolutionM) + "]");
}

void AddOptions(CLI::App* app, Args* args) {
  app->footer(kNotes);
  app->add_option("--world", args->world, "world file (worlds/*.yaml)");
  app->add_option("--building", args->building, "building file (worlds/*.building.yaml)");
  app->add_option("--out", args->out, "BASE of the maps (--world) or their folder DIR (--building)")->required();
  app->add_option("--resolution", args->resolution_m, "metres per cell")->capture_default_str()
      ->check(MapResolution());
  app->add_option("--laser-height", args->laser_height_m,
                  "height whose surfaces are obstacles, m [each world's laser mount height]")
      ->check(tools::PositiveNumber());
  app->callback([args] {
    if (args->world.empty() == args->building.empty()) throw UsageError("give one of --world and --building");
  });
}

int Count(const dl::OccupancyGrid& grid, std::int8_t value) {
  return static_cast<int>(std::count(grid.cells.begin(), grid.cells.end(), value));
}

// A world's ground-truth maps, at the laser height of the arguments (or the world's).
struct WorldMaps {
  dl::OccupancyGrid grid;
  dl::TextMap text_map;
  double laser_height_m = 0.0;
};

WorldMaps MakeWorldMaps(const dl::World& world, const Args& args) {
  WorldMaps maps;
  maps.laser_height_m = std::isnan(args.laser_height_m) ? world.sensors.laser.mount_height_m : args.laser_height_m;
  maps.grid = dl::RasterizeWorld(world, args.resolution_m, maps.laser_height_m);
  maps.text_map = dl::GroundTruthTextMap(world);
  return maps;
}

void SaveWorldMaps(const WorldMaps& maps, const std::string& base) {
  tools::SaveMapPair(maps.grid, maps.text_map, base);
  const dl::OccupancyGrid& grid = maps.grid;
  std::cout << base << ".{pgm,yaml}: " << grid.width << " x " << grid.height << " cells at "
            << grid.resolution_m << " m, laser height " << maps.laser_height_m << " m: "
            << Count(grid, dl::OccupancyGrid::kFree) << " free, " << Count(grid, dl::OccupancyGrid::kOccupied)
            << " occupied\n"
            << base << ".text_map.yaml: " << maps.text_map.landmarks.size() << " plates, "
            << maps.text_map.adjacent.size() << " adjacent pairs\n";
}

// --building: every floor's maps made (from its world) or loaded (its map pair) and validated with the
// lifts before anything is written; then the maps of the worlds and the building file of the maps.
int RunBuilding(const Args& args) {
  namespace fs = std::filesystem;
  const dl::BuildingFile building = dl::LoadBuildingFile(args.building);
  dl::BuildingFile out = building;
  dl::BuildingMaps truth;
  truth.name = building.name;
  truth.lifts = building.lifts;
  std::vector<std::pair<WorldMaps, std::string>> to_save;  // maps and their base path
  std::map<std::string, std::string> floor_of_world;       // world name -> floor id
  for (size_t i = 0; i < out.floors.size(); ++i) {
    dl::BuildingFloor& floor = out.floors[i];
    const std::string at = args.building + ": floors[" + std::to_string(i) + "] (id '" + floor.id + "'): ";
    dl::FloorMaps floor_maps;
    floor_maps.id = floor.id;
    if (floor.world.empty()) {  // no world: its map pair is kept as it is
      if (floor.occupancy_map.empty() || floor.text_map.empty()) {
        throw std::runtime_error(at + "needs a world, or an occupancy_map and a text_map");
      }
      try {
        floor_maps.grid = dl::LoadOccupancyMap(floor.occupancy_map);
        floor_maps.text_map = std::make_shared<const dl::TextMap>(dl::LoadTextMap(floor.text_map));
      } catch (const std::runtime_error& e) {
        throw std::runtime_error(at + e.what());
      }
    } else {
      dl::World world;
      try {
        world = dl::LoadWorldFile(floor.world);
      } catch (const std::runtime_error& e) {
        throw std::runtime_error(at + e.what());
      }
      const auto [other, fresh] = floor_of_world.emplace(world.name, floor.id);
      if (!fresh) {
        throw std::runtime_error(at + "its world's name '" + world.name + "' is also floor '" + other->second +
                                 "''s: their maps would overwrite each other");
      }
      const std::string base = (fs::path(args.out) / world.name).string();
      WorldMaps maps = MakeWorldMaps(world, args);
      floor_maps.grid = maps.grid;
      floor_maps.text_map = std::make_shared<const dl::TextMap>(maps.text_map);
      to_save.emplace_back(std::move(maps), base);
      floor = {floor.id, base + ".yaml", base + ".text_map.yaml", ""};
    }
    truth.floors.push_back(std::move(floor_maps));
  }
  dl::ValidateBuildingMaps(truth, args.building);
  const std::string path = (fs::path(args.out) / (building.name + ".building.yaml")).string();
  std::vector<tools::NamedPath> inputs{{"--building", args.building}}, outputs{{"--out", path}};
  for (const dl::BuildingFloor& floor : building.floors) inputs.push_back({"--building (floor " + floor.id + ")", floor.world});
  for (const auto& item : to_save) {
    for (const char* ext : {".pgm", ".yaml", ".text_map.yaml"}) outputs.push_back({"--out", item.second + ext});
  }
  tools::RefuseOverwritingInputs(inputs, outputs);
  fs::create_directories(args.out);
  for (const auto& [maps, base] : to_save) SaveWorldMaps(maps, base);
  dl::SaveBuildingFile(out, path);
  std::cout << path << ": " << out.floors.size() << " floors, " << out.lifts.size() << " lifts\n";
  return 0;
}

int Run(const Args& args) {
  if (!args.building.empty()) return RunBuilding(args);
  tools::RefuseOverwritingInputs({{"--world", args.world}}, {{"--out", args.out + ".pgm"}, {"--out", args.out + ".yaml"},
                                                             {"--out", args.out + ".text_map.yaml"}});
  SaveWorldMaps(MakeWorldMaps(dl::LoadWorldFile(args.world), args), args.out);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::RunTool("doorplate_world_maps", kDescription, AddOptions, Run, argc, argv);
}

// doorplate_world_maps: writes the ground-truth maps of a world file: BASE.pgm + BASE.yaml (map_server
// occupancy map at the laser's mount height) and BASE.text_map.yaml (its doorplates, naming BASE.yaml).
// The maps of the built-in worlds are in maps/.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>

#include "cli_args.h"
#include "map_tool_output.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/world_loader.h"

namespace dl = doorplate_localization;

namespace {

const char kUsage[] =
    "usage: doorplate_world_maps --world FILE --out BASE [--resolution 0.05] [--laser-height H_M]\n"
    "  Writes BASE.pgm, BASE.yaml and BASE.text_map.yaml. --resolution is metres per cell; the laser\n"
    "  height (default: the world's laser mount height) picks which surfaces are obstacles.\n";

struct Args {
  std::string world, out;
  double resolution_m = 0.05;
  double laser_height_m = NAN;  // NaN: the world's laser mount height
};

namespace tools = doorplate_localization::tools;
using tools::UsageError;

Args ParseArgs(int argc, char** argv) {
  Args args;
  tools::ForEachOptionValue(argc, argv, kUsage, [&](const std::string& option, const std::string& value) {
    if (option == "--world") args.world = value;
    else if (option == "--out") args.out = value;
    else if (option == "--resolution") args.resolution_m = tools::ParsePositiveNumber(option, value);
    else if (option == "--laser-height") args.laser_height_m = tools::ParsePositiveNumber(option, value);
    else throw UsageError("unknown option '" + option + "'");
  });
  if (args.world.empty()) throw UsageError("--world is required");
  if (args.out.empty()) throw UsageError("--out is required");
  return args;
}

int Count(const dl::OccupancyGrid& grid, std::int8_t value) {
  return static_cast<int>(std::count(grid.cells.begin(), grid.cells.end(), value));
}

int Run(const Args& args) {
  const dl::World world = dl::LoadWorldFile(args.world);
  const double laser_height_m =
      std::isnan(args.laser_height_m) ? world.sensors.laser.mount_height_m : args.laser_height_m;
  const dl::OccupancyGrid grid = dl::RasterizeWorld(world, args.resolution_m, laser_height_m);
  const dl::TextMap text_map = dl::GroundTruthTextMap(world);
  tools::SaveMapPair(grid, text_map, args.out);
  std::cout << args.out << ".{pgm,yaml}: " << grid.width << " x " << grid.height << " cells at "
            << grid.resolution_m << " m, laser height " << laser_height_m << " m: "
            << Count(grid, dl::OccupancyGrid::kFree) << " free, " << Count(grid, dl::OccupancyGrid::kOccupied)
            << " occupied\n"
            << args.out << ".text_map.yaml: " << text_map.landmarks.size() << " plates, "
            << text_map.adjacent.size() << " adjacent pairs\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::RunTool("doorplate_world_maps", kUsage, ParseArgs, Run, argc, argv);
}

// doorplate_photo_world: builds a bench world whose doorplates are real plate photographs. Reads a TSV of
// plate crops (image_path, x, y, w, h, text; box in that photo's pixels; '#' lines skipped; relative paths
// from the TSV's folder), writes the crops as PNGs and a world YAML (WritePhotoWorld, photo_world.h) into
// OUT/worlds/, and its ground-truth maps into OUT/maps/ (where `doorplate_eval localize` looks by default).
// The photos are read, never copied whole.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "cli_args.h"
#include "output_guard.h"
#include "map_tool_output.h"
#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/photo_world.h"
#include "doorplate_localization/sim/world_loader.h"

namespace dl = doorplate_localization;

namespace {

const char kUsage[] =
    "usage: doorplate_photo_world --crops CROPS.tsv --out DIR [--name photo_plates] [--plate-width 0.25]\n"
    "         [--max-plate-height 0.25] [--door-spacing 5.4] [--corridor-width 1.85] [--plate-height 1.65]\n"
    "  CROPS.tsv lines: image_path<TAB>x<TAB>y<TAB>w<TAB>h<TAB>text (box in the photo's pixels, text = the\n"
    "  room number); '#' lines are skipped, relative image paths are from the TSV's folder.\n"
    "  Writes DIR/worlds/NAME.yaml, DIR/worlds/faces/plate_NN.png and DIR/maps/NAME.{pgm,yaml,text_map.yaml}.\n"
    "  Then: doorplate_eval ocr --world DIR/worlds/NAME.yaml; doorplate_eval localize --world DIR/worlds/NAME.yaml\n";

struct Args {
  std::string crops, out;
  dl::PhotoWorldOptions world;
};

namespace tools = doorplate_localization::tools;
using tools::UsageError;

Args ParseArgs(int argc, char** argv) {
  Args args;
  tools::ForEachOptionValue(argc, argv, kUsage, [&](const std::string& option, const std::string& value) {
    if (option == "--crops") args.crops = value;
    else if (option == "--out") args.out = value;
    else if (option == "--name") args.world.name = value;
    else if (option == "--plate-width") args.world.plate_width_m = tools::ParsePositiveNumber(option, value);
    else if (option == "--max-plate-height") args.world.max_plate_height_m = tools::ParsePositiveNumber(option, value);
    else if (option == "--door-spacing") args.world.door_spacing_m = tools::ParsePositiveNumber(option, value);
    else if (option == "--corridor-width") args.world.corridor_width_m = tools::ParsePositiveNumber(option, value);
    else if (option == "--plate-height") args.world.plate_center_height_m = tools::ParsePositiveNumber(option, value);
    else throw UsageError("unknown option '" + option + "'");
  });
  if (args.crops.empty()) throw UsageError("--crops is required");
  if (args.out.empty()) throw UsageError("--out is required");
  return args;
}

int Run(const Args& args) {
  tools::RefuseOverwritingInputs({{"--crops", args.crops}},
                                 {{"--out", (std::filesystem::path(args.out) / "worlds" / (args.world.name + ".yaml")).string()}});
  std::ifstream in(args.crops);
  if (!in) throw std::runtime_error(args.crops + ": cannot open crops TSV");
  std::stringstream text;
  text << in.rdbuf();
  const std::string base_dir = std::filesystem::path(args.crops).parent_path().string();
  const std::vector<dl::PlateCrop> crops = dl::ParsePlateCropTsv(text.str(), args.crops, base_dir);
  const dl::PhotoWorld written = dl::WritePhotoWorld(crops, args.world, args.out);
  const dl::World world = dl::LoadWorldFile(written.world_path);  // what the tools will read
  const std::filesystem::path maps = std::filesystem::path(args.out) / "maps";
  std::filesystem::create_directories(maps);
  const std::string base = (maps / args.world.name).string();
  tools::SaveMapPair(dl::RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m),
                     dl::GroundTruthTextMap(world), base);
  std::cout << written.world_path << ": " << world.Plates().size() << " photo plates in a " << written.length_m
            << " m corridor (faces in " << (std::filesystem::path(written.world_path).parent_path() / "faces").string()
            << ")\n"
            << base << ".{pgm,yaml,text_map.yaml}: ground-truth maps\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tools::RunTool("doorplate_photo_world", kUsage, &ParseArgs, &Run, argc, argv);
}

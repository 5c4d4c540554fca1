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

#include "cli_app.h"
#include "output_guard.h"
#include "map_tool_output.h"
#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/photo_world.h"
#include "doorplate_localization/sim/world_loader.h"

namespace dl = doorplate_localization;

namespace {

const char kDescription[] = "Builds a bench world whose doorplates are real plate photographs.";
const char kNotes[] =
    "CROPS.tsv lines: image_path<TAB>x<TAB>y<TAB>w<TAB>h<TAB>text (box in the photo's pixels, text = the\n"
    "room number); '#' lines are skipped, relative image paths are from the TSV's folder.\n"
    "Writes DIR/worlds/NAME.yaml, DIR/worlds/faces/plate_NN.png and DIR/maps/NAME.{pgm,yaml,text_map.yaml}.\n"
    "Then: doorplate_eval ocr --world DIR/worlds/NAME.yaml; doorplate_eval localize --world DIR/worlds/NAME.yaml";

struct Args {
  std::string crops, out;
  dl::PhotoWorldOptions world;
};

namespace tools = doorplate_localization::tools;

void AddOptions(CLI::App* app, Args* args) {
  app->footer(kNotes);
  app->add_option("--crops", args->crops, "the TSV of plate crops")->required();
  app->add_option("--out", args->out, "output folder DIR")->required();
  app->add_option("--name", args->world.name, "world name NAME")->capture_default_str();
  const auto size = [&](const char* name, double* value, const char* help) {
    app->add_option(name, *value, help)->capture_default_str()->check(tools::PositiveNumber());
  };
  size("--plate-width", &args->world.plate_width_m, "plate width, m");
  size("--max-plate-height", &args->world.max_plate_height_m, "largest plate height, m");
  size("--door-spacing", &args->world.door_spacing_m, "distance between doors, m");
  size("--corridor-width", &args->world.corridor_width_m, "corridor width, m");
  size("--plate-height", &args->world.plate_center_height_m, "height of the plates' centres, m");
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
  return tools::RunTool("doorplate_photo_world", kDescription, AddOptions, Run, argc, argv);
}

// Command-line pieces of doorplate_eval's subcommands (on CLI11, tools/cli_app.h): the options every
// experiment shares, the seed of each pass, and where a world's text map lies.
#pragma once

#include <cstdint>
#include <string>

#include "usage_error.h"

namespace CLI {
class App;
}  // namespace CLI

namespace doorplate_localization {

using tools::UsageError;  // a bad command line: doorplate_eval exits with status 2

struct CommonArgs {
  std::string world_path;
  std::uint64_t seed = 1;
  int passes = 3;
  double speed_mps = 0.4;
  std::string json_path;   // "" : no JSON file
  std::string dump_dir;    // "" : no failure images
};

// --world (required), --seed, --passes, --speed-mps, --json (its folder must exist), --dump-dir on
// `command`, bound to *common (whose values are the defaults).
void AddCommonOptions(CLI::App* command, CommonArgs* common);

// The simulator seed of pass `pass` (0-based) of an experiment run with `seed`: distinct, well mixed
// (SplitMix64), the same on every machine.
std::uint64_t PassSeed(std::uint64_t seed, int pass);

// Where a built-in world's text map lies: <world file's folder>/../maps/<world name>.text_map.yaml.
std::string DefaultTextMapPath(const std::string& world_path, const std::string& world_name);

}  // namespace doorplate_localization

#include "eval_args.h"

#include <filesystem>

#include "cli_app.h"

namespace doorplate_localization {

void AddCommonOptions(CLI::App* command, CommonArgs* common) {
  command->add_option("--world", common->world_path, "world file (worlds/*.yaml, docs/world-format.md)")->required();
  command->add_option("--seed", common->seed, "experiment seed; pass i runs the simulator with a seed derived from it")
      ->capture_default_str()->transform(tools::Seed());
  command->add_option("--passes", common->passes, "number of passes (sweeps) through the world")
      ->capture_default_str()->transform(tools::WholeNumber(1));
  command->add_option("--speed-mps", common->speed_mps, "cruise speed of the robot, m/s")->capture_default_str()
      ->check(tools::PositiveNumber());
  command->add_option("--json", common->json_path, "write the results as JSON to this file")
      ->check(tools::InExistingFolder());
  command->add_option("--dump-dir", common->dump_dir, "save images of failures (wrong or missed readings) into this folder");
}

std::uint64_t PassSeed(std::uint64_t seed, int pass) {
  std::uint64_t z = seed + 0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(pass + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::string DefaultTextMapPath(const std::string& world_path, const std::string& world_name) {
  const std::filesystem::path dir = std::filesystem::path(world_path).parent_path();
  return ((dir.empty() ? std::filesystem::path(".") : dir) / ".." / "maps" / (world_name + ".text_map.yaml"))
      .lexically_normal()
      .string();
}

}  // namespace doorplate_localization

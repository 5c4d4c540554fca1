#include "eval_args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace doorplate_localization {

EvalArgs::EvalArgs(std::string command, std::vector<OptionSpec> specs)
    : command_(std::move(command)), specs_(std::move(specs)) {}

const OptionSpec& EvalArgs::Spec(const std::string& name) const {
  for (const OptionSpec& spec : specs_) {
    if (spec.name == name) return spec;
  }
  throw UsageError(command_ + ": unknown option --" + name);
}

void EvalArgs::Parse(const std::vector<std::string>& args) {
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& word = args[i];
    if (word == "--help" || word == "-h") {
      help_requested_ = true;
      return;
    }
    if (word.size() < 3 || word.compare(0, 2, "--") != 0) {
      throw UsageError(command_ + ": expected an option (--name value), got '" + word + "'");
    }
    const std::string name = word.substr(2);
    Spec(name);  // known?
    if (i + 1 >= args.size()) throw UsageError(command_ + ": --" + name + " needs a value");
    values_[name] = args[++i];
  }
  for (const OptionSpec& spec : specs_) {
    if (spec.required && values_.count(spec.name) == 0) {
      throw UsageError(command_ + ": --" + spec.name + " is required");
    }
  }
}

const std::string& EvalArgs::String(const std::string& name) const {
  const OptionSpec& spec = Spec(name);
  const auto it = values_.find(name);
  return it == values_.end() ? spec.default_value : it->second;
}

double EvalArgs::Number(const std::string& name) const {
  const std::string& text = String(name);
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno != 0 || !std::isfinite(value)) {
    throw UsageError(command_ + ": --" + name + ": '" + text + "' is not a number");
  }
  return value;
}

int EvalArgs::Integer(const std::string& name, int min_value) const {
  const std::string& text = String(name);
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno != 0 || value < min_value || value > 1000000000L) {
    throw UsageError(command_ + ": --" + name + ": '" + text + "' is not an integer >= " + std::to_string(min_value));
  }
  return static_cast<int>(value);
}

std::uint64_t EvalArgs::Unsigned(const std::string& name) const {
  const std::string& text = String(name);
  char* end = nullptr;
  errno = 0;
  const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || text[0] == '-' || *end != '\0' || errno != 0) {
    throw UsageError(command_ + ": --" + name + ": '" + text + "' is not an unsigned integer");
  }
  return value;
}

bool EvalArgs::OnOff(const std::string& name) const {
  const std::string& text = String(name);
  if (text == "on" || text == "true" || text == "1") return true;
  if (text == "off" || text == "false" || text == "0") return false;
  throw UsageError(command_ + ": --" + name + ": '" + text + "' must be on or off");
}

std::string EvalArgs::Usage() const {
  std::ostringstream usage;
  usage << "usage: doorplate_eval " << command_ << " [options]\n";
  for (const OptionSpec& spec : specs_) {
    usage << "  --" << spec.name << (spec.required ? " (required)" : "") << "  " << spec.help;
    if (!spec.required && !spec.default_value.empty()) usage << " [" << spec.default_value << "]";
    usage << "\n";
  }
  return usage.str();
}

std::vector<OptionSpec> CommonOptions() {
  return {
      {"world", "", "world file (worlds/*.yaml, docs/world-format.md)", true},
      {"seed", "1", "experiment seed; pass i runs the simulator with a seed derived from it"},
      {"passes", "3", "number of passes (sweeps) through the world"},
      {"speed-mps", "0.4", "cruise speed of the robot, m/s"},
      {"json", "", "write the results as JSON to this file"},
      {"dump-dir", "", "save images of failures (wrong or missed readings) into this folder"},
  };
}

CommonArgs ReadCommonArgs(const EvalArgs& args) {
  CommonArgs common;
  common.world_path = args.String("world");
  common.seed = args.Unsigned("seed");
  common.passes = args.Integer("passes", 1);
  common.speed_mps = args.Number("speed-mps");
  if (common.speed_mps <= 0.0) throw UsageError("--speed-mps must be > 0");
  common.json_path = args.String("json");
  common.dump_dir = args.String("dump-dir");
  return common;
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

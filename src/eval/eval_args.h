// Command-line options of doorplate_eval subcommands: `--name value` pairs, declared per subcommand with
// a default and a help line, checked strictly (unknown option, missing or malformed value: UsageError
// naming the option). The options shared by every experiment are declared by CommonOptions().
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace doorplate_localization {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct OptionSpec {
  std::string name;           // without the leading "--"
  std::string default_value;  // "" with required = true: must be given
  std::string help;
  bool required = false;
};

class EvalArgs {
 public:
  // `command` names the subcommand in messages and the usage text.
  EvalArgs(std::string command, std::vector<OptionSpec> specs);

  // Parses `args` (the words after the subcommand). "--help" sets help_requested() and stops.
  // Throws UsageError for an unknown option, a missing value or a missing required option.
  void Parse(const std::vector<std::string>& args);

  bool help_requested() const { return help_requested_; }
  // The value given, or the default.
  const std::string& String(const std::string& name) const;
  // Typed views; throw UsageError naming the option when the text is not of that type or out of range.
  double Number(const std::string& name) const;
  int Integer(const std::string& name, int min_value) const;
  std::uint64_t Unsigned(const std::string& name) const;
  bool OnOff(const std::string& name) const;  // "on"/"off" (also "true"/"false", "1"/"0")

  std::string Usage() const;

 private:
  const OptionSpec& Spec(const std::string& name) const;

  std::string command_;
  std::vector<OptionSpec> specs_;
  std::map<std::string, std::string> values_;
  bool help_requested_ = false;
};

// --world, --seed, --passes, --speed-mps, --json, --dump-dir.
std::vector<OptionSpec> CommonOptions();

struct CommonArgs {
  std::string world_path;
  std::uint64_t seed = 1;
  int passes = 3;
  double speed_mps = 0.4;
  std::string json_path;   // "" : no JSON file
  std::string dump_dir;    // "" : no failure images
};

CommonArgs ReadCommonArgs(const EvalArgs& args);

// The simulator seed of pass `pass` (0-based) of an experiment run with `seed`: distinct, well mixed
// (SplitMix64), the same on every machine.
std::uint64_t PassSeed(std::uint64_t seed, int pass);

// Where a built-in world's text map lies: <world file's folder>/../maps/<world name>.text_map.yaml.
std::string DefaultTextMapPath(const std::string& world_path, const std::string& world_name);

}  // namespace doorplate_localization

// Command-line helpers shared by the offline tools (doorplate_sim_snapshot, doorplate_world_maps,
// doorplate_map_log, doorplate_map_rawlog, doorplate_map_bag): the usage error they exit with, strict
// number parsing, the option-loop pieces (--help, an option's value, --seed-style whole numbers,
// --set NAME=VALUE) and the main() wrapper with the tools' exit statuses. ROS-free, header-only.
#pragma once

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

namespace doorplate_localization::tools {

// A bad command line; the tools print what() and their usage, and exit with status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The whole of `text` as a finite number; nullopt for "", "1.5x", "nan", "inf" or anything not a number.
inline std::optional<double> ParseFiniteNumber(const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// `text` (the value of `option`) as a finite number; throws UsageError "OPTION: 'TEXT' is not a number".
inline double ParseNumber(const std::string& option, const std::string& text) {
  if (const auto value = ParseFiniteNumber(text)) return *value;
  throw UsageError(option + ": '" + text + "' is not a number");
}

// `text` (the value of `option`) as a finite number > 0; throws UsageError "OPTION: 'TEXT' is not a number > 0".
inline double ParsePositiveNumber(const std::string& option, const std::string& text) {
  const auto value = ParseFiniteNumber(text);
  if (!value || *value <= 0.0) throw UsageError(option + ": '" + text + "' is not a number > 0");
  return *value;
}

// `text` as a whole number in [min_value, max_value]; throws UsageError
// "OPTION: 'TEXT' is not a whole number >= MIN" otherwise (or "is not a number").
inline double ParseWholeNumber(const std::string& option, const std::string& text, int min_value,
                               double max_value = 1e9) {
  const double n = ParseNumber(option, text);
  if (n < min_value || n != std::floor(n) || n > max_value) {
    throw UsageError(option + ": '" + text + "' is not a whole number >= " + std::to_string(min_value));
  }
  return n;
}

// For --help / -h: prints `usage` on stdout and exits with status 0; any other option returns.
inline void ExitIfHelp(const std::string& option, const char* usage) {
  if (option == "--help" || option == "-h") {
    std::cout << usage;
    std::exit(0);
  }
}

// The value after argv[*i] (advancing *i); throws UsageError "OPTION needs a value" at the end of argv.
inline std::string TakeValue(int argc, char** argv, int* i) {
  const std::string option = argv[*i];
  if (*i + 1 >= argc) throw UsageError(option + " needs a value");
  return argv[++*i];
}

// The option loop of a tool whose options all take a value: for each "--name value" pair calls
// fn(option, value); --help / -h prints `usage` and exits 0; a last option without its value throws
// UsageError. `fn` throws UsageError for an option it does not know.
template <typename OptionFn>
void ForEachOptionValue(int argc, char** argv, const char* usage, OptionFn fn) {
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    ExitIfHelp(option, usage);
    const std::string value = TakeValue(argc, argv, &i);
    fn(option, value);
  }
}

// --set NAME=VALUE: calls set(NAME, VALUE as a number). Throws UsageError for a missing '=', a value that
// is not a number ("--set NAME: ..."), or a name `set` rejects with std::invalid_argument ("--set: ...").
template <typename SetFn>
void ApplySetOption(const std::string& name_value, SetFn set) {
  const std::size_t eq = name_value.find('=');
  if (eq == std::string::npos) throw UsageError("--set: expected NAME=VALUE, got '" + name_value + "'");
  const std::string name = name_value.substr(0, eq);
  const double value = ParseNumber("--set " + name, name_value.substr(eq + 1));
  try {
    set(name, value);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--set: ") + e.what());
  }
}

// A tool's main(): args = parse(argc, argv), then run(args)'s exit status. A UsageError prints
// "TOOL: what" and the usage on stderr (status 2); any other exception prints "TOOL: what" (status 1).
template <typename Args, typename RunFn>
int RunTool(const char* tool, const char* usage, Args (*parse)(int, char**), RunFn run, int argc, char** argv) {
  Args args;
  try {
    args = parse(argc, argv);
  } catch (const UsageError& e) {
    std::cerr << tool << ": " << e.what() << "\n" << usage;
    return 2;
  }
  try {
    return run(args);
  } catch (const std::exception& e) {
    std::cerr << tool << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace doorplate_localization::tools

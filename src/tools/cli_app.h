// The command line of the package's tools (doorplate_eval, doorplate_soak, doorplate_map_log, ...) on CLI11:
// strict validators for their values (the whole text, finite, in range: CLI11's own conversions take
// "nan", "inf", octal "010" and wrap a negative seed round), on/off switches, --set NAME=VALUE, and the
// main() wrapper with the tools' exit statuses. ROS-free, header-only (as CLI11 is).
#pragma once

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "usage_error.h"

namespace doorplate_localization::tools {

// The whole of `text` as a finite number; nullopt for "", "1.5x", "nan", "inf" or anything not a number.
inline std::optional<double> ParseFiniteNumber(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (*end != '\0' || errno == ERANGE || !std::isfinite(value)) return std::nullopt;
  return value;
}

inline std::string FormatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

// The validators below name no option: CLI11 prefixes their message with it ("--seed: '1x' is not ...").
// WholeNumber, Seed and OnOff rewrite the text CLI11 then converts: add them with ->transform(), not
// ->check() (whose validators may not modify it). The others are ->check()s.

// A finite number > `min` (`exclusive`) or >= `min`; the error reads "--opt: 'TEXT' is not a number [> MIN]".
inline CLI::Validator Number(double min = -HUGE_VAL, bool exclusive = false) {
  const std::string bound =
      std::isinf(min) ? "" : (exclusive ? " > " : " >= ") + FormatNumber(min);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const auto value = ParseFiniteNumber(text);
        if (!value || *value < min || (exclusive && *value == min)) return "'" + text + "' is not a number" + bound;
        return "";
      },
      std::isinf(min) ? "FINITE" : bound.substr(1));
}

inline CLI::Validator PositiveNumber() { return Number(0.0, true); }

// A whole number in [min, max] ("12", "1e3", "3.0"); rewritten as plain decimal digits for CLI11's integer
// conversion. The error reads "--opt: 'TEXT' is not a whole number >= MIN" (or "... in MIN..MAX").
inline CLI::Validator WholeNumber(double min, double max = 1e9) {
  const std::string range =
      max >= 1e9 ? ">= " + FormatNumber(min) : "in " + FormatNumber(min) + ".." + FormatNumber(max);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const auto value = ParseFiniteNumber(text);
        if (!value || *value != std::floor(*value) || *value < min || *value > max) {
          return "'" + text + "' is not a whole number " + range;
        }
        text = std::to_string(static_cast<long long>(*value));
        return "";
      },
      range);
}

// A seed: decimal digits of an unsigned 64-bit number (all of them; no sign, exponent or fraction).
inline CLI::Validator Seed() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::string error = "'" + text + "' is not a whole number >= 0";
        if (text.empty() || !std::isdigit(static_cast<unsigned char>(text[0]))) return error;
        char* end = nullptr;
        errno = 0;
        const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
        if (*end != '\0' || errno == ERANGE) return error;
        text = std::to_string(value);  // no octal for CLI11: "010" is 10
        return "";
      },
      ">= 0");
}

// on/off (also true/false, 1/0), for an option bound to a bool.
inline CLI::Validator OnOff() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (text == "on" || text == "true" || text == "1") text = "1";
        else if (text == "off" || text == "false" || text == "0") text = "0";
        else return "'" + text + "' must be on or off";
        return "";
      },
      "on|off");
}

// A file to write whose folder exists ("" passes: no file); the error reads "--opt: folder F does not exist".
inline CLI::Validator InExistingFolder() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        const std::filesystem::path parent = std::filesystem::path(path).parent_path();
        if (!parent.empty() && !std::filesystem::is_directory(parent)) {
          return "folder " + parent.string() + " does not exist";
        }
        return "";
      },
      "");
}

// --set NAME=VALUE: calls set(NAME, VALUE as a number). Throws UsageError for a missing '=', a value that
// is not a number ("--set NAME: ..."), or a name `set` rejects with std::invalid_argument ("--set: ...").
template <typename SetFn>
void ApplySetOption(const std::string& name_value, SetFn set) {
  const std::size_t eq = name_value.find('=');
  if (eq == std::string::npos) throw UsageError("--set: expected NAME=VALUE, got '" + name_value + "'");
  const std::string name = name_value.substr(0, eq), text = name_value.substr(eq + 1);
  const auto value = ParseFiniteNumber(text);
  if (!value) throw UsageError("--set " + name + ": '" + text + "' is not a number");
  try {
    set(name, *value);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--set: ") + e.what());
  }
}

// The tools' conventions on `app`, before its options are added: a repeated option counts once, its last
// value (as the tools' hand-written loops did); options that collect values take one per occurrence.
inline void UseToolConventions(CLI::App* app) {
  app->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

// Parses argv with `app`. Returns -1 when the tool should run; 0 after --help / -h printed the help on
// stdout; 2 for a bad command line (CLI11's errors and the UsageError of `app`'s callbacks: "NAME: what"
// and the help on stderr). With subcommands the help is the chosen subcommand's.
inline int ParseCommandLine(CLI::App* app, int argc, const char* const* argv) {
  try {
    app->parse(argc, argv);
    return -1;
  } catch (const CLI::CallForHelp&) {
    std::cout << app->help();
    return 0;
  } catch (const CLI::RequiredError& e) {
    // CLI11 checks the required options before the unknown ones: name "--sede", not only "--seed is required".
    const std::vector<std::string> unknown = app->remaining(true);
    const std::string what = unknown.empty() ? e.what() : CLI::ExtrasError(unknown).what();
    std::cerr << app->get_name() << ": " << what << "\n" << app->help();
  } catch (const CLI::ParseError& e) {
    std::cerr << app->get_name() << ": " << e.what() << "\n" << app->help();
  } catch (const UsageError& e) {
    std::cerr << app->get_name() << ": " << e.what() << "\n" << app->help();
  }
  return 2;
}

// A tool's main(): add_options(&app, &args) binds the options to `args` (and may add a callback that throws
// UsageError for what the options cannot say alone), then run(args)'s exit status. Status 0 after --help,
// 2 for a bad command line, 1 with "NAME: what" on stderr when run throws.
template <typename Args, typename RunFn>
int RunTool(const std::string& name, const std::string& description, void (*add_options)(CLI::App*, Args*),
            RunFn run, int argc, char** argv) {
  CLI::App app(description, name);
  UseToolConventions(&app);
  Args args;
  add_options(&app, &args);
  const int parsed = ParseCommandLine(&app, argc, argv);
  if (parsed >= 0) return parsed;
  try {
    return run(args);
  } catch (const std::exception& e) {
    std::cerr << name << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace doorplate_localization::tools

// The subcommands of doorplate_eval. Each Add…Command adds its subcommand and options (CLI11) to the
// doorplate_eval app and returns the experiment to run once the command line chose it: it returns the
// process exit code, throws UsageError for options that do not go together and any other exception when
// the experiment fails. `command_line` is recorded in the results.
#pragma once

#include <functional>
#include <string>

namespace CLI {
class App;
}  // namespace CLI

namespace doorplate_localization {

struct EvalCommand {
  CLI::App* app = nullptr;  // the subcommand, owned by the doorplate_eval app
  std::function<int()> run;
};

// Text reading on a corridor sweep (paper Table I, Figure 12): ocr_command.cpp.
EvalCommand AddOcrCommand(CLI::App* eval, const std::string& command_line);

// Global localization and kidnapped-robot trials (paper Table III): localize_command.cpp.
EvalCommand AddLocalizeCommand(CLI::App* eval, const std::string& command_line);

// SLAM of a corridor sweep, laser only or with doorplate text (paper Table II): map_command.cpp.
EvalCommand AddMapCommand(CLI::App* eval, const std::string& command_line);

// Go to any room on a floor from a random corridor pose, on the Text AMCL estimate (issue 17): goto_command.cpp.
EvalCommand AddGotoCommand(CLI::App* eval, const std::string& command_line);

}  // namespace doorplate_localization

// The subcommands of doorplate_eval. Each takes the words after its name and the whole command line (to
// record in its results), returns the process exit code and throws UsageError for bad options.
#pragma once

#include <string>
#include <vector>

namespace doorplate_localization {

// Text reading on a corridor sweep (paper Table I, Figure 12): ocr_command.cpp.
int RunOcrCommand(const std::vector<std::string>& args, const std::string& command_line);

// Global localization and kidnapped-robot trials (paper Table III): localize_command.cpp.
int RunLocalizeCommand(const std::vector<std::string>& args, const std::string& command_line);

// SLAM of a corridor sweep, laser only or with doorplate text (paper Table II): map_command.cpp.
int RunMapCommand(const std::vector<std::string>& args, const std::string& command_line);

// Go to any room on a floor from a random corridor pose, on the Text AMCL estimate (issue 17): goto_command.cpp.
int RunGotoCommand(const std::vector<std::string>& args, const std::string& command_line);

}  // namespace doorplate_localization

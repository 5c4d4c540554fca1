// The error of a bad command line, shared by the command-line tools (cli_app.h) and what they check before
// they write (output_guard.h): the tools print what() and exit with status 2. ROS-free, header-only.
#pragma once

#include <stdexcept>

namespace doorplate_localization::tools {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace doorplate_localization::tools

// doorplate_eval: the experiments of the paper reproduced on the built-in simulator, without ROS.
//   doorplate_eval <subcommand> [--option value ...]     doorplate_eval <subcommand> --help
// Exit codes: 0 done, 1 the experiment failed (bad world file, missing model, ...), 2 bad command line.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "eval_args.h"
#include "eval_commands.h"

namespace dl = doorplate_localization;

namespace {

struct Subcommand {
  const char* name;
  int (*run)(const std::vector<std::string>&, const std::string&);
  const char* summary;
};

const Subcommand kSubcommands[] = {
    {"ocr", dl::RunOcrCommand, "doorplate text reading on a corridor sweep (paper Table I, Figure 12)"},
    {"map", dl::RunMapCommand, "SLAM of a corridor sweep, rbpf or rbpf_text (paper Table II)"},
    {"localize", dl::RunLocalizeCommand, "global localization and kidnap trials, amcl or text_amcl (paper Table III)"},
    {"goto", dl::RunGotoCommand, "go to a random room from a random corridor pose on a floor (issue 17)"},
};

void PrintUsage(std::FILE* out) {
  std::fprintf(out, "usage: doorplate_eval <subcommand> [--option value ...]\nsubcommands:\n");
  for (const Subcommand& s : kSubcommands) std::fprintf(out, "  %-6s %s\n", s.name, s.summary);
  std::fprintf(out, "doorplate_eval <subcommand> --help lists its options.\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    PrintUsage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  std::string command_line = "doorplate_eval";
  for (int i = 1; i < argc; ++i) command_line += std::string(" ") + argv[i];
  const std::vector<std::string> args(argv + 2, argv + argc);
  for (const Subcommand& s : kSubcommands) {
    if (argv[1] != std::string(s.name)) continue;
    try {
      return s.run(args, command_line);
    } catch (const dl::UsageError& e) {
      std::fprintf(stderr, "doorplate_eval: %s\n", e.what());
      return 2;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "doorplate_eval %s: %s\n", s.name, e.what());
      return 1;
    }
  }
  std::fprintf(stderr, "doorplate_eval: unknown subcommand '%s'\n", argv[1]);
  PrintUsage(stderr);
  return 2;
}

// doorplate_eval: the experiments of the paper reproduced on the built-in simulator, without ROS.
//   doorplate_eval <subcommand> [--option value ...]     doorplate_eval <subcommand> --help
// Exit codes: 0 done, 1 the experiment failed (bad world file, missing model, ...), 2 bad command line.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli_app.h"
#include "eval_args.h"
#include "eval_commands.h"

namespace dl = doorplate_localization;

int main(int argc, char** argv) {
  std::string command_line = "doorplate_eval";
  for (int i = 1; i < argc; ++i) command_line += std::string(" ") + argv[i];
  CLI::App app("The experiments of the paper on the built-in simulator; doorplate_eval <subcommand> --help lists "
               "its options.",
               "doorplate_eval");
  dl::tools::UseToolConventions(&app);
  app.require_subcommand(1);
  const std::vector<dl::EvalCommand> commands = {
      dl::AddOcrCommand(&app, command_line), dl::AddMapCommand(&app, command_line),
      dl::AddLocalizeCommand(&app, command_line), dl::AddGotoCommand(&app, command_line)};
  const auto known = [&](const std::string& name) {
    return std::any_of(commands.begin(), commands.end(), [&](const dl::EvalCommand& c) { return c.app->get_name() == name; });
  };
  if (argc > 1 && argv[1][0] != '-' && !known(argv[1])) {  // CLI11 would only say "A subcommand is required"
    std::fprintf(stderr, "doorplate_eval: unknown subcommand '%s'\n%s", argv[1], app.help().c_str());
    return 2;
  }
  const int parsed = dl::tools::ParseCommandLine(&app, argc, argv);
  if (parsed >= 0) return parsed;
  for (const dl::EvalCommand& command : commands) {
    if (!command.app->parsed()) continue;
    try {
      return command.run();
    } catch (const dl::UsageError& e) {
      std::fprintf(stderr, "doorplate_eval: %s\n", e.what());
      return 2;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "doorplate_eval %s: %s\n", command.app->get_name().c_str(), e.what());
      return 1;
    }
  }
  return 2;  // not reached: CLI11 requires one subcommand
}

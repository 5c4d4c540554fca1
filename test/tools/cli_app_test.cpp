// The tools' command line on CLI11 (cli_app.h): strict values, on/off switches, --set, and the exit statuses.
#include "cli_app.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace doorplate_localization::tools {
namespace {

struct Args {
  double speed = 0.4, offset = 0.0;
  int particles = 30;
  std::uint64_t seed = 1;
  bool band = true, clean = false;
  std::vector<std::string> sets;
};

void AddOptions(CLI::App* app, Args* args) {
  app->add_option("--speed", args->speed)->check(PositiveNumber());
  app->add_option("--offset", args->offset)->check(Number());
  app->add_option("--particles", args->particles)->transform(WholeNumber(1));
  app->add_option("--seed", args->seed)->transform(Seed());
  app->add_option("--band", args->band)->transform(OnOff());
  app->add_flag("--clean", args->clean);
  app->add_option("--set", args->sets)->allow_extra_args(false);
  app->callback([args] {
    if (args->clean && !args->band) throw UsageError("--clean needs the band");
  });
}

// Parses `line` into *args; "" when it parses, else the error.
std::string Parse(const std::string& line, Args* args) {
  CLI::App app("test", "tool");
  UseToolConventions(&app);
  AddOptions(&app, args);
  try {
    app.parse(line, false);
  } catch (const CLI::ParseError& e) {
    return e.what();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

std::string Error(const std::string& line) {
  Args args;
  return Parse(line, &args);
}

TEST(CliApp, ReadsValuesIncludingNegativeNumbersAndTheLastOfARepeatedOption) {
  Args args;
  ASSERT_EQ(Parse("--speed 0.8 --offset -3.5 --particles 1e3 --seed 010 --band off --set a=1 --set b=2 --speed 1.2",
                  &args), "");
  EXPECT_DOUBLE_EQ(args.speed, 1.2);
  EXPECT_DOUBLE_EQ(args.offset, -3.5);
  EXPECT_EQ(args.particles, 1000);
  EXPECT_EQ(args.seed, 10u);  // decimal, not octal
  EXPECT_FALSE(args.band);
  EXPECT_EQ(args.sets, (std::vector<std::string>{"a=1", "b=2"}));
}

TEST(CliApp, RefusesValuesThatAreNotWhollyFiniteNumbersInRangeNamingTheOption) {
  EXPECT_EQ(Error("--offset 1.5x"), "--offset: '1.5x' is not a number");
  EXPECT_EQ(Error("--offset nan"), "--offset: 'nan' is not a number");
  EXPECT_EQ(Error("--offset inf"), "--offset: 'inf' is not a number");
  EXPECT_EQ(Error("--speed 0"), "--speed: '0' is not a number > 0");
  EXPECT_EQ(Error("--particles 2.5"), "--particles: '2.5' is not a whole number >= 1");
  EXPECT_EQ(Error("--particles 0"), "--particles: '0' is not a whole number >= 1");
  EXPECT_EQ(Error("--seed 1x"), "--seed: '1x' is not a whole number >= 0");
  EXPECT_EQ(Error("--seed -1"), "--seed: '-1' is not a whole number >= 0");
  EXPECT_EQ(Error("--seed 99999999999999999999"), "--seed: '99999999999999999999' is not a whole number >= 0");
  EXPECT_EQ(Error("--band maybe"), "--band: 'maybe' must be on or off");
}

TEST(CliApp, RefusesUnknownOptionsMissingValuesAndWhatTheCallbackRefuses) {
  EXPECT_NE(Error("--sede 3").find("--sede"), std::string::npos);
  EXPECT_NE(Error("--speed").find("--speed"), std::string::npos);
  EXPECT_EQ(Error("--band off --clean"), "--clean needs the band");
}

TEST(NumberValidators, WholeNumberSaysItsRangeWhenItHasAnUpperBound) {
  std::string text = "2";
  EXPECT_EQ(WholeNumber(0, 1)(text), "'2' is not a whole number in 0..1");
  text = "1";
  EXPECT_EQ(WholeNumber(0, 1)(text), "");
}

TEST(ApplySetOption, CallsTheSetterWithTheNumberOrThrowsAUsageErrorNamingTheName) {
  std::map<std::string, double> set;
  const auto setter = [&](const std::string& name, double value) {
    if (name == "bogus") throw std::invalid_argument("unknown option 'bogus'");
    set[name] = value;
  };
  ApplySetOption("num_particles=10", setter);
  EXPECT_DOUBLE_EQ(set.at("num_particles"), 10.0);
  EXPECT_THROW(ApplySetOption("num_particles", setter), UsageError);
  try {
    ApplySetOption("sigma=1.5x", setter);
    FAIL();
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(), "--set sigma: '1.5x' is not a number");
  }
  EXPECT_THROW(ApplySetOption("bogus=1", setter), UsageError);
}

TEST(ParseCommandLine, NamesAnUnknownOptionBeforeAMissingRequiredOne) {
  CLI::App app("test", "tool");
  std::string world;
  app.add_option("--world", world)->required();
  const char* argv[] = {"tool", "--wrold", "w.yaml"};
  testing::internal::CaptureStderr();
  EXPECT_EQ(ParseCommandLine(&app, 3, argv), 2);
  const std::string errors = testing::internal::GetCapturedStderr();
  EXPECT_NE(errors.find("not expected"), std::string::npos) << errors;
  EXPECT_NE(errors.find("--wrold"), std::string::npos) << errors;
}

// RunTool's statuses: 0 after --help, 2 for a bad command line, 1 when the run throws, else the run's.
TEST(RunTool, ExitsZeroForHelpTwoForABadCommandLineOneForAFailedRun) {
  const auto run = [](const Args& args) -> int {
    if (args.particles == 7) throw std::runtime_error("no world");
    return args.particles == 3 ? 3 : 0;
  };
  const auto status = [&](std::vector<const char*> argv) {
    argv.insert(argv.begin(), "tool");
    return RunTool("tool", "test", AddOptions, run, static_cast<int>(argv.size()), const_cast<char**>(argv.data()));
  };
  testing::internal::CaptureStdout();
  EXPECT_EQ(status({"--help"}), 0);
  EXPECT_NE(testing::internal::GetCapturedStdout().find("--particles"), std::string::npos);
  testing::internal::CaptureStderr();
  EXPECT_EQ(status({"--seed", "1x"}), 2);
  EXPECT_EQ(status({"--bogus"}), 2);
  EXPECT_EQ(status({"--band", "off", "--clean"}), 2);
  EXPECT_EQ(status({"--particles", "7"}), 1);
  const std::string errors = testing::internal::GetCapturedStderr();
  EXPECT_NE(errors.find("tool: --seed: '1x' is not a whole number >= 0\n"), std::string::npos) << errors;
  EXPECT_NE(errors.find("tool: no world\n"), std::string::npos) << errors;
  EXPECT_EQ(status({"--particles", "3"}), 3);
  EXPECT_EQ(status({}), 0);
}

}  // namespace
}  // namespace doorplate_localization::tools

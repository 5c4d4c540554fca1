#include "eval_args.h"

#include <gtest/gtest.h>

#include <set>

namespace doorplate_localization {
namespace {

EvalArgs Parsed(const std::vector<std::string>& words) {
  std::vector<OptionSpec> specs = CommonOptions();
  specs.push_back({"band", "on", "band"});
  EvalArgs args("ocr", specs);
  args.Parse(words);
  return args;
}

std::string UsageMessage(const std::vector<std::string>& words) {
  try {
    ReadCommonArgs(Parsed(words));
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(EvalArgs, ReadsCommonOptionsWithDefaults) {
  const CommonArgs common = ReadCommonArgs(Parsed({"--world", "w.yaml", "--seed", "7", "--json", "out.json"}));
  EXPECT_EQ(common.world_path, "w.yaml");
  EXPECT_EQ(common.seed, 7u);
  EXPECT_EQ(common.passes, 3);
  EXPECT_DOUBLE_EQ(common.speed_mps, 0.4);
  EXPECT_EQ(common.json_path, "out.json");
  EXPECT_EQ(common.dump_dir, "");
}

TEST(EvalArgs, ReadsOnOffSwitches) {
  EXPECT_TRUE(Parsed({"--world", "w"}).OnOff("band"));
  EXPECT_FALSE(Parsed({"--world", "w", "--band", "off"}).OnOff("band"));
  EXPECT_THROW(Parsed({"--world", "w", "--band", "maybe"}).OnOff("band"), UsageError);
}

TEST(EvalArgs, ErrorsNameTheOption) {
  EXPECT_NE(UsageMessage({"--world", "w", "--sede", "3"}).find("unknown option --sede"), std::string::npos);
  EXPECT_NE(UsageMessage({"--world"}).find("--world needs a value"), std::string::npos);
  EXPECT_NE(UsageMessage({"--seed", "3"}).find("--world is required"), std::string::npos);
  EXPECT_NE(UsageMessage({"--world", "w", "--passes", "0"}).find("--passes"), std::string::npos);
  EXPECT_NE(UsageMessage({"--world", "w", "--speed-mps", "fast"}).find("--speed-mps"), std::string::npos);
  EXPECT_NE(UsageMessage({"--world", "w", "--seed", "-1"}).find("--seed"), std::string::npos);
  EXPECT_NE(UsageMessage({"--world", "w", "stray"}).find("'stray'"), std::string::npos);
}

TEST(EvalArgs, HelpStopsParsingAndUsageListsTheOptions) {
  const EvalArgs args = Parsed({"--help", "--bogus"});
  EXPECT_TRUE(args.help_requested());
  EXPECT_NE(args.Usage().find("--world (required)"), std::string::npos);
  EXPECT_NE(args.Usage().find("--passes"), std::string::npos);
}

TEST(PassSeed, IsDeterministicAndDistinctPerPassAndSeed) {
  EXPECT_EQ(PassSeed(1, 0), PassSeed(1, 0));
  std::set<std::uint64_t> seeds;
  for (std::uint64_t seed = 0; seed < 4; ++seed) {
    for (int pass = 0; pass < 4; ++pass) seeds.insert(PassSeed(seed, pass));
  }
  EXPECT_EQ(seeds.size(), 16u);
}

}  // namespace
}  // namespace doorplate_localization

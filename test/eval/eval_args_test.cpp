#include "eval_args.h"

#include <gtest/gtest.h>

#include <set>

#include "cli_app.h"

namespace doorplate_localization {
namespace {

// `words` parsed by an `ocr` subcommand with the common options; "" when they parse, else the error.
std::string Parse(const std::string& words, CommonArgs* common) {
  CLI::App eval("test", "doorplate_eval");
  CLI::App* ocr = eval.add_subcommand("ocr");
  AddCommonOptions(ocr, common);
  try {
    eval.parse("ocr " + words, false);
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
  return "";
}

std::string Error(const std::string& words) {
  CommonArgs common;
  return Parse(words, &common);
}

TEST(AddCommonOptions, ReadsTheOptionsWithTheirDefaults) {
  CommonArgs common;
  ASSERT_EQ(Parse("--world w.yaml --seed 7 --json out.json", &common), "");
  EXPECT_EQ(common.world_path, "w.yaml");
  EXPECT_EQ(common.seed, 7u);
  EXPECT_EQ(common.passes, 3);
  EXPECT_DOUBLE_EQ(common.speed_mps, 0.4);
  EXPECT_EQ(common.json_path, "out.json");
  EXPECT_EQ(common.dump_dir, "");
}

TEST(AddCommonOptions, ErrorsNameTheOption) {
  EXPECT_NE(Error("--world w --sede 3").find("--sede"), std::string::npos);
  EXPECT_NE(Error("--seed 3").find("--world is required"), std::string::npos);
  EXPECT_NE(Error("--world w --passes 0").find("--passes: '0' is not a whole number >= 1"), std::string::npos);
  EXPECT_NE(Error("--world w --speed-mps fast").find("--speed-mps: 'fast' is not a number > 0"), std::string::npos);
  EXPECT_NE(Error("--world w --speed-mps 0").find("--speed-mps"), std::string::npos);
  EXPECT_NE(Error("--world w --seed -1").find("--seed"), std::string::npos);
  EXPECT_NE(Error("--world w --seed 1x").find("--seed: '1x' is not a whole number >= 0"), std::string::npos);
  EXPECT_NE(Error("--world w --json /no/such/folder/out.json").find("--json: folder /no/such/folder does not exist"),
            std::string::npos);
  EXPECT_NE(Error("--world w stray").find("stray"), std::string::npos);
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

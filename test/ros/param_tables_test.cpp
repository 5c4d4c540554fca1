// The nodelets' parameter tables against what ships with them, without a ROS master: every key of
// config/<nodelet>.yaml is a parameter of the table with its default (or the value the table documents as
// the config's), every table is docs/parameters.md's table verbatim, and the shipped configs load. The
// generated tables are also written to <build>/param_tables/<nodelet>.md (copy them into the docs).
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "corridor_sim_options.h"
#include "doorplate_localization/slam/rbpf_slam_options.h"
#include "go_to_room_options.h"
#include "slam_mapping_options.h"
#include "text_amcl_options.h"
#include "text_extractor_options.h"
#include "wall_follower_options.h"

namespace doorplate_localization {
namespace {

const std::string kSource = DOORPLATE_SOURCE_DIR;

// A YAML file's values under "/<node>/", nested maps flattened with '/', typed as the parameter server
// types them for getParam.
class YamlSource : public ParamSource {
 public:
  YamlSource(const std::string& path, std::string node) : node_(std::move(node)) { Flatten(YAML::LoadFile(path), ""); }
  YamlSource(const YAML::Node& root, std::string node) : node_(std::move(node)) { Flatten(root, ""); }

  std::optional<ParamValue> Get(const std::string& name, const ParamValue& like) const override {
    const auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    try {
      switch (like.index()) {
        case 0: return it->second.as<bool>();
        case 1: return it->second.as<int>();
        case 2: return it->second.as<double>();
        default: return it->second.as<std::string>();
      }
    } catch (const YAML::Exception&) {
      throw ParameterError(Resolve(name) + " must be " + ParamTypeName(like));
    }
  }
  bool Has(const std::string& name) const override { return values_.count(name) > 0; }
  std::string Resolve(const std::string& name) const override { return "/" + node_ + "/" + name; }
  void Warn(const std::string& message) const override { warnings.push_back(message); }
  std::optional<std::vector<std::string>> GetStringList(const std::string& name) const override {
    const auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    if (!it->second.IsSequence()) throw ParameterError(Resolve(name) + " must be a list of strings");
    return it->second.as<std::vector<std::string>>();
  }

  std::vector<std::string> Keys() const {
    std::vector<std::string> keys;
    for (const auto& [key, value] : values_) keys.push_back(key);
    return keys;
  }
  mutable std::vector<std::string> warnings;

 private:
  void Flatten(const YAML::Node& node, const std::string& prefix) {
    for (const auto& entry : node) {
      const std::string key = prefix + entry.first.as<std::string>();
      if (entry.second.IsMap()) {
        Flatten(entry.second, key + "/");
      } else {
        values_[key] = entry.second;
      }
    }
  }
  std::string node_;
  std::map<std::string, YAML::Node> values_;
};

// Every key of the config is a parameter of `table`, set to its default or to the value the table
// documents as the config's (ParamSpec::shipped).
template <typename O>
void ExpectConfigMatchesTable(const ParamTable<O>& table, const std::string& config,
                              const std::vector<std::string>& lists = {}) {
  const YamlSource yaml(kSource + "/config/" + config, "node");
  const O defaults{};
  for (const std::string& key : yaml.Keys()) {
    if (std::find(lists.begin(), lists.end(), key) != lists.end()) continue;  // read beside the table
    const ParamSpec<O>* spec = nullptr;
    for (const ParamSpec<O>& s : table) {
      if (s.name == key) spec = &s;
    }
    if (spec == nullptr) {
      ADD_FAILURE() << "config/" << config << ": " << key << " is not a parameter of the nodelet's table";
      continue;
    }
    const ParamValue expected = spec->shipped ? *spec->shipped : spec->get(defaults);
    const std::optional<ParamValue> value = yaml.Get(key, expected);
    ASSERT_TRUE(value.has_value());
    EXPECT_EQ(*value, expected) << "config/" << config << ": " << key << " = " << FormatParamValue(*value)
                                << ", the table's " << (spec->shipped ? "documented config value" : "default")
                                << " is " << FormatParamValue(expected);
  }
}

// docs/parameters.md holds the table verbatim; the generated one is also written for copying.
template <typename O>
void ExpectDocumented(const ParamTable<O>& table, const std::string& nodelet) {
  const std::string markdown = MarkdownParamTable(table);
  std::filesystem::create_directories("param_tables");
  std::ofstream("param_tables/" + nodelet + ".md") << markdown;
  std::ifstream in(kSource + "/docs/parameters.md");
  std::stringstream docs;
  docs << in.rdbuf();
  EXPECT_NE(docs.str().find(markdown), std::string::npos)
      << "docs/parameters.md does not hold " << nodelet << "'s parameter table; it should be:\n" << markdown;
}

TEST(ParamTables, EveryKeyOfTheShippedConfigsIsAParameterWithTheTablesValue) {
  ExpectConfigMatchesTable(WallFollowerParamTable(), "wall_follower.yaml");
  ExpectConfigMatchesTable(CorridorSimParamTable(), "sim.yaml");
  ExpectConfigMatchesTable(GoToRoomParamTable(), "go_to_room.yaml");
  ExpectConfigMatchesTable(TextAmclParamTable(), "text_amcl.yaml");
  ExpectConfigMatchesTable(SlamMappingParamTable(), "mapping.yaml");
  ExpectConfigMatchesTable(TextExtractorParamTable(), "text_extractor.yaml", {"validator/known_rooms"});
}

TEST(ParamTables, DocsParametersMdHoldsEveryTableAsGenerated) {
  ExpectDocumented(WallFollowerParamTable(), "WallFollowerNodelet");
  ExpectDocumented(CorridorSimParamTable(), "CorridorSimNodelet");
  ExpectDocumented(GoToRoomParamTable(), "GoToRoomNodelet");
  ExpectDocumented(TextAmclParamTable(), "TextAmclNodelet");
  ExpectDocumented(SlamMappingParamTable(), "SlamMappingNodelet");
  ExpectDocumented(TextExtractorParamTable(), "TextExtractorNodelet");
}

TEST(ParamTables, TheShippedConfigsLoadWithoutWarnings) {
  const YamlSource follower(kSource + "/config/wall_follower.yaml", "corridor_follower");
  EXPECT_EQ(WallFollowerOptionsFrom(follower).mode, CorridorDriveMode::kFollow);
  const YamlSource amcl(kSource + "/config/text_amcl.yaml", "amcl");
  const TextAmclNodeOptions o = TextAmclOptionsFrom(amcl);
  EXPECT_EQ(o.session.setup.likelihood_field.beams.laser_max_beams, 60);
  EXPECT_EQ(o.session.setup.beam.beams.laser_max_beams, 60);
  EXPECT_EQ(o.session.setup.motion.noise_law, OdometryNoiseLaw::kDiffCorrected);
  const YamlSource mapping(kSource + "/config/mapping.yaml", "slam_mapping");
  const SlamMappingNodeOptions m = SlamMappingOptionsFrom(mapping);
  for (const std::string& name : TextSlamOptionNames()) {  // the core's defaults, as the offline tools run
    EXPECT_EQ(GetTextSlamOption(name, m.slam), GetTextSlamOption(name, TextSlamOptions())) << name;
  }
  const YamlSource extractor(kSource + "/config/text_extractor.yaml", "text_extractor");
  const TextExtractorNodeOptions x = TextExtractorOptionsFrom(extractor);
  EXPECT_TRUE(x.extractor.validator.known_rooms.empty());
  EXPECT_EQ(x.extractor.tracker.read_every_n_frames, 1);  // unset in the config: tesseract's schedule
  EXPECT_TRUE(follower.warnings.empty() && amcl.warnings.empty() && mapping.warnings.empty() &&
              extractor.warnings.empty());
}

// The structured-building profile (loaded after mapping.yaml): known parameters, no warnings, and the
// settings docs/results/real-logs.md measured.
TEST(ParamTables, TheStructuredBuildingProfileLoadsTheMeasuredSettings) {
  const YamlSource profile(kSource + "/config/mapping_structured_building.yaml", "slam_mapping");
  const SlamMappingNodeOptions m = SlamMappingOptionsFrom(profile);
  EXPECT_TRUE(profile.warnings.empty());
  EXPECT_EQ(m.slam.slam.degenerate_min_points, 0.0);
  EXPECT_EQ(m.slam.back_end.front_end_history_sigma_m, 0.005);
  EXPECT_EQ(m.slam.back_end.front_end_history_sigma_rad, 0.0025);
  EXPECT_TRUE(m.slam.back_end.enabled);
}

TEST(ParamTables, UnsetTextAmclParametersAreAmclsDefaultsOneSourceForLoaderAndDocs) {
  const TextAmclNodeOptions o = TextAmclOptionsFrom(YamlSource(YAML::Load("{}"), "amcl"));
  EXPECT_EQ(o.session.setup.likelihood_field.beams.laser_max_beams, 30);  // amcl's; the core's is 60
  EXPECT_EQ(o.session.setup.beam.beams.laser_max_beams, 30);
  EXPECT_EQ(o.session.setup.motion.noise_law, OdometryNoiseLaw::kDiff);  // amcl's; the core's diff-corrected
  EXPECT_DOUBLE_EQ(o.session.setup.filter.recovery_alpha_slow, 0.001);     // documented difference
  const std::string docs = MarkdownParamTable(TextAmclParamTable());
  EXPECT_NE(docs.find("| `~laser_max_beams` | `session.setup.likelihood_field.beams.laser_max_beams` | "
                      "30 (config: 60) | >= 2 |"),
            std::string::npos);
}

TEST(ParamTables, RenamedParametersStillWorkUnderTheirOldNamesWithAWarning) {
  const YamlSource amcl(YAML::Load("{tf_timeout: 0.3}"), "amcl");
  EXPECT_DOUBLE_EQ(TextAmclOptionsFrom(amcl).tf_timeout_s, 0.3);
  ASSERT_EQ(amcl.warnings.size(), 1u);
  EXPECT_EQ(amcl.warnings[0], "/amcl/tf_timeout is deprecated: use /amcl/tf_timeout_s");
}

TEST(ParamTables, CrossFieldRulesComeFromTheCoreAndNameTheParameters) {
  try {
    WallFollowerOptionsFrom(YamlSource(YAML::Load("{end_stop_distance_m: 2.0}"), "follower"));
    ADD_FAILURE() << "no error";
  } catch (const ParameterError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("/follower/slow_down_distance_m = 1.5"), std::string::npos) << what;
    EXPECT_NE(what.find("/follower/end_stop_distance_m = 2.0"), std::string::npos) << what;
  }
  try {
    TextAmclOptionsFrom(YamlSource(YAML::Load("{max_particles: 50}"), "amcl"));
    ADD_FAILURE() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("/amcl/max_particles = 50"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace doorplate_localization

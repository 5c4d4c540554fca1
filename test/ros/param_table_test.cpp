// The parameter-table machinery (include/doorplate_localization/ros/param_table.h), ROS-free: reading a
// table over defaults with type and rule checks, deprecated names, enum parameters, core errors turned
// into errors naming parameters, and the markdown table docs/parameters.md is made of.
#include "doorplate_localization/ros/param_table.h"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

struct Inner {
  double distance_m = 0.6;
};
enum class Mode { kSlow, kFast };
struct Options {
  Inner inner;
  int passes = 2;
  bool enabled = true;
  std::string frame = "map";
  Mode mode = Mode::kSlow;
};

// Values by name under the namespace "/node"; a number is accepted for a double, as by the parameter server.
class MapSource : public ParamSource {
 public:
  std::map<std::string, ParamValue> values;
  mutable std::vector<std::string> warnings;

  std::optional<ParamValue> Get(const std::string& name, const ParamValue& like) const override {
    const auto it = values.find(name);
    if (it == values.end()) return std::nullopt;
    if (it->second.index() == like.index()) return it->second;
    if (std::holds_alternative<double>(like) && std::holds_alternative<int>(it->second)) {
      return static_cast<double>(std::get<int>(it->second));
    }
    throw ParameterError(Resolve(name) + " must be " + ParamTypeName(like));
  }
  bool Has(const std::string& name) const override { return values.count(name) > 0; }
  std::string Resolve(const std::string& name) const override { return "/node/" + name; }
  void Warn(const std::string& message) const override { warnings.push_back(message); }
};

const ParamTable<Options>& Table() {
  namespace r = param_rules;
  static const ParamTable<Options> table = {
      Param<Options>("distance_m", DOORPLATE_PARAM_FIELD(inner.distance_m), "kept from the wall", r::Positive()),
      Param<Options>("passes", DOORPLATE_PARAM_FIELD(passes), "how often", r::AtLeast(1)).Shipped(3),
      Param<Options>("enabled", DOORPLATE_PARAM_FIELD(enabled), "start at once"),
      Param<Options>("global_frame_id", DOORPLATE_PARAM_FIELD(frame), "the map frame", r::FrameId())
          .Deprecated("map_frame_id"),
      EnumParam<Options>("mode", DOORPLATE_PARAM_FIELD(mode), {{"slow", Mode::kSlow}, {"fast", Mode::kFast}},
                         "how to drive"),
  };
  return table;
}

std::string ErrorOf(const MapSource& source) {
  try {
    Options o;
    ApplyParamTable(Table(), source, &o);
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}

TEST(ParamTable, ReadsTheSetParametersOverTheDefaultsAndLeavesTheOthers) {
  MapSource source;
  source.values = {{"distance_m", 0.8}, {"enabled", false}, {"mode", std::string("fast")}};
  Options o;
  ApplyParamTable(Table(), source, &o);
  EXPECT_EQ(o.inner.distance_m, 0.8);
  EXPECT_FALSE(o.enabled);
  EXPECT_EQ(o.mode, Mode::kFast);
  EXPECT_EQ(o.passes, 2);
  EXPECT_EQ(o.frame, "map");
  source.values = {{"distance_m", 1}};  // an integer where a number is expected is that number
  ApplyParamTable(Table(), source, &o);
  EXPECT_EQ(o.inner.distance_m, 1.0);
}

TEST(ParamTable, AWrongTypeOrABrokenRuleIsAnErrorNamingTheResolvedParameterAndValue) {
  MapSource source;
  source.values = {{"passes", 1.5}};
  EXPECT_EQ(ErrorOf(source), "/node/passes must be an integer");
  source.values = {{"passes", 0}};
  EXPECT_EQ(ErrorOf(source), "/node/passes must be >= 1, got 0");
  source.values = {{"distance_m", -0.5}};
  EXPECT_EQ(ErrorOf(source), "/node/distance_m must be finite and > 0, got -0.5");
  source.values = {{"global_frame_id", std::string("/map")}};
  EXPECT_EQ(ErrorOf(source), "/node/global_frame_id must be a non-empty tf2 frame id without a leading '/', got /map");
  source.values = {{"mode", std::string("medium")}};
  EXPECT_EQ(ErrorOf(source), "/node/mode must be 'slow' or 'fast', got medium");
}

TEST(ParamTable, ADeprecatedNameIsReadWithAWarningAndWinsOverTheNewOne) {
  MapSource source;
  source.values = {{"map_frame_id", std::string("world")}};
  Options o;
  ApplyParamTable(Table(), source, &o);
  EXPECT_EQ(o.frame, "world");
  ASSERT_EQ(source.warnings.size(), 1u);
  EXPECT_EQ(source.warnings[0], "/node/map_frame_id is deprecated: use /node/global_frame_id");
  // The new name set too (by a shipped config): the user's old name still decides, and the warning says so.
  source.values["global_frame_id"] = std::string("map");
  ApplyParamTable(Table(), source, &o);
  EXPECT_EQ(o.frame, "world");
  EXPECT_NE(source.warnings.back().find("its value world is used, not /node/global_frame_id = map"),
            std::string::npos)
      << source.warnings.back();
  source.values = {{"map_frame_id", std::string("/world")}};
  EXPECT_EQ(ErrorOf(source).rfind("/node/map_frame_id must be", 0), 0u) << ErrorOf(source);
}

TEST(ParamTable, CoreErrorsNameEveryParameterWhoseFieldTheyMention) {
  const MapSource source;
  const Options o;
  try {
    CheckWithCore(Table(), o, source, [] {
      throw std::invalid_argument("InnerOptions.distance_m: must be < passes");
    });
    ADD_FAILURE() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_EQ(std::string(e.what()),
              "/node/distance_m = 0.6, /node/passes = 2: refused by the core options: InnerOptions.distance_m: "
              "must be < passes");
  }
  try {
    CheckWithCore(Table(), o, source, [] { throw std::invalid_argument("Grid: resolution: must be > 0"); });
    ADD_FAILURE() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_EQ(std::string(e.what()), "/node/: refused by the core options: Grid: resolution: must be > 0");
  }
  EXPECT_NO_THROW(CheckWithCore(Table(), o, source, [] {}));
}

TEST(ParamTable, TheMarkdownTableListsNameFieldDefaultShippedValueRuleAndDoc) {
  EXPECT_EQ(MarkdownParamTable(Table()),
            "| parameter | field | default | valid | meaning |\n"
            "|---|---|---|---|---|\n"
            "| `~distance_m` | `inner.distance_m` | 0.6 | finite and > 0 | kept from the wall |\n"
            "| `~passes` | `passes` | 2 (config: 3) | >= 1 | how often |\n"
            "| `~enabled` | `enabled` | true | a boolean | start at once |\n"
            "| `~global_frame_id` (deprecated: `~map_frame_id`) | `frame` | map | a non-empty tf2 frame id without a "
            "leading '/' | the map frame |\n"
            "| `~mode` | `mode` | slow | 'slow' or 'fast' | how to drive |\n");
}

TEST(ParamTable, NumbersAreFormattedAsYamlReadsThemBack) {
  EXPECT_EQ(FormatParamValue(0.2), "0.2");
  EXPECT_EQ(FormatParamValue(1500.0), "1500.0");
  EXPECT_EQ(FormatParamValue(-1.0), "-1.0");
  EXPECT_EQ(FormatParamValue(M_PI / 6), "0.5235987755982988");
  EXPECT_EQ(FormatParamValue(30), "30");
  EXPECT_EQ(FormatParamValue(true), "true");
  EXPECT_EQ(FormatParamValue(std::string("odom")), "odom");
}

}  // namespace
}  // namespace doorplate_localization

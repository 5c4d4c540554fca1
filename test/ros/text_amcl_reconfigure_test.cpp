// cfg/TextAmcl.cfg against the parameter table (names, types, defaults, ranges; docs/parameters.md lists the
// reconfigurable ones), and a request's path through the startup checks. No ROS master.
#include "text_amcl_reconfigure.h"

#include <climits>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

using O = TextAmclNodeOptions;

const ParamSpec<O>* Spec(const std::string& name) {
  for (const ParamSpec<O>& spec : TextAmclParamTable()) {
    if (spec.name == name) return &spec;
  }
  return nullptr;
}

bool Accepts(const ParamSpec<O>& spec, const ParamValue& v) { return !spec.rule.ok || spec.rule.ok(v); }

// The same number as `like`'s type (int or double).
ParamValue Number(const ParamValue& like, double x) {
  if (like.index() == 1) return static_cast<int>(x);
  return x;
}

// [lo, hi] must be the closure of the rule's valid numbers: every value inside valid, a finite end valid
// or the limit of valid values (an open bound), and the rule refusing just past a finite end. The problems.
std::vector<std::string> RangeProblems(const ParamSpec<O>& spec, const ParamValue& lo_v, const ParamValue& hi_v) {
  std::vector<std::string> problems;
  auto expect = [&](bool ok, const std::string& what) {
    if (!ok) problems.push_back(spec.name + ": " + what + " (rule '" + spec.rule.text + "')");
  };
  const bool is_int = lo_v.index() == 1;
  const double lo = param_rules::Number(lo_v), hi = param_rules::Number(hi_v);
  const bool lo_bounded = is_int ? lo > INT_MIN : std::isfinite(lo);
  const bool hi_bounded = is_int ? hi < INT_MAX : std::isfinite(hi);
  auto step = [is_int](double x) { return is_int ? 1.0 : std::max(1e-9, std::fabs(x) * 1e-9); };
  const double inner_lo = lo_bounded ? lo : -1e9, inner_hi = hi_bounded ? hi : 1e9;
  for (const double t : {0.25, 0.5, 0.75}) {
    const double x = inner_lo + t * (inner_hi - inner_lo);
    expect(Accepts(spec, Number(lo_v, is_int ? std::round(x) : x)), "refuses " + std::to_string(x) + " inside");
  }
  if (lo_bounded) {
    // An integer range's ends are values; a number's may be open ends (kld_err > 0: min 0).
    expect(Accepts(spec, lo_v) || (!is_int && Accepts(spec, Number(lo_v, lo + step(lo)))),
           "cfg min is not the lower bound");
    expect(!Accepts(spec, Number(lo_v, lo - step(lo))), "accepts below the cfg min");
  } else {
    expect(Accepts(spec, Number(lo_v, -1e9)), "no cfg min, but a lower bound");
  }
  if (hi_bounded) {
    expect(Accepts(spec, hi_v) || (!is_int && Accepts(spec, Number(hi_v, hi - step(hi)))),
           "cfg max is not the upper bound");
    expect(!Accepts(spec, Number(hi_v, hi + step(hi))), "accepts above the cfg max");
  } else {
    expect(Accepts(spec, Number(hi_v, 1e9)), "no cfg max, but an upper bound");
  }
  return problems;
}

TEST(TextAmclReconfigure, TheCfgsParametersAreTheTablesWithItsTypesDefaultsAndRanges) {
  const O defaults{};
  const auto cfg_defaults = ReconfigureValues(TextAmclConfig::__getDefault__());
  const auto cfg_min = ReconfigureValues(TextAmclConfig::__getMin__());
  const auto cfg_max = ReconfigureValues(TextAmclConfig::__getMax__());
  ASSERT_GE(cfg_defaults.size(), 20u);
  for (const auto& [name, value] : cfg_defaults) {
    const ParamSpec<O>* spec = Spec(name);
    ASSERT_NE(spec, nullptr) << "cfg/TextAmcl.cfg: " << name << " is not a parameter of TextAmclParamTable";
    EXPECT_TRUE(spec->deprecated_names.empty()) << name << ": a renamed parameter cannot be reconfigured";
    const ParamValue table_default = spec->get(defaults);
    ASSERT_EQ(value.index(), table_default.index()) << name << ": cfg type differs from the table's";
    // Exactly (the server's first call, with unset parameters at the cfg's defaults, then changes nothing).
    EXPECT_EQ(value, table_default) << name << ": cfg default " << FormatParamValue(value) << ", table's "
                                    << FormatParamValue(table_default);
    if (value.index() == 1 || value.index() == 2) {
      for (const std::string& p : RangeProblems(*spec, cfg_min.at(name), cfg_max.at(name))) ADD_FAILURE() << p;
    }
  }
}

TEST(TextAmclReconfigure, TheRangeCheckFailsForARangeWiderOrNarrowerThanTheRule) {
  const ParamSpec<O>& kld_err = *Spec("kld_err");  // finite and > 0
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(RangeProblems(kld_err, -1.0, inf).size(), 1u);  // wider: -1 is no bound of the rule
  EXPECT_FALSE(RangeProblems(kld_err, 0.0, 1.0).empty());   // narrower: the rule accepts above 1
  EXPECT_TRUE(RangeProblems(kld_err, 0.0, inf).empty());
  const ParamSpec<O>& particles = *Spec("max_particles");  // in [1, 1000000]
  EXPECT_FALSE(RangeProblems(particles, 0, 1000000).empty());
  EXPECT_TRUE(RangeProblems(particles, 1, 1000000).empty());
}

TEST(TextAmclReconfigure, DocsParametersMdNamesEveryReconfigurableParameter) {
  std::string line = "Reconfigurable at run time (dynamic_reconfigure, `cfg/TextAmcl.cfg`):";
  for (const auto& d : TextAmclConfig::__getParamDescriptions__()) line += " `~" + d->name + "`";
  std::ifstream in(std::string(DOORPLATE_SOURCE_DIR) + "/docs/parameters.md");
  std::stringstream docs;
  docs << in.rdbuf();
  EXPECT_NE(docs.str().find(line + "\n"), std::string::npos) << "docs/parameters.md should hold the line\n" << line;
}

TEST(TextAmclReconfigure, AGoodValueIsAppliedAndTheConfigRoundTripsTheOptions) {
  O current;
  std::map<std::string, ParamValue> values = ReconfigureValues(ToReconfigureConfig(current));
  values["kld_err"] = 0.05;
  values["max_particles"] = 300;
  values["laser_z_hit"] = 0.8;
  const O next = ReconfiguredTextAmclOptions(current, values, "/amcl");
  EXPECT_DOUBLE_EQ(next.session.setup.filter.kld_err, 0.05);
  EXPECT_EQ(next.session.setup.filter.max_particles, 300);
  EXPECT_DOUBLE_EQ(next.session.setup.likelihood_field.z_hit, 0.8);  // both laser models, as at startup
  EXPECT_DOUBLE_EQ(next.session.setup.beam.z_hit, 0.8);
  EXPECT_EQ(DescribeReconfigureChange(current, next, values),
            "kld_err 0.01 -> 0.05, laser_z_hit 0.95 -> 0.8, max_particles 5000 -> 300");
  EXPECT_EQ(ReconfigureValues(ToReconfigureConfig(next)), values);
}

TEST(TextAmclReconfigure, ABadValueIsRefusedNamingTheParameterAsAtStartup) {
  const O current;
  std::map<std::string, ParamValue> values = ReconfigureValues(ToReconfigureConfig(current));
  values["kld_err"] = 0.0;
  try {
    ReconfiguredTextAmclOptions(current, values, "/amcl");
    ADD_FAILURE() << "kld_err 0 accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(std::string(e.what()), "/amcl/kld_err must be finite and > 0, got 0.0");
  }
  values = ReconfigureValues(ToReconfigureConfig(current));
  values["min_particles"] = 400;
  values["max_particles"] = 300;  // each value valid; the pair refused by the core's rule
  try {
    ReconfiguredTextAmclOptions(current, values, "/amcl");
    ADD_FAILURE() << "min_particles > max_particles accepted";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("/amcl/max_particles = 300"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace doorplate_localization

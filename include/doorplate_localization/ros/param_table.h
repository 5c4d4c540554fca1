// Parameter tables: each nodelet lists its parameters once — name, field of its node-options struct,
// default (read from a default-constructed struct), rule and one doc line — and that table is the loader
// (ApplyParamTable over a ParamSource: the parameter server, or a YAML file in the tests), the
// docs/parameters.md table (MarkdownParamTable) and the reference config/*.yaml is checked against
// (test/ros/param_tables_test.cpp). Rules here are per value (type, range, frame id); rules between fields
// belong to the core options' own checks (their constructors throw std::invalid_argument naming the
// field), which CheckWithCore turns into an error naming the parameters. ROS-free: reading from a
// NodeHandle is RosParamSource (ros/param_reader.h).
#pragma once

#include <cctype>
#include <cmath>
#include <functional>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace doorplate_localization {

// A parameter that cannot be used; what() names the fully resolved parameter.
class ParameterError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A parameter's value; its alternative is the parameter's type (a number is a double, an integer an int).
using ParamValue = std::variant<bool, int, double, std::string>;

// "a boolean", "an integer", "a number", "a string": the type a value of `like`'s alternative needs.
inline const char* ParamTypeName(const ParamValue& like) {
  static const char* const kNames[] = {"a boolean", "an integer", "a number", "a string"};
  return kNames[like.index()];
}

// As written in YAML: true, 30, 0.2, -1, 1500 (shortest round-trip digits), strings as they are.
inline std::string FormatParamValue(const ParamValue& value) {
  if (const bool* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const int* i = std::get_if<int>(&value)) return std::to_string(*i);
  if (const std::string* s = std::get_if<std::string>(&value)) return *s;
  const double d = std::get<double>(value);
  std::ostringstream out;
  for (int digits = 6; digits <= 17; ++digits) {  // the shortest form that reads back as the same number
    out.str("");
    out.precision(digits);
    out << d;
    if (std::stod(out.str()) == d) break;
  }
  std::string text = out.str();
  if (std::isfinite(d) && text.find_first_of(".e") == std::string::npos) text += ".0";  // a number, not an int
  return text;
}

// A rule on one value: `ok` and the text that completes "<parameter> must be ...".
struct ParamRule {
  std::string text;                              // empty: any value of the type
  std::function<bool(const ParamValue&)> ok;     // null: any value of the type
};

namespace param_rules {
inline double Number(const ParamValue& v) {
  if (const int* i = std::get_if<int>(&v)) return *i;
  return std::get<double>(v);
}
inline ParamRule Finite() { return {"finite", [](const ParamValue& v) { return std::isfinite(Number(v)); }}; }
inline ParamRule Positive() {
  return {"finite and > 0", [](const ParamValue& v) { return std::isfinite(Number(v)) && Number(v) > 0.0; }};
}
inline ParamRule NonNegative() {
  return {"finite and >= 0", [](const ParamValue& v) { return std::isfinite(Number(v)) && Number(v) >= 0.0; }};
}
inline ParamRule Probability() {
  return {"in [0, 1]", [](const ParamValue& v) { return Number(v) >= 0.0 && Number(v) <= 1.0; }};
}
inline ParamRule AtLeast(int minimum) {
  return {">= " + std::to_string(minimum), [minimum](const ParamValue& v) { return Number(v) >= minimum; }};
}
// Any rule on a number: Holds("in (0, 0.1] seconds", [](double x) { return x > 0 && x <= 0.1; }).
inline ParamRule Holds(std::string text, std::function<bool(double)> ok) {
  return {std::move(text), [ok = std::move(ok)](const ParamValue& v) { return ok(Number(v)); }};
}
inline ParamRule OneOf(const std::vector<std::string>& choices) {
  std::string text;
  for (size_t i = 0; i < choices.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + ("'" + choices[i] + "'");
  }
  return {text, [choices](const ParamValue& v) {
            for (const std::string& c : choices) {
              if (std::get<std::string>(v) == c) return true;
            }
            return false;
          }};
}
inline ParamRule FrameId() {
  return {"a non-empty tf2 frame id without a leading '/'", [](const ParamValue& v) {
            const std::string& f = std::get<std::string>(v);
            return !f.empty() && f.front() != '/';
          }};
}
}  // namespace param_rules

// One parameter of a node-options struct O.
template <typename O>
struct ParamSpec {
  std::string name;   // relative to the private namespace; nested with '/': "explore/passes"
  std::string field;  // where it goes in O: "follower.wall_distance_m" (core errors name its last part)
  std::function<ParamValue(const O&)> get;          // the field as the parameter's type
  std::function<void(O&, const ParamValue&)> set;   // given a value of get()'s type
  std::string doc;                                  // one line of docs/parameters.md
  ParamRule rule;
  std::vector<std::string> deprecated_names;  // older names still read, with a warning; they win if both set
  std::string default_text;                   // docs: shown instead of the default (e.g. "the world's")
  std::optional<ParamValue> shipped;          // the reference config sets this instead (documented)

  ParamSpec& Deprecated(std::string old_name) { deprecated_names.push_back(std::move(old_name)); return *this; }
  ParamSpec& DefaultText(std::string text) { default_text = std::move(text); return *this; }
  ParamSpec& Shipped(ParamValue value) { shipped = std::move(value); return *this; }
};

template <typename O>
using ParamTable = std::vector<ParamSpec<O>>;

// A parameter bound to a field of type bool, int, double or std::string through `access(o)` -> field&.
// Usually written with DOORPLATE_PARAM_FIELD(path), which gives the field's path and its accessor.
template <typename O, typename Access>
ParamSpec<O> Param(std::string name, std::string field, Access access, std::string doc, ParamRule rule = {}) {
  using T = std::decay_t<decltype(access(std::declval<O&>()))>;
  ParamSpec<O> spec;
  spec.name = std::move(name);
  spec.field = std::move(field);
  spec.get = [access](const O& o) { return ParamValue(T(access(const_cast<O&>(o)))); };
  spec.set = [access](O& o, const ParamValue& v) { access(o) = std::get<T>(v); };
  spec.doc = std::move(doc);
  spec.rule = std::move(rule);
  return spec;
}
#define DOORPLATE_PARAM_FIELD(path) #path, [](auto& o) -> auto& { return o.path; }

// A parameter of type T (bool, int, double, std::string) stored differently: get(o) -> T, set(o, T).
template <typename O, typename T, typename Get, typename Set>
ParamSpec<O> ConvertedParam(std::string name, std::string field, Get get, Set set, std::string doc,
                            ParamRule rule = {}) {
  ParamSpec<O> spec;
  spec.name = std::move(name);
  spec.field = std::move(field);
  spec.get = [get](const O& o) { return ParamValue(T(get(o))); };
  spec.set = [set](O& o, const ParamValue& v) { set(o, std::get<T>(v)); };
  spec.doc = std::move(doc);
  spec.rule = std::move(rule);
  return spec;
}

// A string parameter bound to an enum field: `choices` pairs each accepted string with its value.
template <typename O, typename Access, typename E = std::decay_t<decltype(std::declval<Access>()(std::declval<O&>()))>>
ParamSpec<O> EnumParam(std::string name, std::string field, Access access,
                       std::vector<std::pair<std::string, E>> choices, std::string doc) {
  std::vector<std::string> names;
  for (const auto& c : choices) names.push_back(c.first);
  ParamSpec<O> spec;
  spec.name = std::move(name);
  spec.field = std::move(field);
  spec.get = [access, choices](const O& o) {
    for (const auto& c : choices) {
      if (c.second == access(const_cast<O&>(o))) return ParamValue(c.first);
    }
    return ParamValue(std::string("?"));
  };
  spec.set = [access, choices](O& o, const ParamValue& v) {
    for (const auto& c : choices) {
      if (c.first == std::get<std::string>(v)) access(o) = c.second;
    }
  };
  spec.doc = std::move(doc);
  spec.rule = param_rules::OneOf(names);
  return spec;
}

// Where values come from: the parameter server (RosParamSource) or a parsed YAML file (tests).
class ParamSource {
 public:
  virtual ~ParamSource() = default;
  // The value of `name`, of `like`'s type; nullopt if unset. A value of another type throws ParameterError.
  virtual std::optional<ParamValue> Get(const std::string& name, const ParamValue& like) const = 0;
  virtual bool Has(const std::string& name) const = 0;
  virtual std::string Resolve(const std::string& name) const = 0;  // "/amcl/kld_err"
  virtual void Warn(const std::string& message) const = 0;
  // A list of strings (the few list parameters, read outside the tables, e.g. ~validator/known_rooms);
  // nullopt if unset. Throws ParameterError naming it when it is not a list of strings, or when this source
  // holds no lists.
  virtual std::optional<std::vector<std::string>> GetStringList(const std::string& name) const {
    if (!Has(name)) return std::nullopt;
    throw ParameterError(Resolve(name) + ": lists cannot be given here");
  }
};

// Reads every parameter of `table` from `source` into `*o` over its current values (the defaults, or
// what the caller loaded before, e.g. a world file's): type and rule checked, deprecated names honoured
// with a warning. Throws ParameterError naming the resolved parameter.
template <typename O>
void ApplyParamTable(const ParamTable<O>& table, const ParamSource& source, O* o) {
  for (const ParamSpec<O>& spec : table) {
    const ParamValue like = spec.get(*o);
    std::string used = spec.name;
    std::optional<ParamValue> value = source.Get(spec.name, like);
    // A deprecated name can only come from a user's own launch file or YAML: it wins over the new name
    // (which the shipped config sets), so launch files written for the old name keep working.
    for (const std::string& old_name : spec.deprecated_names) {
      std::optional<ParamValue> old_value = source.Get(old_name, like);
      if (!old_value) continue;
      std::string warning = source.Resolve(old_name) + " is deprecated: use " + source.Resolve(spec.name);
      if (value && *value != *old_value) {
        warning += " (its value " + FormatParamValue(*old_value) + " is used, not " + source.Resolve(spec.name) +
                   " = " + FormatParamValue(*value) + ")";
      }
      source.Warn(warning);
      value = std::move(old_value);
      used = old_name;
    }
    if (!value) continue;
    if (spec.rule.ok && !spec.rule.ok(*value)) {
      throw ParameterError(source.Resolve(used) + " must be " + spec.rule.text + ", got " + FormatParamValue(*value));
    }
    try {
      spec.set(*o, *value);
    } catch (const std::invalid_argument& e) {  // a setter's own check (e.g. a fractional integer option)
      throw ParameterError(source.Resolve(used) + ": " + e.what());
    }
  }
}

// Runs `build` (constructs the core objects from `o`); an std::invalid_argument it throws becomes a
// ParameterError naming every parameter whose field the core's message mentions ("WallFollowerOptions.
// slow_down_distance_m: must be > end_stop_distance_m" names ~slow_down_distance_m and
// ~end_stop_distance_m with their values), or the namespace if it mentions none.
template <typename O, typename Build>
void CheckWithCore(const ParamTable<O>& table, const O& o, const ParamSource& source, const Build& build) {
  try {
    build();
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    std::vector<std::string> words;
    std::string word;
    for (const char c : message + " ") {
      if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
        word += c;
      } else if (!word.empty()) {
        words.push_back(word);
        word.clear();
      }
    }
    std::string named;
    for (const ParamSpec<O>& spec : table) {
      const std::string last = spec.field.substr(spec.field.find_last_of('.') + 1);
      bool mentioned = false;
      for (const std::string& w : words) mentioned = mentioned || w == last || w == spec.name;
      if (!mentioned) continue;
      named += (named.empty() ? "" : ", ") + source.Resolve(spec.name) + " = " + FormatParamValue(spec.get(o));
    }
    if (named.empty()) named = source.Resolve("");
    throw ParameterError(named + ": refused by the core options: " + message);
  }
}

// `text` as a markdown table cell: '|' escaped.
inline std::string MarkdownCell(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

// The docs/parameters.md table of `table`: | parameter | field | default | valid | meaning |, one row each
// (valid: the rule, or the type when any value of it is).
template <typename O>
std::string MarkdownParamTable(const ParamTable<O>& table) {
  const O defaults{};
  std::string out = "| parameter | field | default | valid | meaning |\n|---|---|---|---|---|\n";
  for (const ParamSpec<O>& spec : table) {
    std::string name = "`~" + spec.name + "`";
    for (const std::string& old_name : spec.deprecated_names) name += " (deprecated: `~" + old_name + "`)";
    std::string value = spec.default_text;
    if (value.empty()) {
      value = FormatParamValue(spec.get(defaults));
      if (value.empty()) value = "\"\"";
    }
    if (spec.shipped && *spec.shipped != spec.get(defaults)) {
      value += " (config: " + FormatParamValue(*spec.shipped) + ")";
    }
    const std::string rule = spec.rule.text.empty() ? ParamTypeName(spec.get(defaults)) : spec.rule.text;
    out += "| " + name + " | `" + spec.field + "` | " + MarkdownCell(value) + " | " + MarkdownCell(rule) + " | " +
           MarkdownCell(spec.doc) + " |\n";
  }
  return out;
}

}  // namespace doorplate_localization

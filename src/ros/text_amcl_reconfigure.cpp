#include "text_amcl_reconfigure.h"

#include <stdexcept>
#include <utility>

#include <boost/any.hpp>
#include <dynamic_reconfigure/config_tools.h>
#include <ros/console.h>

namespace doorplate_localization {
namespace {

// The reconfigure request's values as a parameter source: only its names are set.
class ReconfigureSource : public ParamSource {
 public:
  ReconfigureSource(const std::map<std::string, ParamValue>& values, std::string ns)
      : values_(values), ns_(std::move(ns)) {}
  std::optional<ParamValue> Get(const std::string& name, const ParamValue& like) const override {
    const auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    if (it->second.index() != like.index()) throw ParameterError(Resolve(name) + " must be " + ParamTypeName(like));
    return it->second;
  }
  bool Has(const std::string& name) const override { return values_.count(name) > 0; }
  std::string Resolve(const std::string& name) const override { return ns_ + "/" + name; }
  void Warn(const std::string& message) const override { ROS_WARN("%s", message.c_str()); }

 private:
  const std::map<std::string, ParamValue>& values_;
  std::string ns_;
};

const ParamSpec<TextAmclNodeOptions>& SpecNamed(const std::string& name) {
  for (const ParamSpec<TextAmclNodeOptions>& spec : TextAmclParamTable()) {
    if (spec.name == name) return spec;
  }
  throw std::invalid_argument("cfg/TextAmcl.cfg: '" + name + "' is not a parameter of TextAmclParamTable");
}

}  // namespace

std::map<std::string, ParamValue> ReconfigureValues(const TextAmclConfig& config) {
  std::map<std::string, ParamValue> values;
  for (const TextAmclConfig::AbstractParamDescriptionConstPtr& d : TextAmclConfig::__getParamDescriptions__()) {
    boost::any value;
    d->getValue(config, value);
    if (d->type == "int") values[d->name] = boost::any_cast<int>(value);
    else if (d->type == "double") values[d->name] = boost::any_cast<double>(value);
    else if (d->type == "bool") values[d->name] = boost::any_cast<bool>(value);
    else values[d->name] = boost::any_cast<std::string>(value);
  }
  return values;
}

TextAmclConfig ToReconfigureConfig(const TextAmclNodeOptions& options) {
  dynamic_reconfigure::Config msg;
  for (const auto& [name, like] : ReconfigureValues(TextAmclConfig::__getDefault__())) {
    const ParamValue value = SpecNamed(name).get(options);
    if (value.index() != like.index()) {
      throw std::invalid_argument("cfg/TextAmcl.cfg: '" + name + "' is not " + ParamTypeName(value) +
                                  " as in TextAmclParamTable");
    }
    std::visit([&msg, &name = name](const auto& v) { dynamic_reconfigure::ConfigTools::appendParameter(msg, name, v); },
               value);
  }
  TextAmclConfig config = TextAmclConfig::__getDefault__();
  config.__fromMessage__(msg);
  return config;
}

TextAmclNodeOptions ReconfiguredTextAmclOptions(const TextAmclNodeOptions& current,
                                                const std::map<std::string, ParamValue>& values,
                                                const std::string& ns) {
  for (const auto& [name, value] : values) (void)SpecNamed(name);
  const ReconfigureSource source(values, ns);
  TextAmclNodeOptions next = current;
  ApplyParamTable(TextAmclParamTable(), source, &next);
  CheckTextAmclOptions(next, source);
  return next;
}

std::string DescribeReconfigureChange(const TextAmclNodeOptions& before, const TextAmclNodeOptions& after,
                                      const std::map<std::string, ParamValue>& names) {
  std::string change;
  for (const auto& [name, value] : names) {
    const ParamSpec<TextAmclNodeOptions>& spec = SpecNamed(name);
    const ParamValue old_value = spec.get(before);
    const ParamValue new_value = spec.get(after);
    if (old_value == new_value) continue;
    change += (change.empty() ? "" : ", ") + name + " " + FormatParamValue(old_value) + " -> " +
              FormatParamValue(new_value);
  }
  return change;
}

TextAmclReconfigureServer::TextAmclReconfigureServer(const ros::NodeHandle& private_nh,
                                                     const TextAmclNodeOptions& options, Apply apply)
    : ns_(private_nh.getNamespace()),
      in_force_(options),
      apply_(std::move(apply)),
      server_(server_mutex_, private_nh) {
  // The first call (now) has the parameter server's values, which the options in force were loaded from.
  server_.setCallback([this](TextAmclConfig& config, std::uint32_t level) { OnRequest(config, level); });
}

void TextAmclReconfigureServer::OnRequest(TextAmclConfig& config, std::uint32_t /*level*/) {
  const std::map<std::string, ParamValue> values = ReconfigureValues(config);
  TextAmclNodeOptions next;
  try {
    next = ReconfiguredTextAmclOptions(in_force_, values, ns_);
  } catch (const ParameterError& e) {
    ROS_ERROR("%s/set_parameters: refused: %s; the values in force are kept", ns_.c_str(), e.what());
    config = ToReconfigureConfig(in_force_);
    return;
  }
  const std::string change = DescribeReconfigureChange(in_force_, next, values);
  if (change.empty()) return;
  const std::string problem = apply_(next);
  if (!problem.empty()) {
    ROS_ERROR("%s/set_parameters: %s refused by the localizer: %s; the values in force are kept", ns_.c_str(),
              change.c_str(), problem.c_str());
    config = ToReconfigureConfig(in_force_);
    return;
  }
  in_force_ = next;
  ROS_INFO("%s/set_parameters: %s", ns_.c_str(), change.c_str());
}

}  // namespace doorplate_localization

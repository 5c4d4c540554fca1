// Strict reading of nodelet parameters, shared by every Load...Options() function: a parameter of the
// wrong type or out of range is an error naming the fully resolved parameter, never silently replaced.
// RosParamSource / ReadParamTable read a nodelet's parameter table (ros/param_table.h) from its private
// namespace.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

#include <ros/console.h>
#include <ros/node_handle.h>

#include "doorplate_localization/ros/param_table.h"

namespace doorplate_localization {

namespace param_detail {
template <typename T>
const char* TypeName();
template <>
inline const char* TypeName<double>() { return "a number"; }
template <>
inline const char* TypeName<int>() { return "an integer"; }
template <>
inline const char* TypeName<bool>() { return "a boolean"; }
template <>
inline const char* TypeName<std::string>() { return "a string"; }
}  // namespace param_detail

// The parameter's value, `fallback` if it is not set; a value of the wrong type throws ParameterError.
template <typename T>
T ReadParam(const ros::NodeHandle& nh, const std::string& name, const T& fallback) {
  if (!nh.hasParam(name)) return fallback;
  T value;
  if (!nh.getParam(name, value)) {
    throw ParameterError(nh.resolveName(name) + " must be " + param_detail::TypeName<T>());
  }
  return value;
}

// Throws ParameterError "<resolved name> must be <rule>, got <value>" unless `ok`.
template <typename T>
void RequireParam(bool ok, const ros::NodeHandle& nh, const std::string& name, const std::string& rule,
                  const T& value) {
  if (ok) return;
  std::ostringstream out;
  out << nh.resolveName(name) << " must be " << rule << ", got " << value;
  throw ParameterError(out.str());
}

// A tf2 frame id: non-empty, no leading '/'.
inline std::string ReadFrameParam(const ros::NodeHandle& nh, const std::string& name, const std::string& fallback) {
  const std::string frame = ReadParam(nh, name, fallback);
  if (frame.empty() || frame.front() == '/') {
    throw ParameterError(nh.resolveName(name) + " must be a non-empty tf2 frame id without a leading '/', got '" +
                         frame + "'");
  }
  return frame;
}

// A parameter table's values from the parameter server, under `nh`'s namespace.
class RosParamSource : public ParamSource {
 public:
  explicit RosParamSource(const ros::NodeHandle& nh) : nh_(nh) {}
  std::optional<ParamValue> Get(const std::string& name, const ParamValue& like) const override {
    if (!nh_.hasParam(name)) return std::nullopt;
    return std::visit(
        [&](const auto& typed) -> ParamValue {
          using T = std::decay_t<decltype(typed)>;
          T value;
          if (!nh_.getParam(name, value)) {
            throw ParameterError(nh_.resolveName(name) + " must be " + ParamTypeName(like));
          }
          return value;
        },
        like);
  }
  bool Has(const std::string& name) const override { return nh_.hasParam(name); }
  std::string Resolve(const std::string& name) const override { return nh_.resolveName(name); }
  void Warn(const std::string& message) const override { ROS_WARN_STREAM(message); }
  std::optional<std::vector<std::string>> GetStringList(const std::string& name) const override {
    if (!nh_.hasParam(name)) return std::nullopt;
    std::vector<std::string> list;
    if (!nh_.getParam(name, list)) {  // not a list, or an entry is not a string (an unquoted 201 is an int)
      throw ParameterError(nh_.resolveName(name) + " must be a list of strings (quote room numbers: ['201', '202A'])");
    }
    return list;
  }

 private:
  ros::NodeHandle nh_;
};

// Reads `table` from `nh`'s namespace into `*o` (ApplyParamTable). Throws ParameterError.
template <typename O>
void ReadParamTable(const ros::NodeHandle& nh, const ParamTable<O>& table, O* o) {
  ApplyParamTable(table, RosParamSource(nh), o);
}

}  // namespace doorplate_localization

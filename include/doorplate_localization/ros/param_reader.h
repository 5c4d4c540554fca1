// Strict reading of nodelet parameters, shared by every Load...Options() function: a parameter of the
// wrong type or out of range is an error naming the fully resolved parameter, never silently replaced.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

#include <ros/node_handle.h>

namespace doorplate_localization {

// A parameter that cannot be used; what() names the fully resolved parameter.
class ParameterError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

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

}  // namespace doorplate_localization

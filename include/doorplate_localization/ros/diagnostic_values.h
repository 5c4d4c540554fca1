// Building a diagnostic_msgs/DiagnosticStatus's key/value list: shared by the nodelets' health conversions
// (amcl_conversions.h, slam_conversions.h). Header-only: each nodelet library includes it without linking
// another's.
#pragma once

#include <sstream>
#include <string>

#include <diagnostic_msgs/DiagnosticStatus.h>

namespace doorplate_localization {

// Appends `key: value` to status->values.
inline void AddDiagnosticValue(diagnostic_msgs::DiagnosticStatus* status, const std::string& key,
                               const std::string& value) {
  diagnostic_msgs::KeyValue kv;
  kv.key = key;
  kv.value = value;
  status->values.push_back(kv);
}

// `value` in fixed notation with `precision` decimals ("12.5").
inline std::string FixedDecimals(double value, int precision) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(precision);
  out << value;
  return out.str();
}

}  // namespace doorplate_localization

// One named entry of /diagnostics as a rostest checker sees it (test/ros/*_rostest.cpp): the latest status
// published under that name, and its key/value pairs. Delivered by rostest_util::WaitFor's callback
// processing, like every subscription of the single-threaded checkers.
#pragma once

#include <string>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/ros.h>

namespace doorplate_localization {
namespace rostest_util {

class DiagnosticsEntry {
 public:
  // Listens to /diagnostics for the entry named `name` (e.g. "/amcl: localization").
  explicit DiagnosticsEntry(const std::string& name) : name_(name) {
    sub_ = nh_.subscribe<diagnostic_msgs::DiagnosticArray>(
        "/diagnostics", 10, [this](const diagnostic_msgs::DiagnosticArray::ConstPtr& m) {
          for (const auto& s : m->status) {
            if (s.name != name_) continue;
            status_ = s;
            seen_ = true;
          }
        });
  }
  DiagnosticsEntry(const DiagnosticsEntry&) = delete;
  DiagnosticsEntry& operator=(const DiagnosticsEntry&) = delete;

  bool seen() const { return seen_; }
  const diagnostic_msgs::DiagnosticStatus& status() const { return status_; }
  // The value under `key` in the latest status, or "(missing)".
  std::string Value(const std::string& key) const {
    for (const auto& kv : status_.values) {
      if (kv.key == key) return kv.value;
    }
    return "(missing)";
  }

 private:
  ros::NodeHandle nh_;
  std::string name_;
  diagnostic_msgs::DiagnosticStatus status_;
  bool seen_ = false;
  ros::Subscriber sub_;
};

}  // namespace rostest_util
}  // namespace doorplate_localization

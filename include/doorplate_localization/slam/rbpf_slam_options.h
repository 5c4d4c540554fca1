// RbpfSlamOptions by name: the one table of parameter names shared by the offline command
// (`doorplate_map_log --set NAME=VALUE`) and the mapping nodelet (ROS parameters of the same names),
// so both run the filter with the same settings.
#pragma once

#include <string>
#include <vector>

#include "doorplate_localization/slam/rbpf_slam.h"
#include "doorplate_localization/slam/text_slam.h"

namespace doorplate_localization {

// Every numeric option's name: "num_particles", "linear_update_m", "matcher.field_sigma_m", ...
// (the field path in RbpfSlamOptions).
std::vector<std::string> RbpfSlamOptionNames();

// Sets the option `name` to `value`. Throws std::invalid_argument naming the option if the name is
// unknown or an integer option gets a fractional value. Ranges are checked when the filter is built.
void SetRbpfSlamOption(const std::string& name, double value, RbpfSlamOptions* options);

// The current value of option `name`; throws std::invalid_argument if the name is unknown.
double GetRbpfSlamOption(const std::string& name, const RbpfSlamOptions& options);

// TextSlamOptions by name: every RbpfSlamOptions name above (for options.slam) plus "text.<field>" for
// the text fields ("text.min_confidence", "text.plate_sigma_m", ...). Same errors as above.
std::vector<std::string> TextSlamOptionNames();
void SetTextSlamOption(const std::string& name, double value, TextSlamOptions* options);
double GetTextSlamOption(const std::string& name, const TextSlamOptions& options);

}  // namespace doorplate_localization

// Text AMCL's dynamic_reconfigure server (cfg/TextAmcl.cfg; issue 19: amcl's run-time parameters). A
// request is read through the parameter table (per-value rules) and CheckTextAmclOptions (the rules between
// parameters and the whole set against the core), exactly as the startup parameters are. A refused request
// is logged naming the parameter and its value and is answered with the values in force: nothing changes.
// An accepted one is handed to the nodelet, which applies it to the running localizer (LocalizerCore::
// Reconfigure: the particles are kept) and to its own publishing (transform_tolerance, gui_publish_rate).
// dynamic_reconfigure's server clamps a value outside the .cfg's range to its end before the callback sees
// it; the ranges are the rules' closures, so an open end (kld_err 0) is still refused here.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include <boost/thread/recursive_mutex.hpp>
#include <dynamic_reconfigure/server.h>
#include <ros/node_handle.h>

#include "doorplate_localization/TextAmclConfig.h"
#include "text_amcl_options.h"

namespace doorplate_localization {

// The config's values by parameter name, typed as the parameter table types them (int, double, bool,
// string: the .cfg's int_t, double_t, bool_t, str_t).
std::map<std::string, ParamValue> ReconfigureValues(const doorplate_localization::TextAmclConfig& config);

// Every reconfigurable parameter's value in `options` (as the parameter table reads it from the fields).
doorplate_localization::TextAmclConfig ToReconfigureConfig(const TextAmclNodeOptions& options);

// `current` with `values` (parameter name -> value) applied through the parameter table and checked as at
// startup (ApplyParamTable, CheckTextAmclOptions). Throws ParameterError naming the parameter resolved in
// `ns` ("/amcl/kld_err must be finite and > 0, got 0.0", "/amcl/max_particles = 50, /amcl/min_particles =
// 100: refused by the core options: ..."), std::invalid_argument for a name the table does not have.
TextAmclNodeOptions ReconfiguredTextAmclOptions(const TextAmclNodeOptions& current,
                                                const std::map<std::string, ParamValue>& values,
                                                const std::string& ns);

// "kld_err 0.01 -> 0.05, max_particles 5000 -> 300": the parameters of `names` whose values differ; "" if none.
std::string DescribeReconfigureChange(const TextAmclNodeOptions& before, const TextAmclNodeOptions& after,
                                      const std::map<std::string, ParamValue>& names);

class TextAmclReconfigureServer {
 public:
  // Applies options already checked; returns "" or why they cannot be applied (nothing changed then).
  using Apply = std::function<std::string(const TextAmclNodeOptions&)>;

  // Serves ~set_parameters (and ~parameter_descriptions, ~parameter_updates) under `private_nh`, starting
  // from the parameter server's values, which `options` (the options in force) were loaded from.
  TextAmclReconfigureServer(const ros::NodeHandle& private_nh, const TextAmclNodeOptions& options, Apply apply);

 private:
  void OnRequest(doorplate_localization::TextAmclConfig& config, std::uint32_t level);

  std::string ns_;
  TextAmclNodeOptions in_force_;
  Apply apply_;
  boost::recursive_mutex server_mutex_;  // dynamic_reconfigure's, held while it calls OnRequest
  dynamic_reconfigure::Server<doorplate_localization::TextAmclConfig> server_;
};

}  // namespace doorplate_localization

#include "slam_mapping_options.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "doorplate_localization/common/room_id.h"
#include "doorplate_localization/slam/rbpf_slam_options.h"

namespace doorplate_localization {
namespace {

// A gmapping parameter that is the same option as a core one.
struct GmappingAlias {
  const char* gmapping;
  const char* core;     // name in TextSlamOptionNames()
  double gmapping_default;
};

// gmapping's defaults (slam_gmapping.cpp / ROS wiki). srr..stt: gmapping's odometry noise coefficients
// (translation per translation, translation per rotation, rotation per translation, rotation per
// rotation) are our motion model's standard deviations per metre / radian (motion_model.h).
const GmappingAlias kAliases[] = {
    {"particles", "num_particles", 30},
    {"linearUpdate", "linear_update_m", 1.0},
    {"angularUpdate", "angular_update_rad", 0.5},
    {"resampleThreshold", "resample_neff_ratio", 0.5},
    {"maxUrange", "max_usable_range_m", 80.0},
    {"delta", "grid.resolution_m", 0.05},
    {"srr", "motion.trans_stddev_m_per_m", 0.1},
    {"srt", "motion.trans_stddev_m_per_rad", 0.2},
    {"str", "motion.rot_stddev_rad_per_m", 0.1},
    {"stt", "motion.rot_stddev_rad_per_rad", 0.2},
};

// gmapping parameters without a counterpart (its scan matcher and likelihood are built differently, our
// tiled map grows as needed): reported when set, never silently taken for something else.
const char* const kIgnoredGmapping[] = {
    "sigma", "kernelSize", "lstep", "astep", "iterations", "lsigma", "ogain", "lskip", "minimumScore",
    "llsamplerange", "llsamplestep", "lasamplerange", "lasamplestep", "xmin", "ymin", "xmax", "ymax",
    "temporalUpdate", "occ_thresh", "tf_delay"};

double ReadFinite(const ros::NodeHandle& nh, const std::string& name, double fallback) {
  const double value = ReadParam(nh, name, fallback);
  RequireParam(std::isfinite(value), nh, name, "finite", value);
  return value;
}

void ReadCoreOptions(const ros::NodeHandle& nh, TextSlamOptions* slam) {
  // gmapping's defaults for its names, unless the core name is set instead.
  for (const GmappingAlias& a : kAliases) {
    const std::string core_param = SlamOptionParamName(a.core);
    if (nh.hasParam(a.gmapping) && nh.hasParam(core_param)) {
      throw ParameterError(nh.resolveName(a.gmapping) + " and " + nh.resolveName(core_param) +
                           " are the same option: set only one");
    }
    if (nh.hasParam(core_param)) continue;  // read below with the other core names
    const double value = ReadFinite(nh, a.gmapping, a.gmapping_default);
    try {
      SetTextSlamOption(a.core, value, slam);
    } catch (const std::invalid_argument& e) {
      throw ParameterError(nh.resolveName(a.gmapping) + ": " + e.what());
    }
  }
  for (const std::string& name : TextSlamOptionNames()) {
    const std::string param = SlamOptionParamName(name);
    if (!nh.hasParam(param)) continue;
    const double value = ReadFinite(nh, param, 0.0);
    try {
      SetTextSlamOption(name, value, slam);
    } catch (const std::invalid_argument& e) {
      throw ParameterError(nh.resolveName(param) + ": " + e.what());
    }
  }
}

std::string DefaultOutputDir() {
  if (const char* ros_home = std::getenv("ROS_HOME"); ros_home != nullptr && *ros_home != '\0') {
    return std::string(ros_home) + "/doorplate_maps";
  }
  const char* home = std::getenv("HOME");
  return std::string(home != nullptr ? home : ".") + "/.ros/doorplate_maps";
}

}  // namespace

std::string SlamOptionParamName(const std::string& option_name) {
  std::string param = option_name;
  for (char& c : param) {
    if (c == '.') c = '/';
  }
  return param;
}

SlamMappingNodeOptions LoadSlamMappingOptions(const ros::NodeHandle& nh) {
  SlamMappingNodeOptions o;
  ReadCoreOptions(nh, &o.slam);
  const int seed = ReadParam(nh, "seed", static_cast<int>(o.slam.slam.seed));
  RequireParam(seed >= 0, nh, "seed", ">= 0", seed);
  o.slam.slam.seed = static_cast<std::uint64_t>(seed);
  try {
    TextSlam check(o.slam);  // the core validates its own ranges; its message names the field
  } catch (const std::invalid_argument& e) {
    throw ParameterError(nh.resolveName("") + ": invalid SLAM options: " + e.what() +
                         " (parameter ~<field path with / for .>, or its gmapping name)");
  }

  o.base_frame = ReadFrameParam(nh, "base_frame", o.base_frame);
  o.odom_frame = ReadFrameParam(nh, "odom_frame", o.odom_frame);
  o.map_frame = ReadFrameParam(nh, "map_frame", o.map_frame);
  if (o.base_frame == o.odom_frame || o.odom_frame == o.map_frame || o.base_frame == o.map_frame) {
    throw ParameterError(nh.resolveName("") + ": base_frame, odom_frame and map_frame must all differ");
  }
  o.map_update_interval_s = ReadFinite(nh, "map_update_interval", o.map_update_interval_s);
  RequireParam(o.map_update_interval_s > 0.0, nh, "map_update_interval", "> 0 seconds", o.map_update_interval_s);
  o.transform_publish_period_s = ReadFinite(nh, "transform_publish_period", o.transform_publish_period_s);
  RequireParam(o.transform_publish_period_s >= 0.0, nh, "transform_publish_period", ">= 0 seconds (0 = off)",
               o.transform_publish_period_s);
  o.max_range_m = ReadFinite(nh, "maxRange", o.max_range_m);
  RequireParam(o.max_range_m >= 0.0, nh, "maxRange", ">= 0 (0 = the scan's range_max)", o.max_range_m);
  o.throttle_scans = ReadParam(nh, "throttle_scans", o.throttle_scans);
  RequireParam(o.throttle_scans >= 1, nh, "throttle_scans", ">= 1", o.throttle_scans);
  o.min_valid_beams = ReadParam(nh, "min_valid_beams", o.min_valid_beams);
  RequireParam(o.min_valid_beams >= 1, nh, "min_valid_beams", ">= 1", o.min_valid_beams);
  o.tf_timeout_s = ReadFinite(nh, "tf_timeout_s", o.tf_timeout_s);
  RequireParam(o.tf_timeout_s >= 0.0 && o.tf_timeout_s <= 10.0, nh, "tf_timeout_s", "in [0, 10] seconds",
               o.tf_timeout_s);
  o.use_text = ReadParam(nh, "use_text", o.use_text);
  o.slam.room_pattern = ReadParam(nh, "room_pattern", o.slam.room_pattern);
  try {
    RoomIdGrammar check(o.slam.room_pattern);
  } catch (const std::invalid_argument& e) {
    throw ParameterError(nh.resolveName("room_pattern") + " must be an ECMAScript regex of the building's room "
                         "numbers (canonical form, docs/text-map-format.md), got '" + o.slam.room_pattern + "': " +
                         e.what());
  }
  o.map_output_dir = ReadParam(nh, "map_output_dir", o.map_output_dir);
  if (o.map_output_dir.empty()) o.map_output_dir = DefaultOutputDir();
  o.map_name = ReadParam(nh, "map_name", o.map_name);
  RequireParam(!o.map_name.empty() && o.map_name.find('/') == std::string::npos, nh, "map_name",
               "a non-empty file name without '/'", o.map_name);
  o.save_on_shutdown = ReadParam(nh, "save_on_shutdown", o.save_on_shutdown);
  for (const char* name : kIgnoredGmapping) {
    if (nh.hasParam(name)) o.ignored_parameters.push_back(nh.resolveName(name));
  }
  return o;
}

}  // namespace doorplate_localization

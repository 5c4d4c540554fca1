// SlamMappingNodelet's parameter table and loader. The table holds gmapping's names (with gmapping's
// defaults) and our node's own parameters; every option of the SLAM core is also a parameter under its name
// in the core's option table (TextSlamOptionNames, shared with the offline tools), read after the table.
// Rules between fields are the core's (TextSlam's constructor).
#include "slam_mapping_options.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "doorplate_localization/common/room_id.h"
#include "doorplate_localization/slam/rbpf_slam_options.h"

namespace doorplate_localization {
namespace {

using O = SlamMappingNodeOptions;

// A gmapping parameter that is the same option as a core one.
struct GmappingAlias {
  const char* gmapping;
  const char* core;     // name in TextSlamOptionNames()
  double gmapping_default;
  const char* doc;
};

// gmapping's defaults (slam_gmapping.cpp / ROS wiki). srr..stt: gmapping's odometry noise coefficients
// (translation per translation, translation per rotation, rotation per translation, rotation per
// rotation) are our motion model's standard deviations per metre / radian (its linear law,
// sensors/odometry_motion_model.h).
const GmappingAlias kAliases[] = {
    {"particles", "num_particles", 30, "particles"},
    {"linearUpdate", "linear_update_m", 1.0, "process a scan after driving this far (m)..."},
    {"angularUpdate", "angular_update_rad", 0.5, "...or turning this much (rad)"},
    {"resampleThreshold", "resample_neff_ratio", 0.5, "resample when Neff < this × particles"},
    {"maxUrange", "max_usable_range_m", 80.0, "longer beams only clear free space (m)"},
    {"delta", "grid.resolution_m", 0.05, "map cell size (m)"},
    {"srr", "motion.trans_noise_from_trans", 0.1, "odometry translation noise per metre driven"},
    {"srt", "motion.trans_noise_from_rot", 0.2, "odometry translation noise per radian turned"},
    {"str", "motion.rot_noise_from_trans", 0.1, "odometry rotation noise per metre driven"},
    {"stt", "motion.rot_noise_from_rot", 0.2, "odometry rotation noise per radian turned"},
};

// gmapping parameters without a counterpart (its scan matcher and likelihood are built differently, our
// tiled map grows as needed): reported when set, never silently taken for something else.
const char* const kIgnoredGmapping[] = {
    "sigma", "kernelSize", "lstep", "astep", "iterations", "lsigma", "ogain", "lskip", "minimumScore",
    "llsamplerange", "llsamplestep", "lasamplerange", "lasamplestep", "xmin", "ymin", "xmax", "ymax",
    "occ_thresh", "tf_delay"};

std::string DefaultOutputDir() {
  if (const char* ros_home = std::getenv("ROS_HOME"); ros_home != nullptr && *ros_home != '\0') {
    return std::string(ros_home) + "/doorplate_maps";
  }
  const char* home = std::getenv("HOME");
  return std::string(home != nullptr ? home : ".") + "/.ros/doorplate_maps";
}

}  // namespace

MappingSessionOptions ToMappingSessionOptions(const SlamMappingNodeOptions& o) {
  MappingSessionOptions session;
  session.slam = o.slam;
  session.throttle_scans = o.throttle_scans;
  session.temporal_update_s = o.temporal_update_s;
  session.map_update_interval_s = o.map_update_interval_s;
  session.map_update_max_solve_share = o.map_update_max_solve_share;
  session.camera_wait_s = o.use_text ? o.camera_wait_s : 0.0;  // nothing to wait for without the detections
  return session;
}

TextSlamOptions GmappingDefaultSlamOptions() {
  TextSlamOptions slam;
  for (const GmappingAlias& a : kAliases) SetTextSlamOption(a.core, a.gmapping_default, &slam);
  return slam;
}

std::string SlamOptionParamName(const std::string& option_name) {
  std::string param = option_name;
  for (char& c : param) {
    if (c == '.') c = '/';
  }
  return param;
}

const ParamTable<O>& SlamMappingParamTable() {
  namespace r = param_rules;
  static const ParamTable<O> table = [] {
    ParamTable<O> t;
    const TextSlamOptions core;
    for (const GmappingAlias& a : kAliases) {
      const std::string name = a.core;
      t.push_back(ConvertedParam<O, double>(
                      a.gmapping, "slam." + name, [name](const O& o) { return GetTextSlamOption(name, o.slam); },
                      [name](O& o, double v) { SetTextSlamOption(name, v, &o.slam); },
                      std::string("= core option `") + SlamOptionParamName(name) + "`: " + a.doc, r::Finite())
                      .Shipped(GetTextSlamOption(name, core)));  // config/mapping.yaml: the core's defaults
    }
    const ParamTable<O> rest = {
        Param<O>("maxRange", DOORPLATE_PARAM_FIELD(max_range_m),
                 "readings >= this are no echo (free space up to `no_return_clear_range_m`); 0 = the scan's "
                 "`range_max`",
                 r::NonNegative()),
        Param<O>("map_update_interval", DOORPLATE_PARAM_FIELD(map_update_interval_s),
                 "seconds (scan stamps) between back-end solves, each published on `map` / `map_metadata`",
                 r::Positive()),
        Param<O>("map_update_max_solve_share", DOORPLATE_PARAM_FIELD(map_update_max_solve_share),
                 "(ours) a solve's cost grows with the trajectory: a periodic solve also waits until the solves "
                 "took at most this share of the wall clock (keeps up with the scans after hours of driving; "
                 "~save_maps solves at once); 0: off",
                 r::Holds("in [0, 1)", [](double v) { return v >= 0.0 && v < 1.0; })),
        Param<O>("temporalUpdate", DOORPLATE_PARAM_FIELD(temporal_update_s),
                 "also process a scan when this many seconds (scan stamps) passed since the last processed one, "
                 "moving or not; <= 0: off (gmapping's name and default)",
                 r::Finite()),
        Param<O>("transform_publish_period", DOORPLATE_PARAM_FIELD(transform_publish_period_s),
                 "seconds between `map → odom` broadcasts (0 = none); each is future-dated by one period",
                 r::NonNegative()),
        Param<O>("throttle_scans", DOORPLATE_PARAM_FIELD(throttle_scans), "use every n-th scan", r::AtLeast(1)),
        Param<O>("base_frame", DOORPLATE_PARAM_FIELD(base_frame), "the robot's frame (gmapping's name)", r::FrameId()),
        Param<O>("odom_frame", DOORPLATE_PARAM_FIELD(odom_frame), "odometry frame (gmapping's name)", r::FrameId()),
        Param<O>("map_frame", DOORPLATE_PARAM_FIELD(map_frame), "map frame (gmapping's name); the three differ",
                 r::FrameId()),
        ConvertedParam<O, int>(
            "seed", "slam.slam.seed", [](const O& o) { return static_cast<int>(o.slam.slam.seed); },
            [](O& o, int seed) { o.slam.slam.seed = static_cast<std::uint64_t>(seed); },
            "(ours) the filter's random seed", r::AtLeast(0)),
        Param<O>("use_text", DOORPLATE_PARAM_FIELD(use_text), "(ours) subscribe `text_detections` and map the plates"),
        Param<O>("camera_wait_s", DOORPLATE_PARAM_FIELD(camera_wait_s),
                 "(ours, with use_text) a scan waits until the text extractor's arrays (empty ones too) reached its "
                 "stamp, at most this long (scan stamps): scans and plates reach the filter in stamp order "
                 "whatever order they arrive in, so a replayed bag maps as doorplate_map_bag maps it; 0: no waiting",
                 r::Holds("in [0, 60] seconds", [](double v) { return v >= 0.0 && v <= 60.0; })),
        Param<O>("room_pattern", DOORPLATE_PARAM_FIELD(slam.room_pattern),
                 "(ours) the building's room identifier format, an ECMAScript regex (the text extractor's "
                 "parameter of the same name): plates whose canonical text does not fit are not mapped; written "
                 "as the saved text map's `room_pattern`"),
        Param<O>("min_valid_beams", DOORPLATE_PARAM_FIELD(min_valid_beams),
                 "(ours) scans with fewer finite returns are dropped (warning)", r::AtLeast(1)),
        Param<O>("tf_timeout_s", DOORPLATE_PARAM_FIELD(tf_timeout_s),
                 "(ours) wait at most this for a tf at a scan's or detection's stamp",
                 r::Holds("in [0, 10] seconds", [](double v) { return v >= 0.0 && v <= 10.0; })),
        Param<O>("map_output_dir", DOORPLATE_PARAM_FIELD(map_output_dir),
                 "(ours) folder of `~save_maps` and the save at shutdown; \"\" = `$ROS_HOME/doorplate_maps` "
                 "(`~/.ros/doorplate_maps`)"),
        Param<O>("map_name", DOORPLATE_PARAM_FIELD(map_name),
                 "(ours) files `<dir>/<name>.pgm`, `<name>.yaml` (map_server), `<name>.text_map.yaml`",
                 {"a non-empty file name without '/'",
                  [](const ParamValue& v) {
                    const std::string& n = std::get<std::string>(v);
                    return !n.empty() && n.find('/') == std::string::npos;
                  }}),
        Param<O>("save_on_shutdown", DOORPLATE_PARAM_FIELD(save_on_shutdown),
                 "(ours) write the maps when the nodelet is unloaded or the manager exits"),
    };
    t.insert(t.end(), rest.begin(), rest.end());
    return t;
  }();
  return table;
}

SlamMappingNodeOptions SlamMappingOptionsFrom(const ParamSource& source) {
  const ParamTable<O>& table = SlamMappingParamTable();
  for (const GmappingAlias& a : kAliases) {
    const std::string core_param = SlamOptionParamName(a.core);
    if (source.Has(a.gmapping) && source.Has(core_param)) {
      throw ParameterError(source.Resolve(a.gmapping) + " and " + source.Resolve(core_param) +
                           " are the same option: set only one");
    }
  }
  O o;
  ApplyParamTable(table, source, &o);
  // Every core option by its table name (a gmapping name's core name included: it replaces gmapping's default).
  for (const std::string& name : TextSlamOptionNames()) {
    const std::string param = SlamOptionParamName(name);
    const std::optional<ParamValue> value = source.Get(param, 0.0);
    if (!value) continue;
    const double v = std::get<double>(*value);
    if (!std::isfinite(v)) throw ParameterError(source.Resolve(param) + " must be finite, got " + FormatParamValue(v));
    try {
      SetTextSlamOption(name, v, &o.slam);
    } catch (const std::invalid_argument& e) {
      throw ParameterError(source.Resolve(param) + ": " + e.what());
    }
  }
  if (o.base_frame == o.odom_frame || o.odom_frame == o.map_frame || o.base_frame == o.map_frame) {
    throw ParameterError(source.Resolve("") + ": base_frame, odom_frame and map_frame must all differ");
  }
  try {
    RoomIdGrammar check(o.slam.room_pattern);
  } catch (const std::invalid_argument& e) {
    throw ParameterError(source.Resolve("room_pattern") + " must be an ECMAScript regex of the building's room "
                         "numbers (canonical form, docs/text-map-format.md), got '" + o.slam.room_pattern + "': " +
                         e.what());
  }
  // The core validates its own ranges; its message names the field (and so the gmapping name, if it has one).
  CheckWithCore(table, o, source, [&o] { ValidateMappingSessionOptions(ToMappingSessionOptions(o)); (void)TextSlam(o.slam); });
  if (o.map_output_dir.empty()) o.map_output_dir = DefaultOutputDir();
  for (const char* name : kIgnoredGmapping) {
    if (source.Has(name)) o.ignored_parameters.push_back(source.Resolve(name));
  }
  return o;
}

SlamMappingNodeOptions LoadSlamMappingOptions(const ros::NodeHandle& nh) {
  return SlamMappingOptionsFrom(RosParamSource(nh));
}

}  // namespace doorplate_localization

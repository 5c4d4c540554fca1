// CorridorSimNodelet's parameter table and loader: every parameter once (name, field, default, rule, doc).
// The simulator core has no options check of its own, so the few rules between values (the principal
// point within the image, six different frames, the world's sensor rates) stay here.
#include "corridor_sim_options.h"

#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>

#include "doorplate_localization/sim/world_loader.h"

namespace doorplate_localization {

const ParamTable<CorridorSimOptions>& CorridorSimParamTable() {
  using O = CorridorSimOptions;
  namespace r = param_rules;
  const auto camera_size = r::Holds("in [16, 8192]", [](double v) { return v >= 16 && v <= 8192; });
  const auto intrinsic = r::Holds("finite and >= 0 pixels (0: derived)",
                                  [](double v) { return std::isfinite(v) && v >= 0.0 && v <= 1e6; });
  static const ParamTable<O> table = {
      Param<O>("world", DOORPLATE_PARAM_FIELD(world_file),
               "world file, docs/world-format.md; its `sensors:` block sets the sensor models and rates")
          .DefaultText("(required, or `building`)"),
      Param<O>("building", DOORPLATE_PARAM_FIELD(building_file),
               "instead of `world`: a building file naming each floor's `world` and the lifts "
               "(docs/building-format.md); the start floor's world gives the sensors of every floor; `ride_lift` "
               "carries the robot between floors"),
      Param<O>("floor", DOORPLATE_PARAM_FIELD(floor),
               "with `building`: the id of the floor the robot starts on; \"\": the building's first"),
      Param<O>("start_x_m", DOORPLATE_PARAM_FIELD(world.start_pose.x_m),
               "where the robot starts, world frame (e.g. a localization run from an unknown pose)", r::Finite())
          .DefaultText("the world's `robot.start`"),
      Param<O>("start_y_m", DOORPLATE_PARAM_FIELD(world.start_pose.y_m), "see `start_x_m`", r::Finite())
          .DefaultText("the world's `robot.start`"),
      ConvertedParam<O, double>(
          "start_theta_deg", "world.start_pose.theta_rad",
          [](const O& o) { return o.world.start_pose.theta_rad * 180.0 / M_PI; },
          [](O& o, double deg) { o.world.start_pose.theta_rad = NormalizeAngle(deg * M_PI / 180.0); },
          "the start heading, degrees", r::Finite())
          .DefaultText("the world's `robot.start`"),
      Param<O>("camera/width_px", DOORPLATE_PARAM_FIELD(world.sensors.camera.width_px),
               "image width (e.g. 1280 for a common USB camera); `camera/camera_info` reports it", camera_size)
          .DefaultText("the world's (640)"),
      Param<O>("camera/height_px", DOORPLATE_PARAM_FIELD(world.sensors.camera.height_px), "image height",
               camera_size)
          .DefaultText("the world's (480)"),
      Param<O>("camera/horizontal_fov_deg", DOORPLATE_PARAM_FIELD(world.sensors.camera.horizontal_fov_deg),
               "horizontal field of view, degrees; gives fx when `camera/fx_px` is 0",
               r::Holds("in (1, 170) degrees", [](double v) { return v > 1.0 && v < 170.0; }))
          .DefaultText("the world's (60)"),
      Param<O>("camera/fx_px", DOORPLATE_PARAM_FIELD(world.sensors.camera.fx_px),
               "pinhole focal length; 0: from the field of view; a non-zero fx wins over the field of view",
               intrinsic)
          .DefaultText("the world's (0)"),
      Param<O>("camera/fy_px", DOORPLATE_PARAM_FIELD(world.sensors.camera.fy_px), "0: fy = fx", intrinsic)
          .DefaultText("the world's (0)"),
      Param<O>("camera/cx_px", DOORPLATE_PARAM_FIELD(world.sensors.camera.cx_px),
               "principal point column, at most width − 1; 0: (width − 1)/2", intrinsic)
          .DefaultText("the world's (0)"),
      Param<O>("camera/cy_px", DOORPLATE_PARAM_FIELD(world.sensors.camera.cy_px),
               "principal point row, at most height − 1; 0: (height − 1)/2", intrinsic)
          .DefaultText("the world's (0)"),
      ConvertedParam<O, int>(
          "seed", "simulator.seed", [](const O& o) { return static_cast<int>(o.simulator.seed); },
          [](O& o, int seed) { o.simulator.seed = static_cast<std::uint64_t>(seed); },
          "seed of the odometry, laser and camera noise streams (independent streams: subscribing to the "
          "camera never changes the odometry)",
          r::AtLeast(0)),
      Param<O>("real_time_factor", DOORPLATE_PARAM_FIELD(real_time_factor),
               "simulated seconds per wall-clock second; 0 = as fast as possible",
               r::Holds("finite and >= 0 (0 = as fast as possible)",
                        [](double v) { return std::isfinite(v) && v >= 0.0; })),
      Param<O>("publish_clock", DOORPLATE_PARAM_FIELD(publish_clock),
               "publish `/clock`; run the graph with `/use_sim_time` true"),
      Param<O>("wait_for_recorder_s", DOORPLATE_PARAM_FIELD(wait_for_recorder_s),
               "wall seconds to wait, before the first step, for a subscriber of `base_pose_ground_truth` (a "
               "recorder such as `rosbag record`), so that a recording holds the run from sim time 0; 0 = start at once",
               r::Holds("finite and >= 0", [](double v) { return std::isfinite(v) && v >= 0.0; })),
      Param<O>("physics_step_s", DOORPLATE_PARAM_FIELD(simulator.physics_step_s), "simulation step",
               r::Holds("in (0, 0.1] seconds", [](double v) { return v > 0.0 && v <= 0.1; })),
      Param<O>("max_linear_speed_mps", DOORPLATE_PARAM_FIELD(simulator.max_linear_speed_mps),
               "`cmd_vel` is clamped to this", r::Positive()),
      Param<O>("max_angular_speed_rps", DOORPLATE_PARAM_FIELD(simulator.max_angular_speed_rps),
               "`cmd_vel` is clamped to this", r::Positive()),
      Param<O>("cmd_vel_timeout_s", DOORPLATE_PARAM_FIELD(cmd_vel_timeout_s),
               "simulated seconds without `cmd_vel` after which the robot stops", r::Positive()),
      Param<O>("publish_ground_truth_tf", DOORPLATE_PARAM_FIELD(publish_ground_truth_tf),
               "broadcast `map → odom` from the true pose (viewing without a localizer; never together with one)"),
      Param<O>("odom_frame_id", DOORPLATE_PARAM_FIELD(odom_frame_id), "odometry frame", r::FrameId()),
      Param<O>("base_frame_id", DOORPLATE_PARAM_FIELD(base_frame_id), "the robot's frame", r::FrameId()),
      Param<O>("laser_frame_id", DOORPLATE_PARAM_FIELD(laser_frame_id), "frame of `scan`", r::FrameId()),
      Param<O>("camera_body_frame_id", DOORPLATE_PARAM_FIELD(camera_body_frame_id),
               "camera body, x along the optical axis (REP-103)", r::FrameId()),
      Param<O>("camera_frame_id", DOORPLATE_PARAM_FIELD(camera_frame_id),
               "optical frame of `camera/image_raw` and `camera/camera_info`: z forward, x right, y down",
               r::FrameId()),
      Param<O>("ground_truth_frame_id", DOORPLATE_PARAM_FIELD(ground_truth_frame_id),
               "frame of `base_pose_ground_truth` (the world frame); the six frames differ", r::FrameId()),
  };
  return table;
}

namespace {

std::string FloorIds(const BuildingFile& building) {
  std::string ids;
  for (const BuildingFloor& floor : building.floors) ids += (ids.empty() ? "" : ", ") + floor.id;
  return ids;
}

// ~building: every floor's world, the start floor's as the world.
void LoadBuildingWorlds(const ParamSource& source, CorridorSimOptions* o) {
  const std::string param = source.Resolve("building") + " = '" + o->building_file + "'";
  try {
    o->building = LoadBuildingFile(o->building_file);
  } catch (const std::exception& e) {  // BuildingFileError names the file and field
    throw ParameterError(param + " cannot be used: " + e.what());
  }
  for (size_t f = 0; f < o->building.floors.size(); ++f) {
    const BuildingFloor& floor = o->building.floors[f];
    const std::string where = param + ": floors[" + std::to_string(f) + "] (id '" + floor.id + "')";
    if (floor.world.empty()) throw ParameterError(where + ": names no world (the simulator needs every floor's)");
    try {
      o->floor_worlds.push_back(LoadWorldFile(floor.world));
    } catch (const std::exception& e) {  // WorldFileError names the file and field
      throw ParameterError(where + ": " + e.what());
    }
  }
  const std::optional<ParamValue> floor = source.Get("floor", std::string());
  o->floor = floor ? std::get<std::string>(*floor) : "";
  o->start_floor = o->floor.empty() ? 0 : o->building.FloorIndex(o->floor);
  if (o->start_floor < 0) {
    throw ParameterError(source.Resolve("floor") + ": no floor '" + o->floor + "' in " + o->building_file +
                         " (floors: " + FloorIds(o->building) + ")");
  }
  o->world_file = o->building.floors[static_cast<size_t>(o->start_floor)].world;
  o->world = o->floor_worlds[static_cast<size_t>(o->start_floor)];
}

}  // namespace

CorridorSimOptions CorridorSimOptionsFrom(const ParamSource& source) {
  CorridorSimOptions o;
  const std::optional<ParamValue> world_file = source.Get("world", std::string());
  const std::optional<ParamValue> building_file = source.Get("building", std::string());
  o.world_file = world_file ? std::get<std::string>(*world_file) : "";
  o.building_file = building_file ? std::get<std::string>(*building_file) : "";
  if (!o.world_file.empty() && !o.building_file.empty()) {
    throw ParameterError(source.Resolve("world") + " and " + source.Resolve("building") +
                         " are both set: give one (a world, or a building of several floors' worlds)");
  }
  if (o.world_file.empty() && o.building_file.empty()) {
    throw ParameterError(source.Resolve("world") + " is required: the path of a world file (worlds/*.yaml), or " +
                         source.Resolve("building") + ": a building file (worlds/*.building.yaml)");
  }
  if (!o.building_file.empty()) {
    LoadBuildingWorlds(source, &o);
  } else {
    try {
      o.world = LoadWorldFile(o.world_file);
    } catch (const std::exception& e) {  // WorldFileError names the file and field
      throw ParameterError(source.Resolve("world") + " = '" + o.world_file + "' cannot be used: " + e.what());
    }
    if (source.Get("floor", std::string())) {
      throw ParameterError(source.Resolve("floor") + " is a floor of " + source.Resolve("building") +
                           ", which is not set (" + source.Resolve("world") + " is one floor)");
    }
    o.building.name = o.world.name;  // one floor, named after the world, no lifts
    o.building.floors.push_back({o.world.name, "", "", o.world_file});
    o.floor_worlds.push_back(o.world);
    o.floor = o.world.name;
  }
  ApplyParamTable(CorridorSimParamTable(), source, &o);  // over the world's camera and start pose
  if (o.floor.empty()) o.floor = o.building.floors.front().id;
  for (World& floor_world : o.floor_worlds) floor_world.sensors = o.world.sensors;  // the robot's, on every floor

  const CameraOptions& camera = o.world.sensors.camera;
  for (const auto& [name, value, limit] : {std::tuple<const char*, double, double>{"camera/cx_px", camera.cx_px,
                                                                                     camera.width_px - 1.0},
                                           {"camera/cy_px", camera.cy_px, camera.height_px - 1.0}}) {
    if (value > limit) {
      throw ParameterError(source.Resolve(name) + " must be in [0, " + std::to_string(limit) +
                           "] pixels (0: derived), got " + std::to_string(value));
    }
  }
  const std::set<std::string> frames{o.odom_frame_id, o.base_frame_id, o.laser_frame_id, o.camera_body_frame_id,
                                     o.camera_frame_id, o.ground_truth_frame_id};
  if (frames.size() != 6) {
    throw ParameterError(source.Resolve("") + ": the six *_frame_id parameters must all differ");
  }
  // The loader validates the world; the publishing schedule divides by these rates, so check them here too.
  const SensorOptions& sensors = o.world.sensors;
  for (const auto& [field, rate_hz] : {std::pair<const char*, double>{"laser.rate_hz", sensors.laser.rate_hz},
                                       {"odometry.rate_hz", sensors.odometry.rate_hz},
                                       {"camera.rate_hz", sensors.camera.rate_hz}}) {
    if (!(rate_hz > 0.0 && std::isfinite(rate_hz))) {
      throw ParameterError(source.Resolve("world") + " = '" + o.world_file + "': sensors." + field +
                           " must be finite and > 0, got " + std::to_string(rate_hz));
    }
  }
  return o;
}

CorridorSimOptions LoadCorridorSimOptions(ros::NodeHandle& private_nh) {
  return CorridorSimOptionsFrom(RosParamSource(private_nh));
}

}  // namespace doorplate_localization

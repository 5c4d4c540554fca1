#include "corridor_sim_options.h"

#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>

#include "doorplate_localization/sim/world_loader.h"

namespace doorplate_localization {
CorridorSimOptions LoadCorridorSimOptions(ros::NodeHandle& private_nh) {
  const ros::NodeHandle& nh = private_nh;
  CorridorSimOptions o;
  o.world_file = ReadParam(nh, "world", std::string());
  if (o.world_file.empty()) {
    throw ParameterError(nh.resolveName("world") + " is required: the path of a world file (worlds/*.yaml)");
  }
  try {
    o.world = LoadWorldFile(o.world_file);
  } catch (const std::exception& e) {  // WorldFileError names the file and field
    throw ParameterError(nh.resolveName("world") + " = '" + o.world_file + "' cannot be used: " + e.what());
  }

  // The camera's image size and intrinsics: the world's unless overridden (e.g. a 1280 x 720 USB camera on
  // a built-in world). fx/fy/cx/cy 0 = derived (fx from the field of view, fy = fx, centred principal point).
  CameraOptions& camera = o.world.sensors.camera;
  camera.width_px = ReadParam(nh, "camera/width_px", camera.width_px);
  camera.height_px = ReadParam(nh, "camera/height_px", camera.height_px);
  RequireParam(camera.width_px >= 16 && camera.width_px <= 8192, nh, "camera/width_px", "in [16, 8192]",
               camera.width_px);
  RequireParam(camera.height_px >= 16 && camera.height_px <= 8192, nh, "camera/height_px", "in [16, 8192]",
               camera.height_px);
  camera.horizontal_fov_deg = ReadParam(nh, "camera/horizontal_fov_deg", camera.horizontal_fov_deg);
  RequireParam(camera.horizontal_fov_deg > 1.0 && camera.horizontal_fov_deg < 170.0, nh,
               "camera/horizontal_fov_deg", "in (1, 170) degrees", camera.horizontal_fov_deg);
  for (const auto& [name, field, limit] :
       {std::tuple<const char*, double*, double>{"camera/fx_px", &camera.fx_px, 1e6},
        {"camera/fy_px", &camera.fy_px, 1e6},
        {"camera/cx_px", &camera.cx_px, camera.width_px - 1.0},
        {"camera/cy_px", &camera.cy_px, camera.height_px - 1.0}}) {
    *field = ReadParam(nh, name, *field);
    RequireParam(std::isfinite(*field) && *field >= 0.0 && *field <= limit, nh, name,
                 "in [0, " + std::to_string(limit) + "] pixels (0: derived)", *field);
  }

  // The robot's start: the world's unless overridden (e.g. to start a localization run somewhere else).
  Pose2D& start = o.world.start_pose;
  start.x_m = ReadParam(nh, "start_x_m", start.x_m);
  start.y_m = ReadParam(nh, "start_y_m", start.y_m);
  const double start_theta_deg = ReadParam(nh, "start_theta_deg", start.theta_rad * 180.0 / M_PI);
  for (const auto& [name, value] : {std::pair<const char*, double>{"start_x_m", start.x_m},
                                    {"start_y_m", start.y_m}, {"start_theta_deg", start_theta_deg}}) {
    RequireParam(std::isfinite(value), nh, name, "finite", value);
  }
  start.theta_rad = NormalizeAngle(start_theta_deg * M_PI / 180.0);

  const int seed = ReadParam(nh, "seed", static_cast<int>(o.simulator.seed));
  RequireParam(seed >= 0, nh, "seed", ">= 0", seed);
  o.simulator.seed = static_cast<std::uint64_t>(seed);
  o.simulator.physics_step_s = ReadParam(nh, "physics_step_s", o.simulator.physics_step_s);
  RequireParam(o.simulator.physics_step_s > 0.0 && o.simulator.physics_step_s <= 0.1, nh, "physics_step_s",
          "in (0, 0.1] seconds", o.simulator.physics_step_s);
  o.simulator.max_linear_speed_mps = ReadParam(nh, "max_linear_speed_mps", o.simulator.max_linear_speed_mps);
  RequireParam(o.simulator.max_linear_speed_mps > 0.0 && std::isfinite(o.simulator.max_linear_speed_mps), nh,
          "max_linear_speed_mps", "finite and > 0", o.simulator.max_linear_speed_mps);
  o.simulator.max_angular_speed_rps = ReadParam(nh, "max_angular_speed_rps", o.simulator.max_angular_speed_rps);
  RequireParam(o.simulator.max_angular_speed_rps > 0.0 && std::isfinite(o.simulator.max_angular_speed_rps), nh,
          "max_angular_speed_rps", "finite and > 0", o.simulator.max_angular_speed_rps);

  o.real_time_factor = ReadParam(nh, "real_time_factor", o.real_time_factor);
  RequireParam(o.real_time_factor >= 0.0 && std::isfinite(o.real_time_factor), nh, "real_time_factor",
          "finite and >= 0 (0 = as fast as possible)", o.real_time_factor);
  o.publish_clock = ReadParam(nh, "publish_clock", o.publish_clock);
  o.cmd_vel_timeout_s = ReadParam(nh, "cmd_vel_timeout_s", o.cmd_vel_timeout_s);
  RequireParam(o.cmd_vel_timeout_s > 0.0 && std::isfinite(o.cmd_vel_timeout_s), nh, "cmd_vel_timeout_s",
          "finite and > 0 seconds", o.cmd_vel_timeout_s);
  o.publish_ground_truth_tf = ReadParam(nh, "publish_ground_truth_tf", o.publish_ground_truth_tf);

  o.odom_frame_id = ReadFrameParam(nh, "odom_frame_id", o.odom_frame_id);
  o.base_frame_id = ReadFrameParam(nh, "base_frame_id", o.base_frame_id);
  o.laser_frame_id = ReadFrameParam(nh, "laser_frame_id", o.laser_frame_id);
  o.camera_body_frame_id = ReadFrameParam(nh, "camera_body_frame_id", o.camera_body_frame_id);
  o.camera_frame_id = ReadFrameParam(nh, "camera_frame_id", o.camera_frame_id);
  o.ground_truth_frame_id = ReadFrameParam(nh, "ground_truth_frame_id", o.ground_truth_frame_id);
  const std::set<std::string> frames{o.odom_frame_id, o.base_frame_id, o.laser_frame_id, o.camera_body_frame_id,
                                     o.camera_frame_id, o.ground_truth_frame_id};
  if (frames.size() != 6) {
    throw ParameterError(nh.resolveName("") + ": the six *_frame_id parameters must all differ");
  }

  // The loader validates the world; the publishing schedule divides by these rates, so check them here too.
  const SensorOptions& sensors = o.world.sensors;
  for (const auto& [field, rate_hz] : {std::pair<const char*, double>{"laser.rate_hz", sensors.laser.rate_hz},
                                       {"odometry.rate_hz", sensors.odometry.rate_hz},
                                       {"camera.rate_hz", sensors.camera.rate_hz}}) {
    if (!(rate_hz > 0.0 && std::isfinite(rate_hz))) {
      throw ParameterError(nh.resolveName("world") + " = '" + o.world_file + "': sensors." + field +
                           " must be finite and > 0, got " + std::to_string(rate_hz));
    }
  }
  return o;
}

}  // namespace doorplate_localization

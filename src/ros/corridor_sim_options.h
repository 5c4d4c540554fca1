// Parameters of CorridorSimNodelet, read and validated once from its private namespace; one table
// (CorridorSimParamTable) is the loader, the docs/parameters.md table and the config/sim.yaml check.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "doorplate_localization/maps/building_map.h"
#include "doorplate_localization/ros/param_reader.h"
#include "doorplate_localization/ros/param_table.h"

#include "doorplate_localization/sim/simulator.h"
#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

struct CorridorSimOptions {
  std::string world_file;           // ~world (or ~building): the world YAML, docs/world-format.md
  // ~building instead of ~world: a building of several floors (docs/building-format.md: each floor's world,
  // and the lifts); ~floor the floor the robot starts on ("" = the first). world_file is that floor's world.
  std::string building_file;
  std::string floor;
  BuildingFile building;            // loaded from building_file (a one-floor building of ~world without it)
  std::vector<World> floor_worlds;  // every floor's world in building order, all with world.sensors
  int start_floor = 0;              // index of ~floor in building.floors
  World world;                      // loaded from world_file; its sensor settings give the rates; its
                                    // start pose overridden by ~start_x_m, ~start_y_m, ~start_theta_deg,
                                    // its camera's size and intrinsics by ~camera/width_px, ~camera/height_px,
                                    // ~camera/horizontal_fov_deg, ~camera/{fx,fy,cx,cy}_px
  SimulatorOptions simulator;       // ~seed, ~physics_step_s, ~max_linear_speed_mps, ~max_angular_speed_rps
  double real_time_factor = 1.0;    // sim seconds per wall second; 0 = as fast as possible
  bool publish_clock = true;        // publish /clock (run the graph with /use_sim_time true)
  // Wall seconds to wait before the first step for a subscriber of base_pose_ground_truth (a recorder such as
  // rosbag record), so that a recording holds the run from sim time 0; 0 = start at once.
  double wait_for_recorder_s = 0.0;
  double cmd_vel_timeout_s = 0.5;   // sim seconds without cmd_vel after which the robot stops
  // Publish map -> odom computed from the true pose ("perfect localization"); off when a localizer runs.
  bool publish_ground_truth_tf = false;
  std::string odom_frame_id = "odom";
  std::string base_frame_id = "base_link";
  std::string laser_frame_id = "laser";
  std::string camera_body_frame_id = "camera_link";      // x along the optical axis (REP-103)
  std::string camera_frame_id = "camera_optical";        // z forward, x right, y down
  std::string ground_truth_frame_id = "map";              // the world frame
};

// Every parameter: name, field, default (or the world's), rule, doc line.
const ParamTable<CorridorSimOptions>& CorridorSimParamTable();

// Loads the world file of ~world (or every floor's world of ~building), then reads every parameter over the
// start floor's and validates. Throws ParameterError naming the parameter (e.g. "/corridor_sim/real_time_factor
// must be finite and >= 0 ..., got -1", "/corridor_sim/floor: no floor '4' in b.building.yaml (floors: 2, 3)").
// ROS-free.
CorridorSimOptions CorridorSimOptionsFrom(const ParamSource& source);

// CorridorSimOptionsFrom(the parameters under `private_nh`).
CorridorSimOptions LoadCorridorSimOptions(ros::NodeHandle& private_nh);

}  // namespace doorplate_localization

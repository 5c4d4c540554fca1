#include "wall_follower_options.h"

#include <cmath>

namespace doorplate_localization {
namespace {

double ReadPositive(const ros::NodeHandle& nh, const std::string& name, double fallback) {
  const double value = ReadParam(nh, name, fallback);
  RequireParam(std::isfinite(value) && value > 0.0, nh, name, "finite and > 0", value);
  return value;
}

}  // namespace

WallFollowerNodeOptions LoadWallFollowerOptions(const ros::NodeHandle& nh) {
  WallFollowerNodeOptions o;
  WallFollowerOptions& f = o.follower;
  f.wall_side = ReadParam(nh, "wall_side", f.wall_side);
  RequireParam(f.wall_side == "left" || f.wall_side == "right", nh, "wall_side", "'left' or 'right'", f.wall_side);
  f.wall_distance_m = ReadPositive(nh, "wall_distance_m", f.wall_distance_m);
  f.cruise_speed_mps = ReadPositive(nh, "cruise_speed_mps", f.cruise_speed_mps);
  f.end_stop_distance_m = ReadPositive(nh, "end_stop_distance_m", f.end_stop_distance_m);
  f.slow_down_distance_m = ReadPositive(nh, "slow_down_distance_m", f.slow_down_distance_m);
  RequireParam(f.slow_down_distance_m > f.end_stop_distance_m, nh, "slow_down_distance_m",
               "> end_stop_distance_m", f.slow_down_distance_m);
  f.distance_gain_rad_per_m = ReadPositive(nh, "distance_gain_rad_per_m", f.distance_gain_rad_per_m);
  f.max_heading_correction_rad = ReadPositive(nh, "max_heading_correction_rad", f.max_heading_correction_rad);
  f.heading_gain_per_s = ReadPositive(nh, "heading_gain_per_s", f.heading_gain_per_s);
  f.max_angular_speed_rps = ReadPositive(nh, "max_angular_speed_rps", f.max_angular_speed_rps);
  f.side_max_range_m = ReadPositive(nh, "side_max_range_m", f.side_max_range_m);
  RequireParam(f.side_max_range_m > f.wall_distance_m, nh, "side_max_range_m", "> wall_distance_m",
               f.side_max_range_m);
  f.front_half_width_m = ReadPositive(nh, "front_half_width_m", f.front_half_width_m);
  const std::string mode = ReadParam(nh, "mode", std::string("follow"));
  RequireParam(mode == "follow" || mode == "sweep" || mode == "patrol" || mode == "explore", nh, "mode",
               "follow, sweep, patrol or explore", mode);
  o.mode = mode == "follow"  ? CorridorDriveMode::kFollow
           : mode == "sweep" ? CorridorDriveMode::kSweep
           : mode == "patrol" ? CorridorDriveMode::kPatrol
                              : CorridorDriveMode::kExplore;
  o.sweep.follower = f;
  o.sweep.turn_speed_rps = ReadPositive(nh, "turn_speed_rps", o.sweep.turn_speed_rps);
  FloorExplorerOptions& e = o.explore;
  e.steering.wall_side = f.wall_side;
  e.steering.wall_distance_m = f.wall_distance_m;
  e.steering.cruise_speed_mps = f.cruise_speed_mps;
  e.steering.max_angular_speed_rps = f.max_angular_speed_rps;
  e.turn_speed_rps = o.sweep.turn_speed_rps;
  e.passes = ReadParam(nh, "explore/passes", e.passes);
  RequireParam(e.passes >= 1, nh, "explore/passes", ">= 1", e.passes);
  e.revisit_plates = ReadParam(nh, "explore/revisit_plates", e.revisit_plates);
  RequireParam(e.revisit_plates >= 1, nh, "explore/revisit_plates", ">= 1", e.revisit_plates);
  e.min_revisit_travel_m = ReadPositive(nh, "explore/min_revisit_travel_m", e.min_revisit_travel_m);
  e.max_pass_distance_m = ReadPositive(nh, "explore/max_pass_distance_m", e.max_pass_distance_m);
  RequireParam(e.max_pass_distance_m > e.min_revisit_travel_m, nh, "explore/max_pass_distance_m",
               "> explore/min_revisit_travel_m", e.max_pass_distance_m);
  o.base_frame_id = ReadFrameParam(nh, "base_frame_id", o.base_frame_id);
  o.odom_frame_id = ReadFrameParam(nh, "odom_frame_id", o.odom_frame_id);
  o.scan_timeout_s = ReadPositive(nh, "scan_timeout_s", o.scan_timeout_s);
  o.enabled = ReadParam(nh, "enabled", o.enabled);
  return o;
}

}  // namespace doorplate_localization

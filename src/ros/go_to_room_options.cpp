#include "go_to_room_options.h"

#include <cmath>
#include <set>
#include <string>

namespace doorplate_localization {
namespace {

double ReadPositive(const ros::NodeHandle& nh, const std::string& name, double fallback) {
  const double value = ReadParam(nh, name, fallback);
  RequireParam(std::isfinite(value) && value > 0.0, nh, name, "finite and > 0", value);
  return value;
}

void LoadFollower(const ros::NodeHandle& nh, WallFollowerOptions* f) {
  if (nh.hasParam("wall_side")) {
    throw ParameterError(nh.resolveName("wall_side") +
                         " is not a go-to-room parameter: the robot follows the wall of the goal's plate");
  }
  f->wall_distance_m = ReadPositive(nh, "wall_distance_m", f->wall_distance_m);
  f->cruise_speed_mps = ReadPositive(nh, "cruise_speed_mps", f->cruise_speed_mps);
  f->end_stop_distance_m = ReadPositive(nh, "end_stop_distance_m", f->end_stop_distance_m);
  f->slow_down_distance_m = ReadPositive(nh, "slow_down_distance_m", f->slow_down_distance_m);
  RequireParam(f->slow_down_distance_m > f->end_stop_distance_m, nh, "slow_down_distance_m",
               "> end_stop_distance_m", f->slow_down_distance_m);
  f->distance_gain_rad_per_m = ReadPositive(nh, "distance_gain_rad_per_m", f->distance_gain_rad_per_m);
  f->max_heading_correction_rad = ReadPositive(nh, "max_heading_correction_rad", f->max_heading_correction_rad);
  f->heading_gain_per_s = ReadPositive(nh, "heading_gain_per_s", f->heading_gain_per_s);
  f->max_angular_speed_rps = ReadPositive(nh, "max_angular_speed_rps", f->max_angular_speed_rps);
  f->side_max_range_m = ReadPositive(nh, "side_max_range_m", f->side_max_range_m);
  RequireParam(f->side_max_range_m > f->wall_distance_m, nh, "side_max_range_m", "> wall_distance_m",
               f->side_max_range_m);
  f->front_half_width_m = ReadPositive(nh, "front_half_width_m", f->front_half_width_m);
}

void LoadController(const ros::NodeHandle& nh, GoToRoomOptions* c) {
  c->approach_sector_max_deg = ReadPositive(nh, "approach_sector_max_deg", c->approach_sector_max_deg);
  RequireParam(c->approach_sector_max_deg > c->follower.side_sector_min_deg && c->approach_sector_max_deg <= 180.0, nh,
               "approach_sector_max_deg", "in (side_sector_min_deg = " + std::to_string(c->follower.side_sector_min_deg) +
               ", 180]", c->approach_sector_max_deg);
  c->approach_tolerance_m = ReadPositive(nh, "approach_tolerance_m", c->approach_tolerance_m);
  c->turn_speed_rps = ReadPositive(nh, "turn_speed_rps", c->turn_speed_rps);
  c->align_tolerance_rad = ReadPositive(nh, "align_tolerance_rad", c->align_tolerance_rad);
  RequireParam(c->align_tolerance_rad < M_PI / 2, nh, "align_tolerance_rad", "in (0, pi/2)", c->align_tolerance_rad);
  c->arrive_tolerance_m = ReadPositive(nh, "arrive_tolerance_m", c->arrive_tolerance_m);
  c->approach_gain_per_s = ReadPositive(nh, "approach_gain_per_s", c->approach_gain_per_s);
  c->min_approach_speed_mps = ReadPositive(nh, "min_approach_speed_mps", c->min_approach_speed_mps);
  RequireParam(c->min_approach_speed_mps <= c->follower.cruise_speed_mps, nh, "min_approach_speed_mps",
               "<= cruise_speed_mps", c->min_approach_speed_mps);
  c->face_gain_per_s = ReadPositive(nh, "face_gain_per_s", c->face_gain_per_s);
  c->face_tolerance_rad = ReadPositive(nh, "face_tolerance_rad", c->face_tolerance_rad);
  RequireParam(c->face_tolerance_rad < M_PI / 2, nh, "face_tolerance_rad", "in (0, pi/2)", c->face_tolerance_rad);
}

}  // namespace

GoToRoomNodeOptions LoadGoToRoomOptions(const ros::NodeHandle& nh) {
  GoToRoomNodeOptions o;
  o.text_map_file = ReadParam(nh, "text_map_file", std::string());
  if (o.text_map_file.empty()) {
    throw ParameterError(nh.resolveName("text_map_file") +
                         " is required: the doorplate text map (docs/text-map-format.md), e.g. maps/x.text_map.yaml");
  }
  try {
    o.text_map = LoadTextMap(o.text_map_file);
  } catch (const std::exception& e) {  // TextMapError names the file and field
    throw ParameterError(nh.resolveName("text_map_file") + " = '" + o.text_map_file + "' cannot be used: " + e.what());
  }
  if (o.text_map.landmarks.empty()) {
    throw ParameterError(nh.resolveName("text_map_file") + " = '" + o.text_map_file +
                         "' has no landmarks: no room can be reached");
  }
  o.planner.duplicate_rule = ReadParam(nh, "duplicate_rule", o.planner.duplicate_rule);
  RequireParam(o.planner.duplicate_rule == "nearest" || o.planner.duplicate_rule == "refuse", nh, "duplicate_rule",
               "'nearest' or 'refuse'", o.planner.duplicate_rule);
  LoadFollower(nh, &o.controller.follower);
  o.planner.wall_distance_m = o.controller.follower.wall_distance_m;
  LoadController(nh, &o.controller);

  o.map_frame_id = ReadFrameParam(nh, "map_frame_id", o.map_frame_id);
  o.odom_frame_id = ReadFrameParam(nh, "odom_frame_id", o.odom_frame_id);
  o.base_frame_id = ReadFrameParam(nh, "base_frame_id", o.base_frame_id);
  if (std::set<std::string>{o.map_frame_id, o.odom_frame_id, o.base_frame_id}.size() != 3) {
    throw ParameterError(nh.resolveName("") + ": map_frame_id, odom_frame_id and base_frame_id must all differ");
  }
  o.scan_timeout_s = ReadPositive(nh, "scan_timeout_s", o.scan_timeout_s);
  o.tf_timeout_s = ReadParam(nh, "tf_timeout_s", o.tf_timeout_s);
  RequireParam(std::isfinite(o.tf_timeout_s) && o.tf_timeout_s >= 0.0, nh, "tf_timeout_s", "finite and >= 0",
               o.tf_timeout_s);
  o.text_fallback = ReadParam(nh, "text_fallback", o.text_fallback);
  o.reading_max_age_s = ReadPositive(nh, "reading_max_age_s", o.reading_max_age_s);
  // The core's own checks (e.g. the follower's), named by their struct field.
  try {
    GoToRoom check(o.controller);
    RoomGoalPlanner planner_check(o.planner, TextMap{}, o.text_map_file);
  } catch (const std::invalid_argument& e) {
    throw ParameterError(nh.resolveName("") + ": " + e.what());
  }
  return o;
}

}  // namespace doorplate_localization

// GoToRoomNodelet's parameter table and loader: every parameter once (name, field, default, rule, doc);
// rules between fields are the core's (GoToRoom, its WallFollowers, RoomGoalPlanner).
#include "go_to_room_options.h"

#include <memory>
#include <set>
#include <string>

namespace doorplate_localization {

const ParamTable<GoToRoomNodeOptions>& GoToRoomParamTable() {
  using O = GoToRoomNodeOptions;
  namespace r = param_rules;
  static const ParamTable<O> table = {
      Param<O>("text_map_file", DOORPLATE_PARAM_FIELD(text_map_file),
               "the doorplate text map (docs/text-map-format.md); unreadable, invalid or empty: the nodelet does "
               "not start, naming it")
          .DefaultText("(required, or `building_file`)"),
      Param<O>("building_file", DOORPLATE_PARAM_FIELD(building_file),
               "a building of several floors (docs/building-format.md, a maps building file) instead of "
               "`text_map_file`: route `grid` on its floors' maps, a room planned from the localizer's floor "
               "(`amcl/floor`, once `amcl/state` is converged), via a lift when on another floor: drive to the "
               "lift's stop, wait for `ride_lift`, search until localized on the room's floor, drive on"),
      Param<O>("search_enable_service", DOORPLATE_PARAM_FIELD(search_enable_service),
               "with `building_file`: the search drive's `std_srvs/SetBool` (the wall follower's `~enable`, "
               "`~mode roam`), on while waiting to be localized, off before driving; \"\": none"),
      Param<O>("route", DOORPLATE_PARAM_FIELD(route),
               "`corridor`: wall following along the goal's corridor (the paper's; eq. 15 fallback); `grid`: a "
               "whole floor, a path planned over the `map` topic round corners and followed with the map pose",
               r::OneOf({"corridor", "grid"})),
      Param<O>("duplicate_rule", DOORPLATE_PARAM_FIELD(planner.duplicate_rule),
               "a room number on several plates: `nearest` (the plate closest to the robot; the log says which "
               "plates there were) or `refuse` (asks for `<room>@<wall>`)",
               r::OneOf({"nearest", "refuse"})),
      Param<O>("wall_distance_m", DOORPLATE_PARAM_FIELD(controller.follower.wall_distance_m),
               "as WallFollowerNodelet (the followed wall is the goal's: no `~wall_side`); also the goal's "
               "distance from the plate's wall",
               r::Positive()),
      Param<O>("cruise_speed_mps", DOORPLATE_PARAM_FIELD(controller.follower.cruise_speed_mps),
               "as WallFollowerNodelet", r::Positive()),
      Param<O>("end_stop_distance_m", DOORPLATE_PARAM_FIELD(controller.follower.end_stop_distance_m),
               "a wall or obstacle this close ahead before the goal: `failed` (plates near a corridor's end are "
               "0.8 m from it)",
               r::Positive())
          .Shipped(0.45),
      Param<O>("slow_down_distance_m", DOORPLATE_PARAM_FIELD(controller.follower.slow_down_distance_m),
               "start slowing down when the wall ahead is this close; > end_stop_distance_m", r::Positive())
          .Shipped(1.2),
      Param<O>("distance_gain_rad_per_m", DOORPLATE_PARAM_FIELD(controller.follower.distance_gain_rad_per_m),
               "as WallFollowerNodelet", r::Positive()),
      Param<O>("max_heading_correction_rad", DOORPLATE_PARAM_FIELD(controller.follower.max_heading_correction_rad),
               "as WallFollowerNodelet", r::Positive()),
      Param<O>("heading_gain_per_s", DOORPLATE_PARAM_FIELD(controller.follower.heading_gain_per_s),
               "as WallFollowerNodelet", r::Positive()),
      Param<O>("max_angular_speed_rps", DOORPLATE_PARAM_FIELD(controller.follower.max_angular_speed_rps),
               "as WallFollowerNodelet", r::Positive()),
      Param<O>("side_max_range_m", DOORPLATE_PARAM_FIELD(controller.follower.side_max_range_m),
               "as WallFollowerNodelet", r::Positive()),
      Param<O>("front_half_width_m", DOORPLATE_PARAM_FIELD(controller.follower.front_half_width_m),
               "as WallFollowerNodelet", r::Positive()),
      Param<O>("approach_sector_max_deg", DOORPLATE_PARAM_FIELD(controller.approach_sector_max_deg),
               "until the goal's wall is within `approach_tolerance_m` of `wall_distance_m`, fit it to the side "
               "beams up to this angle only (beams further back reach the end wall)",
               r::Positive()),
      Param<O>("approach_tolerance_m", DOORPLATE_PARAM_FIELD(controller.approach_tolerance_m),
               "see `approach_sector_max_deg`", r::Positive()),
      Param<O>("turn_speed_rps", DOORPLATE_PARAM_FIELD(controller.turn_speed_rps),
               "in-place turns: towards the goal, and to face the door", r::Positive()),
      Param<O>("align_tolerance_rad", DOORPLATE_PARAM_FIELD(controller.align_tolerance_rad),
               "a turn towards the goal ends within this of the travel direction; while driving, twice this off "
               "turns again",
               r::Positive()),
      Param<O>("arrive_tolerance_m", DOORPLATE_PARAM_FIELD(controller.arrive_tolerance_m),
               "stop this close to the goal along the corridor", r::Positive()),
      Param<O>("approach_gain_per_s", DOORPLATE_PARAM_FIELD(controller.approach_gain_per_s),
               "near the goal the speed is at most gain × remaining distance", r::Positive()),
      Param<O>("min_approach_speed_mps", DOORPLATE_PARAM_FIELD(controller.min_approach_speed_mps),
               "... and at least this; <= cruise_speed_mps", r::Positive()),
      Param<O>("face_gain_per_s", DOORPLATE_PARAM_FIELD(controller.face_gain_per_s),
               "turning to face the door: angular speed = gain × yaw error", r::Positive()),
      Param<O>("face_tolerance_rad", DOORPLATE_PARAM_FIELD(controller.face_tolerance_rad),
               "`arrived` within this yaw error", r::Positive()),
      Param<O>("blocked_wait_s", DOORPLATE_PARAM_FIELD(controller.blocked_wait_s),
               "something within end_stop_distance_m ahead fails the goal only if it is still there after this "
               "long (a person walking past clears); 0: at once",
               r::NonNegative()),
      Param<O>("global_frame_id", DOORPLATE_PARAM_FIELD(global_frame_id),
               "the localizer's frame (amcl's name): the pose is tf `global_frame_id → base_frame_id`",
               r::FrameId())
          .Deprecated("map_frame_id"),
      Param<O>("odom_frame_id", DOORPLATE_PARAM_FIELD(odom_frame_id), "the eq. 15 fallback drives in this frame",
               r::FrameId()),
      Param<O>("base_frame_id", DOORPLATE_PARAM_FIELD(base_frame_id), "the robot's frame; the three frames differ",
               r::FrameId()),
      Param<O>("scan_timeout_s", DOORPLATE_PARAM_FIELD(scan_timeout_s),
               "no valid scan for this long while driving: publish a stop", r::Positive()),
      Param<O>("tf_timeout_s", DOORPLATE_PARAM_FIELD(tf_timeout_s), "wait this long for a tf at a message's stamp",
               r::NonNegative()),
      Param<O>("text_fallback", DOORPLATE_PARAM_FIELD(text_fallback),
               "subscribe `text_detections` and use eq. 15 while there is no map pose"),
      Param<O>("reading_max_age_s", DOORPLATE_PARAM_FIELD(reading_max_age_s),
               "an older plate reading is not used for eq. 15", r::Positive()),
  };
  return table;
}

GoToRoomNodeOptions GoToRoomOptionsFrom(const ParamSource& source) {
  const ParamTable<GoToRoomNodeOptions>& table = GoToRoomParamTable();
  if (source.Has("wall_side")) {
    throw ParameterError(source.Resolve("wall_side") +
                         " is not a go-to-room parameter: the robot follows the wall of the goal's plate");
  }
  GoToRoomNodeOptions o;
  ApplyParamTable(table, source, &o);
  if (!o.building_file.empty()) {
    try {
      o.building =
          std::make_shared<const BuildingMaps>(LoadBuildingMaps(LoadBuildingFile(o.building_file), o.building_file));
    } catch (const std::exception& e) {  // BuildingFileError names the file, the floor and the map file
      throw ParameterError(source.Resolve("building_file") + " = '" + o.building_file +
                           "' cannot be used: " + e.what());
    }
    o.route = "grid";
    o.text_map_file = o.building_file + " (floor " + o.building->floors.front().id + ")";
    o.text_map = *o.building->floors.front().text_map;
  } else if (o.text_map_file.empty()) {
    throw ParameterError(source.Resolve("text_map_file") +
                         " is required: the doorplate text map (docs/text-map-format.md), e.g. maps/x.text_map.yaml, " +
                         "or " + source.Resolve("building_file"));
  } else {
    try {
      o.text_map = LoadTextMap(o.text_map_file);
    } catch (const std::exception& e) {  // TextMapError names the file and field
      throw ParameterError(source.Resolve("text_map_file") + " = '" + o.text_map_file +
                           "' cannot be used: " + e.what());
    }
  }
  if (o.text_map.landmarks.empty()) {
    throw ParameterError(source.Resolve("text_map_file") + " = '" + o.text_map_file +
                         "' has no landmarks: no room can be reached");
  }
  o.planner.wall_distance_m = o.controller.follower.wall_distance_m;  // the goal is where the following ends
  o.floor.follower.cruise_speed_mps = o.controller.follower.cruise_speed_mps;
  o.floor.follower.max_angular_speed_rps = o.controller.follower.max_angular_speed_rps;
  o.floor.follower.turn_speed_rps = o.controller.turn_speed_rps;
  o.floor.follower.face_tolerance_rad = o.controller.face_tolerance_rad;
  if (std::set<std::string>{o.global_frame_id, o.odom_frame_id, o.base_frame_id}.size() != 3) {
    throw ParameterError(source.Resolve("") + ": global_frame_id, odom_frame_id and base_frame_id must all differ");
  }
  CheckWithCore(table, o, source, [&o] {
    (void)GoToRoom(o.controller);
    (void)PathFollower(o.floor.follower);
    (void)RoomGoalPlanner(o.planner, TextMap{}, o.text_map_file);
  });
  return o;
}

GoToRoomNodeOptions LoadGoToRoomOptions(const ros::NodeHandle& nh) { return GoToRoomOptionsFrom(RosParamSource(nh)); }

}  // namespace doorplate_localization

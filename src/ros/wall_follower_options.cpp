// WallFollowerNodelet's parameter table and loader: every parameter once (name, field, default, rule, doc);
// rules between fields are the core's (WallFollower, CorridorSweep, FloorExplorer, ContourSteering).
#include "wall_follower_options.h"

#include <string>

namespace doorplate_localization {

const ParamTable<WallFollowerNodeOptions>& WallFollowerParamTable() {
  using O = WallFollowerNodeOptions;
  namespace r = param_rules;
  static const ParamTable<O> table = {
      EnumParam<O>("mode", DOORPLATE_PARAM_FIELD(mode),
                   {{"follow", CorridorDriveMode::kFollow}, {"sweep", CorridorDriveMode::kSweep},
                    {"patrol", CorridorDriveMode::kPatrol}, {"explore", CorridorDriveMode::kExplore},
                    {"roam", CorridorDriveMode::kRoam}},
                   "`follow` (one wall to the end), `sweep` (out and back, then stop), `patrol` (sweep forever), "
                   "`explore` (a whole floor, then stop) or `roam` (follow one wall of a floor wherever it leads, "
                   "for ever: the search drive of global localization on a floor)"),
      Param<O>("wall_side", DOORPLATE_PARAM_FIELD(follower.wall_side),
               "wall to follow, `left` or `right`; the camera looks at the other one", r::OneOf({"left", "right"})),
      Param<O>("wall_distance_m", DOORPLATE_PARAM_FIELD(follower.wall_distance_m),
               "distance kept from the followed wall", r::Positive()),
      Param<O>("cruise_speed_mps", DOORPLATE_PARAM_FIELD(follower.cruise_speed_mps), "forward speed", r::Positive()),
      Param<O>("end_stop_distance_m", DOORPLATE_PARAM_FIELD(follower.end_stop_distance_m),
               "stop when the wall ahead is this close (the corridor's end)", r::Positive()),
      Param<O>("slow_down_distance_m", DOORPLATE_PARAM_FIELD(follower.slow_down_distance_m),
               "start slowing down when the wall ahead is this close; > end_stop_distance_m", r::Positive()),
      Param<O>("distance_gain_rad_per_m", DOORPLATE_PARAM_FIELD(follower.distance_gain_rad_per_m),
               "heading correction per metre of distance error", r::Positive()),
      Param<O>("max_heading_correction_rad", DOORPLATE_PARAM_FIELD(follower.max_heading_correction_rad),
               "bound on that correction", r::Positive()),
      Param<O>("heading_gain_per_s", DOORPLATE_PARAM_FIELD(follower.heading_gain_per_s),
               "angular speed per radian of heading error", r::Positive()),
      Param<O>("max_angular_speed_rps", DOORPLATE_PARAM_FIELD(follower.max_angular_speed_rps),
               "bound on the angular speed", r::Positive()),
      Param<O>("side_max_range_m", DOORPLATE_PARAM_FIELD(follower.side_max_range_m),
               "side returns farther than this are not the wall (open doors); > wall_distance_m", r::Positive()),
      Param<O>("front_half_width_m", DOORPLATE_PARAM_FIELD(follower.front_half_width_m),
               "returns ahead within this lateral band count as the wall ahead", r::Positive()),
      Param<O>("turn_speed_rps", DOORPLATE_PARAM_FIELD(sweep.turn_speed_rps),
               "sweep/patrol: in-place turn speed at the corridor's end; explore: the turn between passes",
               r::Positive()),
      Param<O>("end_confirm_s", DOORPLATE_PARAM_FIELD(sweep.end_confirm_s),
               "sweep/patrol: something within end_stop_distance_m ends a leg only after the robot has stood "
               "before it this long (a person in the lane walks on); 0: at once",
               r::NonNegative()),
      Param<O>("end_min_width_m", DOORPLATE_PARAM_FIELD(sweep.end_min_width_m),
               "sweep/patrol: something ahead narrower than this (a person standing in the lane) ends a leg only "
               "after narrow_end_confirm_s; 0: every end waits end_confirm_s",
               r::NonNegative()),
      Param<O>("narrow_end_confirm_s", DOORPLATE_PARAM_FIELD(sweep.narrow_end_confirm_s),
               "sweep/patrol: the wait before something narrower than end_min_width_m counts as the end; "
               ">= end_confirm_s",
               r::NonNegative()),
      Param<O>("end_max_wall_angle_rad", DOORPLATE_PARAM_FIELD(sweep.end_max_wall_angle_rad),
               "sweep/patrol: something ahead ends a leg only while the robot runs within this angle of the leg's "
               "wall (or of the way out reversed); turned further (a turn that overshot) it turns back first; "
               "< pi/2",
               r::Positive()),
      Param<O>("explore/passes", DOORPLATE_PARAM_FIELD(explore.passes),
               "explore: 1 follows one side only (enough for a floor without loops); 2 also the other side of a "
               "ring",
               r::AtLeast(1)),
      Param<O>("explore/revisit_plates", DOORPLATE_PARAM_FIELD(explore.revisit_plates),
               "explore: distinct known plates read in a row that end a pass", r::AtLeast(1)),
      Param<O>("explore/min_revisit_travel_m", DOORPLATE_PARAM_FIELD(explore.min_revisit_travel_m),
               "explore: a plate counts as known once driven this far since its first read; no pass ends before "
               "this",
               r::Positive()),
      Param<O>("explore/max_pass_distance_m", DOORPLATE_PARAM_FIELD(explore.max_pass_distance_m),
               "explore: a pass that has not ended by then ends anyway; > explore/min_revisit_travel_m",
               r::Positive()),
      Param<O>("explore/read_latency_window_s", DOORPLATE_PARAM_FIELD(explore.read_latency_window_s),
               "explore: a plate reading is judged by where the robot was at its image's stamp, up to this long "
               "ago (the text extractor's latency on a loaded machine)",
               r::NonNegative()),
      Param<O>("base_frame_id", DOORPLATE_PARAM_FIELD(base_frame_id), "the scan is turned into this frame with tf",
               r::FrameId()),
      Param<O>("odom_frame_id", DOORPLATE_PARAM_FIELD(odom_frame_id),
               "sweep/patrol: the turn is measured with the yaw of tf `odom_frame_id → base_frame_id`",
               r::FrameId()),
      Param<O>("scan_timeout_s", DOORPLATE_PARAM_FIELD(scan_timeout_s),
               "no valid scan for this long (ROS time): publish a stop", r::Positive()),
      Param<O>("max_odom_lag_s", DOORPLATE_PARAM_FIELD(max_odom_lag_s),
               "sweep/patrol/explore: the latest odom tf older than the scan by more than this: stop until it "
               "catches up (a turn measured on stale odometry overshoots)", r::Positive()),
      Param<O>("enabled", DOORPLATE_PARAM_FIELD(enabled),
               "start driving at once; `~enable` (std_srvs/SetBool) switches it"),
  };
  return table;
}

WallFollowerNodeOptions WallFollowerOptionsFrom(const ParamSource& source) {
  const ParamTable<WallFollowerNodeOptions>& table = WallFollowerParamTable();
  WallFollowerNodeOptions o;
  ApplyParamTable(table, source, &o);
  // One set of follower parameters drives every mode.
  o.sweep.follower = o.follower;
  ContourSteeringOptions& steering = o.explore.steering;
  steering.wall_side = o.follower.wall_side;
  steering.wall_distance_m = o.follower.wall_distance_m;
  steering.cruise_speed_mps = o.follower.cruise_speed_mps;
  steering.max_angular_speed_rps = o.follower.max_angular_speed_rps;
  o.explore.turn_speed_rps = o.sweep.turn_speed_rps;
  // The core's checks of what the mode runs (the nodelet builds the same objects).
  CheckWithCore(table, o, source, [&o] {
    (void)WallFollower(o.follower);
    if (o.mode == CorridorDriveMode::kSweep || o.mode == CorridorDriveMode::kPatrol) (void)CorridorSweep(o.sweep);
    if (o.mode == CorridorDriveMode::kExplore) (void)FloorExplorer(o.explore);
    if (o.mode == CorridorDriveMode::kRoam) (void)ContourSteering(o.explore.steering);
  });
  return o;
}

WallFollowerNodeOptions LoadWallFollowerOptions(const ros::NodeHandle& nh) {
  return WallFollowerOptionsFrom(RosParamSource(nh));
}

}  // namespace doorplate_localization

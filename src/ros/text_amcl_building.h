// The floors TextAmclNodelet localizes on: it always runs one BuildingSession (mcl/building_session.h),
// on the floors of ~building_file or, without one, on a one-floor building of the map it got (~map_file,
// the map topic, static_map, set_map) and ~text_map_file, so there is one code path; and LocalizerCore,
// the nodelet's requests on that session (new maps, global localization, initial poses) with the rule that
// a request applies fully or changes nothing, and its state as ~state reports it. No ROS master needed.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "doorplate_localization/maps/building_map.h"
#include "doorplate_localization/mcl/building_session.h"
#include "doorplate_localization/ros/amcl_conversions.h"
#include "doorplate_localization/ros/param_table.h"
#include "text_amcl_options.h"

namespace doorplate_localization {

// ~building_file's maps (LoadBuildingFile + LoadBuildingMaps: every floor's grid and text map, the lifts
// on free cells), with ~start_floor ("" or one of its floors); nullptr when ~building_file is "". Throws
// ParameterError naming the parameter and the file's own error ("/amcl/building_file = 'b.building.yaml'
// cannot be used: b.building.yaml: floors[1] (id '3'): ...", "/amcl/start_floor: no floor '4' in
// b.building.yaml (floors: 2, 3)").
std::shared_ptr<const BuildingMaps> LoadLocalizerBuilding(const TextAmclNodeOptions& options,
                                                         const ParamSource& source);

// ~text_map_file for a one-floor run, loaded; null when ~use_text is false or it is unusable (the filter then
// runs on the laser alone). `problem` (an error) when it cannot be read, `warning` when it is not set or its
// frame_id differs from ~global_frame_id; both name `param` (the resolved ~text_map_file) or the file.
struct LocalizerTextMap {
  std::shared_ptr<const TextMap> text_map;
  std::string problem;
  std::string warning;
};
LocalizerTextMap LoadLocalizerTextMap(const TextAmclNodeOptions& options, const std::string& param);

// The maps the nodelet starts on: ~building_file's (options.building), else ~map_file (a map_server YAML)
// with `text_map` (null: laser only) as one floor with id ~start_floor; nullptr when neither is set (the map
// then comes from the map topic or the static_map service). Throws ParameterError naming `map_param` (the
// resolved ~map_file) and the file's error ("/amcl/map_file = 'm.yaml' cannot be used: m.yaml: ...").
std::shared_ptr<const BuildingMaps> LocalizerStartMaps(const TextAmclNodeOptions& options,
                                                       std::shared_ptr<const TextMap> text_map,
                                                       const std::string& map_param);

// `grid` and `text_map` (null: laser only) as a building of one floor with id `floor_id`, no lifts.
std::shared_ptr<const BuildingMaps> OneFloorBuilding(const OccupancyGrid& grid,
                                                     std::shared_ptr<const TextMap> text_map,
                                                     const std::string& floor_id);

// The BuildingSession the node options ask for (session, floor belief, start floor).
BuildingSessionOptions ToBuildingSessionOptions(const TextAmclNodeOptions& options);

// A session on `maps`; every floor's map is checked by the session now (not at the first switch there). A
// one-floor building whose text map the session refuses (e.g. one without landmarks) runs laser only:
// *text_problem says why (else ""), and the session's maps have no text map. Throws std::invalid_argument when
// the maps cannot be used at all (the grid, or any floor of a building: "floor '3': ...").
std::unique_ptr<BuildingSession> StartBuildingSession(const BuildingSessionOptions& options,
                                                      std::shared_ptr<const BuildingMaps> maps,
                                                      std::string* text_problem);

// A start pose (map frame: x_m, y_m, theta_rad, and its covariance), as initialpose and set_map give it.
struct StartPose {
  Pose2D mean;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
};

// The nodelet's session and what ~state and /diagnostics say about it, without ROS. The rules (issue 18,
// issue 19's amcl habits):
//  - A request applies fully or changes nothing: a new map (UseMaps) is turned into a whole new session
//    first (every floor's filter, the free-space and size checks of the core); only then does it replace
//    the session in force. A refused map leaves the session, the map in force and the state as they were.
//  - global_localization with no map in force is queued (GlobalLocalization returns false): the first map
//    that is used starts with global localization, not at ~initial_pose_*. A later initial pose (initialpose
//    or set_map's) cancels the queued request: the latest request wins.
//  - State (NodeStateText, amcl_conversions.h): waiting_for_map until a map is in force; waiting_for_scan
//    after every (re)start until the session takes a scan, and when none was taken for ~scan_timeout_s;
//    error: <what> after the session threw (Failed), until it takes a scan again; else the filter's.
// Times are ROS time in seconds (any monotonic clock).
class LocalizerCore {
 public:
  // `text_map`: ~text_map_file's for one floor (null: laser only); `options` as loaded (with ~building_file's
  // maps, if any, given to UseMaps by the caller).
  LocalizerCore(const TextAmclNodeOptions& options, std::shared_ptr<const TextMap> text_map);

  struct MapChange {
    bool used = false;
    std::string problem;       // refused: why; nothing changed
    std::string text_problem;  // used without its text map: why (laser only on this map)
    bool ran_queued_global_localization = false;
  };
  // A session on `maps` from `source` (a file, topic or service, for the log), started at `start` (set_map's
  // pose: it also becomes ~initial_pose for later maps), else by the queued global localization, else as the
  // options say (~initial_pose_* or ~start_with_global_localization).
  MapChange UseMaps(std::shared_ptr<const BuildingMaps> maps, const std::string& source,
                    const std::optional<StartPose>& start = std::nullopt);
  // One floor: `grid` with ~text_map_file's text map. Refused with ~building_file (its floors' maps are used).
  MapChange UseGrid(const OccupancyGrid& grid, const std::string& source,
                    const std::optional<StartPose>& start = std::nullopt);
  // amcl's global_localization: true when it ran on the map in force, false when queued (no map yet).
  bool GlobalLocalization();
  // amcl's initialpose: restarts the session on its current floor there (when a map is in force), and is the
  // start pose on later maps; cancels a queued global localization. Throws std::invalid_argument for a
  // covariance the filter refuses (nothing changed).
  void InitialPose(const StartPose& pose);
  // dynamic_reconfigure: the filter and its models from now on (`setup`, validated by the caller as at
  // startup). With a session in force, a whole new one continuing from it (BuildingSession's continuing
  // constructor: every floor keeps its particles) replaces it; "" then, or why the core refused (nothing
  // changed). Without one, the next map's session uses `setup`.
  std::string Reconfigure(const TextAmclSetupOptions& setup);
  // The nodelet took a scan into the session at `now_s` (clears an error), or the session threw `what`.
  void ScanTaken(double now_s);
  void Failed(const std::string& what);
  // A scan was not taken (broken, no tf, dropped waiting for tf): counted, `why` kept as the last (Health).
  void ScanDropped(const std::string& why);

  bool has_session() const { return session_ != nullptr; }
  BuildingSession& session() { return *session_; }  // requires has_session()
  const BuildingSession& session() const { return *session_; }
  bool global_localization_queued() const { return queued_global_localization_; }
  const std::string& map_in_force() const { return map_; }  // "" before the first map
  // State and counters at `now_s`; scan_rate_hz and tf_age_s are left for the caller (it has the clock and tf).
  LocalizerHealth Health(double now_s) const;
  std::string State(double now_s) const { return NodeStateText(Health(now_s)); }

 private:
  void Restarted() { last_scan_s_.reset(); }

  TextAmclNodeOptions options_;
  std::shared_ptr<const TextMap> text_map_;
  std::unique_ptr<BuildingSession> session_;
  bool queued_global_localization_ = false;
  std::string map_;
  std::string error_;
  std::optional<double> last_scan_s_;
  long long scans_dropped_ = 0;
  std::string last_scan_dropped_;
};

}  // namespace doorplate_localization

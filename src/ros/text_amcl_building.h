// The floors TextAmclNodelet localizes on: it always runs one BuildingSession (mcl/building_session.h),
// on the floors of ~building_file or, without one, on a one-floor building of the map it got (~map_file,
// the map topic, static_map, set_map) and ~text_map_file, so there is one code path. ROS-free.
#pragma once

#include <memory>
#include <string>

#include "doorplate_localization/maps/building_map.h"
#include "doorplate_localization/mcl/building_session.h"
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

}  // namespace doorplate_localization

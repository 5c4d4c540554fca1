#include "text_amcl_building.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "doorplate_localization/maps/map_io.h"

namespace doorplate_localization {

std::shared_ptr<const BuildingMaps> LoadLocalizerBuilding(const TextAmclNodeOptions& options,
                                                         const ParamSource& source) {
  if (options.building_file.empty()) return nullptr;
  std::shared_ptr<BuildingMaps> maps;
  try {
    maps = std::make_shared<BuildingMaps>(
        LoadBuildingMaps(LoadBuildingFile(options.building_file), options.building_file));
  } catch (const std::exception& e) {  // BuildingFileError names the file, the floor and the map file
    throw ParameterError(source.Resolve("building_file") + " = '" + options.building_file +
                         "' cannot be used: " + e.what());
  }
  if (!options.start_floor.empty() && maps->FloorIndex(options.start_floor) < 0) {
    std::string ids;
    for (const FloorMaps& floor : maps->floors) ids += (ids.empty() ? "" : ", ") + floor.id;
    throw ParameterError(source.Resolve("start_floor") + ": no floor '" + options.start_floor + "' in " +
                         options.building_file + " (floors: " + ids + ")");
  }
  return maps;
}

LocalizerTextMap LoadLocalizerTextMap(const TextAmclNodeOptions& options, const std::string& param) {
  LocalizerTextMap loaded;
  if (!options.session.setup.use_text) return loaded;
  if (options.text_map_file.empty()) {
    loaded.warning = param + " is not set: localizing with the laser alone";
    return loaded;
  }
  try {
    loaded.text_map = std::make_shared<const TextMap>(LoadTextMap(options.text_map_file));
  } catch (const std::exception& e) {  // TextMapError names the file
    loaded.problem = param + ": " + e.what();
    return loaded;
  }
  if (loaded.text_map->frame_id != options.global_frame_id) {
    loaded.warning = options.text_map_file + ": frame_id '" + loaded.text_map->frame_id +
                     "' differs from global_frame_id '" + options.global_frame_id + "'; using it as " +
                     options.global_frame_id;
  }
  return loaded;
}

std::shared_ptr<const BuildingMaps> OneFloorBuilding(const OccupancyGrid& grid,
                                                     std::shared_ptr<const TextMap> text_map,
                                                     const std::string& floor_id) {
  auto maps = std::make_shared<BuildingMaps>();
  maps->name = "one floor";
  maps->floors.push_back({floor_id, grid, std::move(text_map)});
  return maps;
}

std::shared_ptr<const BuildingMaps> LocalizerStartMaps(const TextAmclNodeOptions& options,
                                                       std::shared_ptr<const TextMap> text_map,
                                                       const std::string& map_param) {
  if (options.building) return options.building;
  if (options.map_file.empty()) return nullptr;
  OccupancyGrid grid;
  try {
    grid = LoadOccupancyMap(options.map_file);
  } catch (const std::exception& e) {  // MapFileError names the file and field
    throw ParameterError(map_param + " = '" + options.map_file + "' cannot be used: " + e.what());
  }
  return OneFloorBuilding(grid, std::move(text_map), options.start_floor);
}

BuildingSessionOptions ToBuildingSessionOptions(const TextAmclNodeOptions& options) {
  BuildingSessionOptions o;
  o.session = options.session;
  o.floor_belief = options.floor_belief;
  o.start_floor = options.start_floor;
  return o;
}

std::unique_ptr<BuildingSession> StartBuildingSession(const BuildingSessionOptions& options,
                                                      std::shared_ptr<const BuildingMaps> maps,
                                                      std::string* text_problem) {
  text_problem->clear();
  try {
    // The session makes every floor's filter now, so a floor map it refuses stops the start ("floor 'X': ...").
    auto session = std::make_unique<BuildingSession>(options, maps);
    return session;
  } catch (const std::invalid_argument& e) {
    // The map, or the text map with it? On one floor, try without the text map (several floors need theirs
    // to tell them apart: no fallback).
    if (!maps || maps->floors.size() != 1 || !maps->floors.front().text_map) throw;
    auto laser_only = std::make_shared<BuildingMaps>(*maps);
    laser_only->floors.front().text_map = nullptr;
    auto session = std::make_unique<BuildingSession>(options, laser_only);  // throws if the map is the problem
    *text_problem = e.what();
    return session;
  }
}

LocalizerCore::LocalizerCore(const TextAmclNodeOptions& options, std::shared_ptr<const TextMap> text_map)
    : options_(options), text_map_(std::move(text_map)) {}

LocalizerCore::MapChange LocalizerCore::UseMaps(std::shared_ptr<const BuildingMaps> maps, const std::string& source,
                                                const std::optional<StartPose>& start) {
  MapChange change;
  BuildingSessionOptions o = ToBuildingSessionOptions(options_);
  if (start) {
    o.session.start_with_global_localization = false;
    o.session.initial_pose = start->mean;
    o.session.initial_covariance = start->covariance;
  } else if (queued_global_localization_) {
    o.session.start_with_global_localization = true;
  }
  std::unique_ptr<BuildingSession> session;
  try {  // the whole new session first: nothing in force changes until it exists
    session = StartBuildingSession(o, maps, &change.text_problem);
  } catch (const std::exception& e) {  // invalid_argument from the checks; anything else (bad_alloc) too
    change.problem = e.what();
    change.text_problem.clear();
    return change;
  }
  // Commit: nothing below throws.
  session_ = std::move(session);
  change.used = true;
  change.ran_queued_global_localization = !start && queued_global_localization_;
  queued_global_localization_ = false;
  if (start) {
    options_.session.initial_pose = start->mean;
    options_.session.initial_covariance = start->covariance;
  }
  const OccupancyGrid& grid = session_->maps().floors[static_cast<size_t>(session_->floor())].grid;
  char size[96];
  std::snprintf(size, sizeof(size), ": %d x %d at %.3f m", grid.width, grid.height, grid.resolution_m);
  map_ = source + size;
  error_.clear();
  Restarted();
  return change;
}

LocalizerCore::MapChange LocalizerCore::UseGrid(const OccupancyGrid& grid, const std::string& source,
                                                const std::optional<StartPose>& start) {
  if (options_.building) {
    MapChange refused;
    refused.problem = "the floors' maps come from " + options_.building_file;
    return refused;
  }
  return UseMaps(OneFloorBuilding(grid, text_map_, options_.start_floor), source, start);
}

bool LocalizerCore::GlobalLocalization() {
  if (!session_) {
    queued_global_localization_ = true;
    return false;
  }
  session_->GlobalLocalization();  // cannot fail on a session the core accepted (it has free cells)
  queued_global_localization_ = false;
  Restarted();
  return true;
}

void LocalizerCore::InitialPose(const StartPose& pose) {
  if (session_) session_->Initialize(session_->floor(), pose.mean, pose.covariance);  // throws before changing
  options_.session.initial_pose = pose.mean;
  options_.session.initial_covariance = pose.covariance;
  queued_global_localization_ = false;
  if (session_) Restarted();
}

std::string LocalizerCore::Reconfigure(const TextAmclSetupOptions& setup) {
  TextAmclSessionOptions session = options_.session;
  session.setup = setup;
  if (session_) {
    try {
      session_ = std::make_unique<BuildingSession>(*session_, session);
    } catch (const std::exception& e) {
      return e.what();
    }
  }
  options_.session = session;
  return "";
}

void LocalizerCore::ScanTaken(double now_s) {
  last_scan_s_ = now_s;
  error_.clear();
}

void LocalizerCore::Failed(const std::string& what) { error_ = what.empty() ? "unknown exception" : what; }

void LocalizerCore::ScanDropped(const std::string& why) {
  ++scans_dropped_;
  last_scan_dropped_ = why;
}

LocalizerHealth LocalizerCore::Health(double now_s) const {
  LocalizerHealth h;
  h.map_in_force = session_ != nullptr;
  h.map = map_;
  h.global_localization_queued = queued_global_localization_;
  h.error = error_;
  h.scan_age_s = last_scan_s_ ? std::max(0.0, now_s - *last_scan_s_) : -1.0;
  h.scan_timeout_s = options_.scan_timeout_s;
  h.scans_dropped = scans_dropped_;
  h.last_scan_dropped = last_scan_dropped_;
  if (session_) {
    h.status = session_->Status();
    const TextAmclSessionCounters& c = session_->session().counters();
    h.plates_weighed = c.plates_weighed;
    h.plates_used = c.plates_used;
    h.unknown_room_readings = c.unknown_room_readings;
  }
  return h;
}

}  // namespace doorplate_localization

// A building of several floors (issue 17, docs/building-format.md): a building file names each floor's
// files — its map pair (occupancy grid + text map) for the localizer and the planner, and/or its simulator
// world — and the lifts that join the floors. Each floor has its own map frame; a lift stop's pose is in
// the frame of its floor. ROS-free.
//
// Example (maps/hospital_two_floors.building.yaml):
//   format_version: 1
//   name: hospital_two_floors
//   floors:
//     - {id: "2", occupancy_map: hospital_floor_ring.yaml, text_map: hospital_floor_ring.text_map.yaml}
//     - {id: "3", occupancy_map: hospital_floor3_ring.yaml, text_map: hospital_floor3_ring.text_map.yaml}
//   lifts:
//     - id: "A"
//       stops:
//         - {floor: "2", x_m: 23, y_m: 28.8, yaw_rad: 1.570796327}
//         - {floor: "3", x_m: 23, y_m: 28.8, yaw_rad: 1.570796327}
//     - id: "B"  # the same stops at x_m: 21 (door lift_2)
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"

namespace doorplate_localization {

// Where a robot waits for a lift and where it leaves it on one floor: in front of the lift door, facing
// the door; metres and radians in that floor's map frame.
struct LiftStop {
  std::string floor;  // a BuildingFloor::id
  Pose2D pose;
};

struct Lift {
  std::string id;               // e.g. "A"; unique in the building
  std::vector<LiftStop> stops;  // >= 2, each on a different floor

  // The stop on `floor`, or nullptr when the lift does not serve it.
  const LiftStop* StopOn(const std::string& floor) const;
};

// One floor's files, as paths resolved against the building file's folder ("" when absent).
struct BuildingFloor {
  std::string id;             // e.g. "2", "B1"; unique, not empty
  std::string occupancy_map;  // map_server YAML
  std::string text_map;       // text map (docs/text-map-format.md)
  std::string world;          // simulator world (docs/world-format.md)
};

struct BuildingFile {
  int format_version = 1;
  std::string name;
  std::vector<BuildingFloor> floors;  // >= 1
  std::vector<Lift> lifts;

  int FloorIndex(const std::string& id) const;  // -1 when there is no such floor
};

// An unusable building file; what() names the file and the field path
// ("maps/b.building.yaml: lifts[0].stops[1].floor: no floor '4' (floors: 2, 3)").
class BuildingFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads and validates a building file; relative paths are resolved against its folder. Unknown fields are
// errors. Does not open the floors' files (LoadBuildingMaps does). Throws BuildingFileError.
BuildingFile LoadBuildingFile(const std::string& path);
// The same from text; relative paths resolved against `base_dir` ("" = as written).
BuildingFile ParseBuildingFile(const std::string& yaml_text, const std::string& source_name,
                               const std::string& base_dir);
// YAML text with every path written relative to `base_dir`, and the atomic write of it (map_io.h's
// WriteFileAtomically; the file's folder is the base). Both validate first; SaveBuildingFile throws
// BuildingFileError naming the path.
std::string BuildingFileToYaml(const BuildingFile& building, const std::string& base_dir);
void SaveBuildingFile(const BuildingFile& building, const std::string& path);

// One floor's maps, loaded.
struct FloorMaps {
  std::string id;
  OccupancyGrid grid;
  std::shared_ptr<const TextMap> text_map;
};

// What the localizer and the planner use: every floor's grid and text map, and the lifts.
struct BuildingMaps {
  std::string name;
  std::vector<FloorMaps> floors;  // in the building file's order
  std::vector<Lift> lifts;

  int FloorIndex(const std::string& id) const;  // -1 when there is no such floor
  // Indexes of the floors whose text map names the room `text` (TextMap::Find: canonical forms),
  // ascending; empty when no floor has it.
  std::vector<int> FloorsOfRoom(const std::string& text) const;
};

// Loads each floor's occupancy_map and text_map (both required for every floor) and checks each lift stop
// lies on a free cell of its floor's grid. Errors name the building file, the floor and the map file
// ("b.building.yaml: floors[1] (id '3'): h3.yaml: resolution: must be > 0"). Throws BuildingFileError.
BuildingMaps LoadBuildingMaps(const BuildingFile& building, const std::string& building_path);
// The same checks on maps built in memory (e.g. ground-truth maps of the simulator worlds); `source` names
// them in errors.
void ValidateBuildingMaps(const BuildingMaps& maps, const std::string& source);

}  // namespace doorplate_localization

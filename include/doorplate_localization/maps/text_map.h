// The text-landmark map (docs/text-map-format.md): the doorplates found while mapping, with their poses in
// the map frame, and the distances between adjacent plates along each wall (paper eqs. 13-15).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/common/room_id.h"

namespace doorplate_localization {

// One doorplate. `pose` is in the map frame: position = the plate's centre projected on the floor plane
// (on the wall surface), theta = the direction the plate faces (the wall normal pointing into the corridor).
struct TextLandmark {
  std::string text;               // room number as printed (validated), e.g. "214", "E14-295"; may repeat
                                  // in a map; fits the map's room_pattern (canonical form, common/room_id.h)
  Pose2D pose;
  double height_m = 1.6;          // plate centre above the floor
  std::string wall;               // which wall it is on (free label, e.g. "north" or "left"), "" if unknown
  int observations = 0;           // readings merged into this landmark while mapping (0: made by hand)
  double position_stddev_m = 0.0; // 1-sigma uncertainty of the position along the wall, 0 if unknown
};

// Distance between two plates next to each other on one wall (paper eq. 13: Dist(i,i+1) = u(i+1) - u(i)).
struct AdjacentDistance {
  int from = -1;                  // indexes into TextMap::landmarks
  int to = -1;
  double distance_m = 0.0;
  std::string source = "map";     // "odometry" (measured while mapping) or "map" (from the landmark poses)
};

struct TextMap {
  int format_version = 1;
  std::string frame_id = "map";
  std::string occupancy_map;      // the matching map_server YAML, relative to the text map's folder ("" if none)
  // The building's room identifier format: an ECMAScript regex every landmark text's canonical form
  // (common/room_id.h) matches; the default accepts "16-186", "E14-295", "B/1404", "39.A", "21/52", "5D", ...
  std::string room_pattern = kDefaultRoomPattern;
  std::vector<TextLandmark> landmarks;
  std::vector<AdjacentDistance> adjacent;

  // Indexes of every landmark naming the same room as `text` (SameRoom: canonical forms, so "E14295" finds
  // "E14-295"; repeated room numbers give several), ascending; empty if none.
  std::vector<int> Find(const std::string& text) const;
  // One text per distinct room (canonical form), as first printed in landmark order; sorted.
  std::vector<std::string> Texts() const;
};

class TextMapError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads and validates a text map; errors name the file and the field. Throws TextMapError.
TextMap LoadTextMap(const std::string& path);
TextMap ParseTextMap(const std::string& yaml_text, const std::string& source_name);
// Serializes to YAML text, and writes it atomically. SaveTextMap throws TextMapError naming the path.
std::string TextMapToYaml(const TextMap& map);
void SaveTextMap(const TextMap& map, const std::string& path);

// Recomputes `adjacent` (source "map") from the landmark poses: plates on the same `wall` sorted along it.
void ComputeAdjacentDistances(TextMap* map);

}  // namespace doorplate_localization

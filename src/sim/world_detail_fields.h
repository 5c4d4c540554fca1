// Reads the optional detail sections of a world file (private to the world loader): door recesses and
// frames, `glass[]`, `clutter[]` and `people[]` (docs/world-format.md). Every field is checked; errors name
// the file and the field (YamlFieldError).
#pragma once

#include <map>
#include <set>
#include <string>

#include "doorplate_localization/common/yaml_reader.h"
#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

// A world position: `f` as [x, y] metres, each within ±limits::kMaxCoordinateM (a world is a building, and
// coordinates like 1e300 would overflow the grids made from it); fails naming the field and the limit.
Vec2 ParsePointM(const YamlField& f);
// A single world coordinate in metres (`start.x_m`, a clutter item's `x_m`), checked the same way.
double ParseCoordinateM(const YamlField& f);

// Door keys `recess_m`, `frame_width_m`, `frame_depth_m`, `frame_color` (doors and door_rows).
extern const std::set<std::string> kDoorDetailKeys;
void ParseDoorDetail(const YamlField& f, Door* door);
// Extra checks of a door's detail against its wall (after ParseDoorDetail and the door's own fields).
void CheckDoorDetail(const YamlField& f, const World& world, const Door& door);

// One entry of each list; `walls` maps wall ids to indexes. Glass must be read before clutter (runs break
// at glass in walls), doors before both.
void ParseGlass(const YamlField& f, const std::map<std::string, int>& walls, World* world);
void ParseClutter(const YamlField& f, const std::map<std::string, int>& walls, World* world);
void ParsePerson(const YamlField& f, World* world);

// After the robot is read: the start is not inside a clutter footprint the bumper would hit.
void CheckStartOutsideClutter(const YamlField& robot, const World& world);

}  // namespace doorplate_localization

// Tiny corridor worlds with doorplates for the experiment tool's tests.
#pragma once

#include <string>
#include <vector>

#include "../sim/test_worlds.h"

namespace doorplate_localization::test {

struct PlateSpec {
  int wall;          // 0 south (faces +y), 1 north (faces −y), as in RectangleCorridor
  double offset_m;   // along the wall from x = 0
  std::string text;
};

// RectangleCorridor(length, width) with plates 1.6 m high, the robot starting at (0.7, 0.6) facing +x.
inline World CorridorWithPlates(double length_m, double width_m, const std::vector<PlateSpec>& plates) {
  World world = RectangleCorridor(length_m, width_m);
  world.name = "test_corridor";
  for (const PlateSpec& spec : plates) {
    TextSign sign;
    sign.text = spec.text;
    sign.wall_index = spec.wall;
    sign.offset_m = spec.offset_m;
    sign.corridor_side_left = world.walls[spec.wall].corridor_side_left;
    world.signs.push_back(sign);
  }
  world.start_pose = {0.7, 0.6, 0.0};
  BuildSurfaces(world);
  return world;
}

// An L-shaped floor of two corridors listed in `corridors`: "along" x in [0, 10], y in [0, 2] (centreline
// (0, 1) → (10, 1)) and "up" x in [8, 10], y in [2, 6] (centreline (9, 2) → (9, 6)); no doors or plates;
// the robot starts at (1, 1) facing +x.
inline World LShapedFloor() {
  World world = LCorridor(10.0, 6.0);
  world.name = "l_floor";
  world.corridors = {{"along", {{0, 1}, {10, 1}}, 2.0}, {"up", {{9, 2}, {9, 6}}, 2.0}};
  world.start_pose = {1.0, 1.0, 0.0};
  BuildSurfaces(world);
  return world;
}

}  // namespace doorplate_localization::test

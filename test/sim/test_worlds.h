// Tiny worlds built in code for the simulator tests.
#pragma once

#include <string>
#include <vector>

#include "doorplate_localization/sim/world.h"

namespace doorplate_localization::test {

// A closed rectangular corridor [0, length] × [0, width] with no doors; the robot starts at (1, width/2).
inline World RectangleCorridor(double length_m = 10.0, double width_m = 2.0) {
  World world;
  world.name = "rectangle";
  world.walls = {
      {"south", {{0, 0}, {length_m, 0}}, true, {200, 200, 200}},
      {"north", {{0, width_m}, {length_m, width_m}}, false, {200, 200, 200}},
      {"west", {{0, 0}, {0, width_m}}, false, {200, 200, 200}},
      {"east", {{length_m, 0}, {length_m, width_m}}, true, {200, 200, 200}},
  };
  world.start_pose = {1.0, width_m / 2, 0.0};
  BuildSurfaces(world);
  return world;
}

// Adds a closed polygon of walls with the corridor on the left of each edge (list an outline
// counter-clockwise, a block inside it clockwise); wall ids `prefix`0, `prefix`1, ... Surfaces not built.
inline void AddWallPolygon(World& world, const std::vector<Vec2>& corners, const std::string& prefix) {
  for (std::size_t i = 0; i < corners.size(); ++i) {
    world.walls.push_back({prefix + std::to_string(i), {corners[i], corners[(i + 1) % corners.size()]}, true,
                           {200, 200, 200}});
  }
}

// An L of 2 m corridors: along x from 0 to `length_x_m` (y in [0, 2]), then up along y (x in
// [length_x_m − 2, length_x_m]) to y = `length_y_m`. Walls 0..5: south, east, north end, the inner corner's
// two walls (inner west, inner north), west end. The robot starts at (1, 1) facing +x.
inline World LCorridor(double length_x_m, double length_y_m) {
  World world;
  world.name = "l_corridor";
  AddWallPolygon(world,
                 {{0, 0}, {length_x_m, 0}, {length_x_m, length_y_m}, {length_x_m - 2, length_y_m},
                  {length_x_m - 2, 2}, {0, 2}},
                 "l");
  world.start_pose = {1.0, 1.0, 0.0};
  BuildSurfaces(world);
  return world;
}

}  // namespace doorplate_localization::test

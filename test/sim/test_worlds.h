// Tiny worlds built in code for the simulator tests.
#pragma once

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

}  // namespace doorplate_localization::test

// Tiny corridor worlds with doorplates for the experiment tool's tests.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "../sim/test_worlds.h"
#include "doorplate_localization/maps/building_map.h"
#include "doorplate_localization/sim/ground_truth_maps.h"

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

// A building of two floors of the same 12 m x 2 m corridor (`corridors` listed), floor "2" with rooms
// 201-204 and floor "3" with 301-304 (same places), a lift at the west end: its stop (1.0, 1.0) faces the
// west wall on both floors. Ground-truth maps (0.05 m) as the robot's maps.
struct TwoFloorBuilding {
  std::vector<World> worlds;
  std::shared_ptr<BuildingMaps> maps = std::make_shared<BuildingMaps>();
  std::vector<OccupancyGrid> grids;
};
inline TwoFloorBuilding MakeTwoFloorBuilding() {
  TwoFloorBuilding b;
  b.maps->name = "two_floor_test";
  for (const char* floor : {"2", "3"}) {
    const std::string f(floor);
    World world = CorridorWithPlates(
        12.0, 2.0, {{1, 3.0, f + "01"}, {1, 7.5, f + "03"}, {0, 2.5, f + "02"}, {0, 6.5, f + "04"}});
    world.name = "floor_" + f;
    world.corridors = {{"main", {{0, 1}, {12, 1}}, 2.0}};
    BuildSurfaces(world);
    OccupancyGrid grid = RasterizeWorld(world, 0.05, world.sensors.laser.mount_height_m);
    b.maps->floors.push_back({f, grid, std::make_shared<const TextMap>(GroundTruthTextMap(world))});
    b.grids.push_back(grid);
    b.worlds.push_back(world);
  }
  b.maps->lifts.push_back({"A", {{"2", {1.0, 1.0, M_PI}}, {"3", {1.0, 1.0, M_PI}}}});
  return b;
}

}  // namespace doorplate_localization::test

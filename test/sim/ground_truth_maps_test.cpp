#include "doorplate_localization/sim/ground_truth_maps.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "doorplate_localization/maps/building_map.h"
#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/sim/laser_simulator.h"
#include "doorplate_localization/sim/world_loader.h"
#include "test_worlds.h"

namespace doorplate_localization {
namespace {

constexpr double kLaserHeight = 0.25;

std::int8_t CellAt(const OccupancyGrid& grid, Vec2 p) {
  int x = 0, y = 0;
  if (!grid.WorldToCell(p, &x, &y)) ADD_FAILURE() << "(" << p.x << ", " << p.y << ") is outside the grid";
  return grid.At(x, y);
}

// worlds/ holds building files (docs/building-format.md) beside the worlds.
bool IsBuildingFile(const std::filesystem::path& path) {
  const std::string name = path.filename().string();
  const std::string suffix = ".building.yaml";
  return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

int Count(const OccupancyGrid& grid, std::int8_t value) {
  return static_cast<int>(std::count(grid.cells.begin(), grid.cells.end(), value));
}

TextSign PlateOn(const World& world, int wall, double offset_m, const std::string& text) {
  TextSign sign;
  sign.text = text;
  sign.wall_index = wall;
  sign.offset_m = offset_m;
  sign.center_height_m = 1.5;
  sign.corridor_side_left = world.walls[wall].corridor_side_left;
  return sign;
}

TEST(RasterizeWorld, ClosedCorridorIsFreeInsideOccupiedOnTheWallsUnknownOutside) {
  const World world = test::RectangleCorridor(10.0, 2.0);
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, kLaserHeight);
  EXPECT_EQ(CellAt(grid, {5.0, 1.0}), OccupancyGrid::kFree);
  EXPECT_EQ(CellAt(grid, {5.0, 0.0}), OccupancyGrid::kOccupied);
  EXPECT_EQ(CellAt(grid, {10.0, 1.0}), OccupancyGrid::kOccupied);
  EXPECT_EQ(CellAt(grid, {5.0, -0.3}), OccupancyGrid::kUnknown);
  EXPECT_EQ(CellAt(grid, {10.3, 1.0}), OccupancyGrid::kUnknown);
  // Walls on round coordinates are cell centres: 199 x 39 cells strictly between them.
  EXPECT_EQ(Count(grid, OccupancyGrid::kFree), 199 * 39);
  int x = 0, y = 0;
  ASSERT_TRUE(grid.WorldToCell({5.0, 2.0}, &x, &y));
  EXPECT_NEAR(grid.CellCenter(x, y).y, 2.0, 1e-9);
  // The grid covers the walls plus the margin and no more.
  EXPECT_NEAR(grid.origin.x_m, -0.525, 1e-9);
  EXPECT_EQ(grid.width, 201 + 20);
}

// docs/world-format.md's "A minimal world" is what a new user copies first: it must load and make maps.
TEST(RasterizeWorld, TheFormatDocsMinimalWorldLoadsAndIsClosed) {
  std::ifstream in(std::string(DOORPLATE_SOURCE_DIR) + "/docs/world-format.md");
  ASSERT_TRUE(in.good());
  std::string line, yaml;
  bool section = false, block = false;
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) section = line == "## A minimal world";
    if (!section) continue;
    if (line == "```yaml") { block = true; continue; }
    if (block && line == "```") break;
    if (block) yaml += line + "\n";
  }
  ASSERT_FALSE(yaml.empty()) << "no yaml block under '## A minimal world'";
  const World world = ParseWorldYaml(yaml, "docs/world-format.md");
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, kLaserHeight);
  EXPECT_EQ(CellAt(grid, {world.start_pose.x_m, world.start_pose.y_m}), OccupancyGrid::kFree);
  EXPECT_EQ(GroundTruthTextMap(world).landmarks.size(), 1u);  // plate 214
}

TEST(RasterizeWorld, RoomsBehindOpenDoorsAreReachableThroughTheGap) {
  World world = test::RectangleCorridor(10.0, 2.0);
  Door door;
  door.wall_index = 1;  // north: the room lies at y > 2
  door.offset_m = 5.0;
  door.open = true;
  world.doors.push_back(door);
  BuildSurfaces(world);
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, kLaserHeight);
  EXPECT_EQ(CellAt(grid, {5.0, 2.0}), OccupancyGrid::kFree);  // in the doorway: the lintel is above the laser
  EXPECT_EQ(CellAt(grid, {5.0, 3.5}), OccupancyGrid::kFree);
  EXPECT_EQ(CellAt(grid, {5.0, 5.0}), OccupancyGrid::kOccupied);  // the room's back wall
  EXPECT_EQ(CellAt(grid, {8.0, 3.5}), OccupancyGrid::kUnknown);   // beside the room, behind the wall
}

TEST(RasterizeWorld, OnlySurfacesSpanningTheLaserHeightAreDrawn) {
  World world = test::RectangleCorridor(10.0, 2.0);
  Door door;
  door.wall_index = 1;
  door.offset_m = 5.0;
  door.open = true;
  world.doors.push_back(door);
  BuildSurfaces(world);
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, 2.2);  // above the door: the lintel closes it
  EXPECT_EQ(CellAt(grid, {5.0, 2.0}), OccupancyGrid::kOccupied);
  EXPECT_EQ(CellAt(grid, {5.0, 3.5}), OccupancyGrid::kUnknown);
}

TEST(RasterizeWorld, SlantedWallsAtAnyAngleStayClosed) {
  World world;
  world.name = "heptagon";
  const int n = 7;
  for (int i = 0; i < n; ++i) {  // irregular radii: every side has its own slope
    const double a0 = 2 * M_PI * i / n + 0.1, a1 = 2 * M_PI * (i + 1) / n + 0.1;
    const double r0 = 3.0 + 0.37 * (i % 3), r1 = 3.0 + 0.37 * (((i + 1) % n) % 3);
    world.walls.push_back({"w" + std::to_string(i),
                           {{r0 * std::cos(a0), r0 * std::sin(a0)}, {r1 * std::cos(a1), r1 * std::sin(a1)}},
                           true,
                           {}});
  }
  world.start_pose = {0.0, 0.0, 0.0};
  BuildSurfaces(world);
  for (double resolution : {0.05, 0.1, 0.13}) {
    const OccupancyGrid grid = RasterizeWorld(world, resolution, kLaserHeight);  // throws if it leaks
    EXPECT_EQ(CellAt(grid, {0.0, 0.0}), OccupancyGrid::kFree);
    EXPECT_EQ(CellAt(grid, {3.5, 3.5}), OccupancyGrid::kUnknown);
  }
}

// Issue 17's whole floor is one closed, connected area: every corridor's centreline, the space in front of
// every plate and every room behind an open door are reachable from the start; the courtyard is not.
TEST(RasterizeWorld, TheHospitalFloorRingIsOneConnectedClosedFloor) {
  const World world = LoadWorldFile(std::string(DOORPLATE_SOURCE_DIR) + "/worlds/hospital_floor_ring.yaml");
  const OccupancyGrid grid = RasterizeWorld(world, 0.05, kLaserHeight);
  for (const CorridorSpec& c : world.corridors) {
    for (double t = 0.02; t <= 0.98; t += 0.02) {
      const Vec2 p = c.centreline.a + t * (c.centreline.b - c.centreline.a);
      EXPECT_EQ(CellAt(grid, p), OccupancyGrid::kFree) << c.id << " at " << p.x << ", " << p.y;
    }
  }
  for (const TextSign* plate : world.Plates()) {
    const Vec2 front = world.SignPosition(*plate) + 0.3 * world.CorridorNormal(plate->wall_index);
    EXPECT_EQ(CellAt(grid, front), OccupancyGrid::kFree) << plate->text;
  }
  for (const Door& door : world.doors) {
    if (!door.open) continue;
    const Wall& wall = world.walls[door.wall_index];
    const Vec2 at = wall.segment.a + (door.offset_m / wall.segment.Length()) * (wall.segment.b - wall.segment.a);
    const Vec2 in_room = at + 1.5 * world.WallNormal(door.wall_index, !wall.corridor_side_left);
    EXPECT_EQ(CellAt(grid, in_room), OccupancyGrid::kFree) << door.id;
  }
  EXPECT_EQ(CellAt(grid, {21.0, 13.0}), OccupancyGrid::kUnknown);  // the courtyard
}

TEST(RasterizeWorld, AnOpenWorldIsReportedAsNotClosed) {
  World world = test::RectangleCorridor(10.0, 2.0);
  world.walls.pop_back();  // no east wall
  BuildSurfaces(world);
  try {
    RasterizeWorld(world, 0.05, kLaserHeight);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("world 'rectangle': the area reachable from the robot start is not closed"),
              std::string::npos)
        << e.what();
  }
}

TEST(RasterizeWorld, RejectsAStartOnAWallAndABadResolution) {
  World world = test::RectangleCorridor(10.0, 2.0);
  EXPECT_THROW(RasterizeWorld(world, 0.0, kLaserHeight), std::invalid_argument);
  world.start_pose = {5.0, 0.0, 0.0};
  EXPECT_THROW(RasterizeWorld(world, 0.05, kLaserHeight), std::invalid_argument);
}

TEST(GroundTruthTextMap, PlatesFaceTheCorridorAndNeighboursAreMeasuredAlongEachWall) {
  World world = test::RectangleCorridor(10.0, 2.0);
  world.signs = {PlateOn(world, 0, 6.0, "103"), PlateOn(world, 0, 2.0, "101"), PlateOn(world, 1, 4.0, "102"),
                 PlateOn(world, 0, 9.5, "105")};
  TextSign poster = PlateOn(world, 0, 4.0, "EXIT");
  poster.kind = TextKind::kDistractor;
  world.signs.push_back(poster);
  const TextMap map = GroundTruthTextMap(world);
  ASSERT_EQ(map.landmarks.size(), 4u);  // the distractor is no landmark
  const TextLandmark& south = map.landmarks[0];
  EXPECT_EQ(south.text, "103");
  EXPECT_NEAR(south.pose.x_m, 6.0, 1e-12);
  EXPECT_NEAR(south.pose.y_m, 0.0, 1e-12);
  EXPECT_NEAR(south.pose.theta_rad, M_PI / 2, 1e-12);  // the south wall's plates face north (+y)
  EXPECT_EQ(south.wall, "south");
  EXPECT_DOUBLE_EQ(south.height_m, 1.5);
  EXPECT_EQ(south.observations, 0);
  EXPECT_NEAR(map.landmarks[2].pose.theta_rad, -M_PI / 2, 1e-12);  // north wall: facing -y
  EXPECT_EQ(map.landmarks[2].wall, "north");
  ASSERT_EQ(map.adjacent.size(), 2u);  // 101 -> 103 -> 105 on the south wall; 102 alone on the north
  EXPECT_EQ(map.adjacent[0].from, 1);
  EXPECT_EQ(map.adjacent[0].to, 0);
  EXPECT_NEAR(map.adjacent[0].distance_m, 4.0, 1e-9);
  EXPECT_EQ(map.adjacent[1].to, 3);
  EXPECT_NEAR(map.adjacent[1].distance_m, 3.5, 1e-9);
}

// maps/ holds the ground truth of every world in worlds/: a world edited without regenerating its maps
// would silently skew every experiment run on them.
TEST(GroundTruthMaps, CommittedMapsMatchTheWorldsTheyWereMadeFrom) {
  const std::filesystem::path root(DOORPLATE_SOURCE_DIR);
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(root / "worlds")) {
    if (entry.path().extension() != ".yaml" || IsBuildingFile(entry.path())) continue;
    const std::string name = entry.path().stem().string();
    SCOPED_TRACE("maps/" + name + " is stale or missing: run doorplate_world_maps --world worlds/" + name +
                 ".yaml --out maps/" + name);
    const World world = LoadWorldFile(entry.path().string());
    const OccupancyGrid saved = LoadOccupancyMap((root / "maps" / (name + ".yaml")).string());
    const OccupancyGrid made = RasterizeWorld(world, saved.resolution_m, world.sensors.laser.mount_height_m);
    EXPECT_EQ(saved.width, made.width);
    EXPECT_EQ(saved.height, made.height);
    EXPECT_NEAR(saved.origin.x_m, made.origin.x_m, 1e-9);
    EXPECT_NEAR(saved.origin.y_m, made.origin.y_m, 1e-9);
    EXPECT_TRUE(saved.cells == made.cells);
    const TextMap saved_text = LoadTextMap((root / "maps" / (name + ".text_map.yaml")).string());
    const TextMap made_text = GroundTruthTextMap(world);
    EXPECT_EQ(saved_text.occupancy_map, name + ".yaml");
    ASSERT_EQ(saved_text.landmarks.size(), made_text.landmarks.size());
    for (size_t i = 0; i < made_text.landmarks.size(); ++i) {
      EXPECT_EQ(saved_text.landmarks[i].text, made_text.landmarks[i].text);
      EXPECT_NEAR(saved_text.landmarks[i].pose.x_m, made_text.landmarks[i].pose.x_m, 1e-9);
      EXPECT_NEAR(saved_text.landmarks[i].pose.y_m, made_text.landmarks[i].pose.y_m, 1e-9);
      EXPECT_NEAR(saved_text.landmarks[i].pose.theta_rad, made_text.landmarks[i].pose.theta_rad, 1e-9);
      EXPECT_EQ(saved_text.landmarks[i].wall, made_text.landmarks[i].wall);
    }
    EXPECT_EQ(saved_text.adjacent.size(), made_text.adjacent.size());
    ++checked;
  }
  EXPECT_GE(checked, 4);
}

// Distance from `origin` along `direction` to the first occupied cell, marching in steps of 1/8 cell.
double GridRange(const OccupancyGrid& grid, Vec2 origin, Vec2 direction, double max_range_m) {
  const double step = grid.resolution_m / 8.0;
  for (double t = 0.0; t <= max_range_m; t += step) {
    int x = 0, y = 0;
    if (!grid.WorldToCell(origin + t * direction, &x, &y)) break;
    if (grid.At(x, y) == OccupancyGrid::kOccupied) return t;
  }
  return max_range_m;
}

// maps/ holds the maps of every building of worlds/: the same floors, each naming its world's maps (checked
// above), and the same lifts, every stop on a free cell of its floor's grid.
TEST(GroundTruthMaps, CommittedBuildingFilesMatchTheBuildingsOfTheWorlds) {
  const std::filesystem::path root(DOORPLATE_SOURCE_DIR);
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(root / "worlds")) {
    if (!IsBuildingFile(entry.path())) continue;
    const std::string file = entry.path().filename().string();
    SCOPED_TRACE("maps/" + file + " is stale or missing: run doorplate_world_maps --building worlds/" + file +
                 " --out maps");
    const BuildingFile worlds = LoadBuildingFile(entry.path().string());
    const std::string maps_path = (root / "maps" / file).string();
    const BuildingFile maps = LoadBuildingFile(maps_path);
    EXPECT_NO_THROW(LoadBuildingMaps(maps, maps_path));
    EXPECT_EQ(maps.name, worlds.name);
    ASSERT_EQ(maps.floors.size(), worlds.floors.size());
    for (size_t i = 0; i < worlds.floors.size(); ++i) {
      const std::string world_name = LoadWorldFile(worlds.floors[i].world).name;
      EXPECT_EQ(maps.floors[i].id, worlds.floors[i].id);
      EXPECT_EQ(maps.floors[i].occupancy_map, (root / "maps" / (world_name + ".yaml")).string());
      EXPECT_EQ(maps.floors[i].text_map, (root / "maps" / (world_name + ".text_map.yaml")).string());
    }
    ASSERT_EQ(maps.lifts.size(), worlds.lifts.size());
    for (size_t l = 0; l < worlds.lifts.size(); ++l) {
      EXPECT_EQ(maps.lifts[l].id, worlds.lifts[l].id);
      ASSERT_EQ(maps.lifts[l].stops.size(), worlds.lifts[l].stops.size());
      for (size_t s = 0; s < worlds.lifts[l].stops.size(); ++s) {
        const LiftStop &a = maps.lifts[l].stops[s], &b = worlds.lifts[l].stops[s];
        EXPECT_EQ(a.floor, b.floor);
        EXPECT_NEAR(a.pose.x_m, b.pose.x_m, 1e-9);
        EXPECT_NEAR(a.pose.y_m, b.pose.y_m, 1e-9);
        EXPECT_NEAR(a.pose.theta_rad, b.pose.theta_rad, 1e-9);
      }
    }
    ++checked;
  }
  EXPECT_GE(checked, 1);
}

// The saved ground-truth map of the ward and the simulated laser see the same walls: ray casting in the
// grid from poses along the corridor gives the laser's exact ranges to within a few cells.
TEST(GroundTruthMaps, RaysInTheSavedGridAgreeWithTheSimulatedLaser) {
  const std::filesystem::path root(DOORPLATE_SOURCE_DIR);
  const World world = LoadWorldFile((root / "worlds" / "hospital_ward.yaml").string());
  const OccupancyGrid grid = LoadOccupancyMap((root / "maps" / "hospital_ward.yaml").string());
  const LaserSimulator laser(world.sensors.laser);
  std::vector<double> errors;
  for (double x = 1.0; x < 29.0; x += 1.7) {
    const Pose2D pose{x, 0.6 + 0.05 * x, 0.1 * x};
    const LaserScan scan = laser.CastExact(world, pose);
    const Pose2D laser_pose = pose.Compose(laser.MountPose());
    for (size_t i = 0; i < scan.ranges_m.size(); ++i) {
      if (!std::isfinite(scan.ranges_m[i])) continue;
      const double angle = laser_pose.theta_rad + scan.angle_min_rad + i * scan.angle_increment_rad;
      const double range = GridRange(grid, laser_pose.Position(), {std::cos(angle), std::sin(angle)}, 20.0);
      errors.push_back(std::abs(range - scan.ranges_m[i]));
    }
  }
  ASSERT_GT(errors.size(), 5000u);
  std::sort(errors.begin(), errors.end());
  const double median = errors[errors.size() / 2], p95 = errors[errors.size() * 95 / 100];
  std::cout << "grid vs laser range error over " << errors.size() << " beams: median " << median << " m, p95 "
            << p95 << " m, max " << errors.back() << " m\n";
  // A wall cell's near face lies half a cell before the wall, more for oblique beams (measured: median
  // 0.028 m, p95 0.147 m at 5 cm; the larger ones are beams grazing a wall or passing a door jamb within
  // half a cell). A flipped or shifted map is off by metres.
  EXPECT_LT(median, 0.6 * grid.resolution_m);
  EXPECT_LT(p95, 4 * grid.resolution_m);
}

}  // namespace
}  // namespace doorplate_localization

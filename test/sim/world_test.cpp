#include "doorplate_localization/sim/world.h"

#include <gtest/gtest.h>

#include "test_worlds.h"

namespace doorplate_localization {
namespace {

TEST(BuildSurfaces, ClosedDoorsLeaveTheWallWhole) {
  World world = test::RectangleCorridor();
  world.doors.push_back({"d", 1, 5.0, 0.9, 2.1, false, 3.0, 3.0, {}});
  BuildSurfaces(world);
  EXPECT_EQ(world.surfaces.size(), 4u);
}

TEST(BuildSurfaces, AnOpenDoorCutsAGapWithALintelAndARoomBehind) {
  World world = test::RectangleCorridor();
  Door door;
  door.id = "d";
  door.wall_index = 1;  // north wall, corridor on its right: the room lies at y > 2
  door.offset_m = 5.0;
  door.open = true;
  world.doors.push_back(door);
  BuildSurfaces(world);
  // north wall: two pieces + lintel; room: three walls.
  EXPECT_EQ(world.surfaces.size(), 4u - 1u + 3u + 3u);
  int lintels = 0, room_walls = 0;
  for (const Surface& s : world.surfaces) {
    if (s.z_min_m > 0) {
      ++lintels;
      EXPECT_NEAR(s.z_min_m, door.height_m, 1e-12);
      EXPECT_NEAR(s.segment.Length(), door.width_m, 1e-9);
    }
    if (s.wall_index < 0) {
      ++room_walls;
      EXPECT_GE(std::min(s.segment.a.y, s.segment.b.y), 2.0 - 1e-9);  // behind the north wall
    }
  }
  EXPECT_EQ(lintels, 1);
  EXPECT_EQ(room_walls, 3);
}

TEST(BuildSurfaces, WallPiecesKnowTheirOffsetAlongTheWall) {
  World world = test::RectangleCorridor();
  Door door;
  door.wall_index = 0;
  door.offset_m = 4.0;
  door.open = true;
  world.doors.push_back(door);
  BuildSurfaces(world);
  bool found_second_piece = false;
  for (const Surface& s : world.surfaces) {
    if (s.wall_index == 0 && s.z_min_m == 0 && s.wall_offset_at_a_m > 0) {
      found_second_piece = true;
      EXPECT_NEAR(s.wall_offset_at_a_m, 4.45, 1e-9);
      EXPECT_NEAR(s.segment.a.x, 4.45, 1e-9);
    }
  }
  EXPECT_TRUE(found_second_piece);
}

TEST(World, SignPositionAndCorridorNormal) {
  World world = test::RectangleCorridor();
  TextSign sign;
  sign.wall_index = 1;
  sign.offset_m = 3.0;
  world.signs.push_back(sign);
  const Vec2 p = world.SignPosition(world.signs[0]);
  EXPECT_NEAR(p.x, 3.0, 1e-12);
  EXPECT_NEAR(p.y, 2.0, 1e-12);
  const Vec2 n = world.CorridorNormal(1);
  EXPECT_NEAR(n.y, -1.0, 1e-12);  // north wall faces south, into the corridor
  EXPECT_NEAR(world.CorridorNormal(0).y, 1.0, 1e-12);
  EXPECT_EQ(world.Plates().size(), 1u);
}

TEST(World, LightingGainIsOneOutsideZonesAndRampsInsideAndAtSoftEdges) {
  World world;
  EXPECT_DOUBLE_EQ(world.LightingGain({3.0, 1.0}), 1.0);
  LightZone dark;  // x 10..20: gain 0.4 at x = 10 rising to 1.6 at x = 20, 1 m soft edge
  dark.min = {10.0, -1.0};
  dark.max = {20.0, 3.0};
  dark.gain = 0.4;
  dark.gain_at_max = 1.6;
  dark.edge_m = 1.0;
  world.lighting.push_back(dark);
  EXPECT_DOUBLE_EQ(world.LightingGain({5.0, 1.0}), 1.0);
  EXPECT_NEAR(world.LightingGain({10.0, 1.0}), 0.4, 1e-12);
  EXPECT_NEAR(world.LightingGain({15.0, 1.0}), 1.0, 1e-12);
  EXPECT_NEAR(world.LightingGain({20.0, 1.0}), 1.6, 1e-12);
  EXPECT_NEAR(world.LightingGain({9.5, 1.0}), 0.7, 1e-12);  // half way through the edge: half the effect
  EXPECT_DOUBLE_EQ(world.LightingGain({8.9, 1.0}), 1.0);
  LightZone bright;  // overlapping zones multiply
  bright.min = {0.0, -1.0};
  bright.max = {12.0, 3.0};
  bright.gain = bright.gain_at_max = 2.0;
  world.lighting.push_back(bright);
  EXPECT_NEAR(world.LightingGain({10.0, 1.0}), 0.8, 1e-12);
}

}  // namespace
}  // namespace doorplate_localization

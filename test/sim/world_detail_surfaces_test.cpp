// Corridor detail as the sensors see it: door recesses and frames, clutter boxes and glass (BuildSurfaces
// with src/sim/world_detail_surfaces.cpp; glass returns via GlassReturnsBeam in the laser).
#include <gtest/gtest.h>

#include <cmath>

#include "doorplate_localization/sim/camera_renderer.h"
#include "doorplate_localization/sim/clutter_presets.h"
#include "doorplate_localization/sim/laser_simulator.h"
#include "test_worlds.h"

namespace doorplate_localization {
namespace {

int BeamAt(const LaserScan& scan, double angle_rad) {
  const double from_first = std::fmod(angle_rad - scan.angle_min_rad + 4 * M_PI, 2 * M_PI);
  return static_cast<int>(std::lround(from_first / scan.angle_increment_rad)) % static_cast<int>(scan.ranges_m.size());
}

LaserOptions Exact(int beams = 3600) {
  LaserOptions o;
  o.num_beams = beams;
  return o;
}

// The range straight right (towards the south wall, y = 0) from (x, 1).
double RangeDown(const World& world, double x) {
  const LaserScan scan = LaserSimulator(Exact()).CastExact(world, {x, 1.0, 0.0});
  return scan.ranges_m[BeamAt(scan, -M_PI / 2)];
}

TEST(WorldDetail, RecessedDoorAndFrameShowAsStepsAlongTheWall) {
  World world = test::RectangleCorridor(10.0, 2.0);
  Door door;
  door.id = "d";
  door.wall_index = 0;  // south
  door.offset_m = 5.0;
  door.recess_m = 0.05;
  door.frame_width_m = 0.07;
  door.frame_depth_m = 0.03;
  world.doors.push_back(door);
  BuildSurfaces(world);
  EXPECT_NEAR(RangeDown(world, 3.0), 1.0, 1e-4);          // plain wall
  EXPECT_NEAR(RangeDown(world, 5.0), 1.05, 1e-4);         // the leaf, 5 cm behind the wall line
  EXPECT_NEAR(RangeDown(world, 5.0 - 0.48), 0.97, 1e-4);  // a jamb, 3 cm out of the wall
  EXPECT_NEAR(RangeDown(world, 5.0 + 0.48), 0.97, 1e-4);
  // Flush doors (the default) leave the wall plain.
  world.doors[0].recess_m = world.doors[0].frame_width_m = world.doors[0].frame_depth_m = 0.0;
  BuildSurfaces(world);
  EXPECT_NEAR(RangeDown(world, 5.0), 1.0, 1e-4);
  EXPECT_EQ(world.surfaces.size(), 4u);
}

TEST(WorldDetail, LaserSeesABenchsLegsButNotItsSeat) {
  World world = test::RectangleCorridor(10.0, 2.0);
  ClutterItem bench{"b", "bench", {5.0, 0.3, 0.0}, {}};  // 1.5 m along x, 0.45 m deep, centred at y = 0.3
  bench.boxes = ClutterPresetBoxes(*FindClutterPreset("bench"), 0.0, 0.0, std::nullopt);
  world.clutter.push_back(bench);
  BuildSurfaces(world);
  // Front legs: 0.05 m posts inset 0.05 m, front face at y = 0.3 + 0.225 - 0.05 = 0.475.
  EXPECT_NEAR(RangeDown(world, 5.0 - 0.75 + 0.075), 1.0 - 0.475, 1e-4);
  EXPECT_NEAR(RangeDown(world, 5.0), 1.0, 1e-4);  // between the legs: under the seat to the wall
  // A laser mounted at seat height sees the seat's front instead.
  LaserOptions seat = Exact();
  seat.mount_height_m = 0.45;
  const LaserScan scan = LaserSimulator(seat).CastExact(world, {5.0, 1.0, 0.0});
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, -M_PI / 2)], 1.0 - 0.525, 1e-4);
}

World CorridorWithGlassAcross(double reflect_probability, std::uint64_t seed = 0) {
  World world = test::RectangleCorridor(10.0, 2.0);
  GlassPanel glass;
  glass.segment = {{5.0, 0.0}, {5.0, 2.0}};  // across the corridor
  glass.laser_reflect_probability = reflect_probability;
  glass.frame_width_m = 0.0;
  glass.seed = seed;
  world.glass.push_back(glass);
  BuildSurfaces(world);
  return world;
}

// Fraction of the beams crossing the glass that return from it, over many poses: a beam crosses the glass
// where the opaque pane (probability 1) is nearer than what lies behind it (probability 0).
double GlassReturnFraction(double reflect_probability, int* crossing) {
  const World glass = CorridorWithGlassAcross(reflect_probability);
  const World opaque = CorridorWithGlassAcross(1.0), clear = CorridorWithGlassAcross(0.0);
  const LaserSimulator laser(Exact(360));
  int returned = 0;
  *crossing = 0;
  for (int k = 0; k < 80; ++k) {
    const Pose2D pose{2.0 + 0.013 * k, 0.6 + 0.0097 * k, 0.01 * k};
    const auto r = laser.CastExact(glass, pose).ranges_m, r1 = laser.CastExact(opaque, pose).ranges_m,
               r0 = laser.CastExact(clear, pose).ranges_m;
    for (size_t i = 0; i < r.size(); ++i) {
      if (!(r1[i] < r0[i])) continue;
      ++*crossing;
      returned += r[i] == r1[i];
    }
  }
  return static_cast<double>(returned) / *crossing;
}

TEST(WorldDetail, GlassPassesMostBeamsAndReflectsSomeDeterministically) {
  int crossing = 0;
  EXPECT_NEAR(GlassReturnFraction(0.1, &crossing), 0.1, 0.02);
  EXPECT_GT(crossing, 3000);
  EXPECT_EQ(GlassReturnFraction(0.0, &crossing), 0.0);
  EXPECT_NEAR(GlassReturnFraction(0.6, &crossing), 0.6, 0.03);
  // The same pose gives the same scan; another seed, other beams.
  const World a = CorridorWithGlassAcross(0.5, 1), b = CorridorWithGlassAcross(0.5, 2);
  const LaserSimulator laser(Exact(360));
  EXPECT_EQ(laser.CastExact(a, {2.0, 1.0, 0.0}).ranges_m, laser.CastExact(a, {2.0, 1.0, 0.0}).ranges_m);
  EXPECT_NE(laser.CastExact(a, {2.0, 1.0, 0.0}).ranges_m, laser.CastExact(b, {2.0, 1.0, 0.0}).ranges_m);
  // A beam that passes goes on to the end wall.
  const LaserScan scan = laser.CastExact(CorridorWithGlassAcross(0.0), {2.0, 1.0, 0.0});
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, 0.0)], 8.0, 1e-4);
}

TEST(WorldDetail, CameraSeesThroughGlassTintedAndClutterHidesTheWall) {
  World world = test::RectangleCorridor(10.0, 2.0);
  world.walls[1].color = {200, 60, 60};  // north wall red
  GlassPanel glass;
  glass.segment = {{3.0, 1.5}, {7.0, 1.5}};  // in front of the north wall
  glass.z_max_m = 2.6;
  glass.tint = {60, 60, 220};
  glass.camera_opacity = 0.3;
  world.glass.push_back(glass);
  BuildSurfaces(world);
  CameraOptions options;
  options.pitch_deg = 0.0;
  const CameraRenderer camera(world, options);
  const cv::Vec3b through = camera.RenderClean({5.0, 0.5, 0.0}).at<cv::Vec3b>(240, 320);  // BGR
  EXPECT_GT(through[2], through[0]);  // still mostly the red wall...
  EXPECT_GT(through[0], 60);          // ...with blue from the glass
  // A plant between the camera and the wall hides it.
  world.glass.clear();
  ClutterItem plant{"p", "plant", {5.0, 1.2, 0.0}, {}};
  plant.boxes = ClutterPresetBoxes(*FindClutterPreset("plant"), 0.0, 0.0, std::nullopt);
  world.clutter.push_back(plant);
  BuildSurfaces(world);
  const CameraRenderer camera2(world, options);
  const cv::Vec3b leaves = camera2.RenderClean({5.0, 0.5, 0.0}).at<cv::Vec3b>(240, 320);
  EXPECT_GT(leaves[1], leaves[2]);  // green foliage, not the red wall
}

}  // namespace
}  // namespace doorplate_localization

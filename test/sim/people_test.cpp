#include "doorplate_localization/sim/people.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "doorplate_localization/sim/ground_truth_maps.h"
#include "doorplate_localization/sim/laser_simulator.h"
#include "doorplate_localization/sim/simulator.h"
#include "test_worlds.h"

namespace doorplate_localization {
namespace {

Person Walker(bool loop = false) {
  Person p;
  p.waypoints = {{2.0, 1.0}, {8.0, 1.0}};
  p.speed_mps = 1.0;
  p.loop = loop;
  return p;
}

TEST(PersonAt, WalksTheWaypointsBackAndForthAtItsSpeed) {
  Person p = Walker();
  EXPECT_NEAR(PersonAt(p, 0.0).position.x, 2.0, 1e-9);
  EXPECT_NEAR(PersonAt(p, 2.5).position.x, 4.5, 1e-9);
  EXPECT_NEAR(PersonAt(p, 2.5).heading_rad, 0.0, 1e-9);
  EXPECT_NEAR(PersonAt(p, 8.0).position.x, 6.0, 1e-9);  // on the way back
  EXPECT_NEAR(std::fabs(PersonAt(p, 8.0).heading_rad), M_PI, 1e-9);
  EXPECT_NEAR(PersonAt(p, 12.0 + 2.5).position.x, 4.5, 1e-9);  // a cycle is 12 s
  EXPECT_NEAR(PersonAt(p, 8.0).walked_m, 8.0, 1e-9);
}

TEST(PersonAt, PausesAtWaypointsAndStartsAtItsOffset) {
  Person p = Walker();
  p.pause_s = 2.0;
  EXPECT_NEAR(PersonAt(p, 7.0).position.x, 8.0, 1e-9);  // arrived at 6 s, stands until 8 s
  EXPECT_TRUE(PersonAt(p, 7.0).standing);
  EXPECT_NEAR(PersonAt(p, 9.0).position.x, 7.0, 1e-9);
  EXPECT_FALSE(PersonAt(p, 9.0).standing);
  p.pause_s = 0.0;
  p.start_offset_s = 3.0;
  EXPECT_NEAR(PersonAt(p, 0.0).position.x, 5.0, 1e-9);
}

TEST(PersonAt, LoopGoesFromTheLastWaypointBackToTheFirst) {
  Person p = Walker(true);
  p.waypoints = {{0, 0}, {4, 0}, {4, 3}};  // 4 + 3 + 5 = 12 m round
  EXPECT_NEAR(PersonAt(p, 5.5).position.y, 1.5, 1e-9);
  EXPECT_NEAR(PersonAt(p, 9.5).position.x, 4.0 - 0.8 * 2.5, 1e-9);  // 2.5 m along the closing leg
  EXPECT_NEAR(PersonAt(p, 12.0).position.x, 0.0, 1e-9);
}

TEST(People, LegsSwingWithTheGaitAndStandTogetherWhenPaused) {
  Person p = Walker();
  std::vector<Surface> quarter, standing;
  PersonState walking = PersonAt(p, 0.35);  // 0.35 m walked: a quarter of the 1.4 m stride
  AppendPersonSurfaces(p, walking, &quarter);
  ASSERT_EQ(quarter.size(), 2u * 8u + 8u);
  const auto leg_x = [](const std::vector<Surface>& s, int leg) {
    double x = 0.0;
    for (int k = 0; k < 8; ++k) x += s[leg * 8 + k].segment.a.x / 8.0;
    return x;
  };
  EXPECT_NEAR(leg_x(quarter, 1) - leg_x(quarter, 0), 2 * 0.18, 1e-6);  // full swing apart
  walking.standing = true;
  AppendPersonSurfaces(p, walking, &standing);
  EXPECT_NEAR(leg_x(standing, 1) - leg_x(standing, 0), 0.0, 1e-9);
  for (const Surface& s : quarter) EXPECT_EQ(s.kind, SurfaceKind::kPerson);
}

World CorridorWithWalker() {
  World world = test::RectangleCorridor(10.0, 2.0);
  world.people.push_back(Walker());
  return world;
}

TEST(People, LaserSeesTheLegsMoveWithSimulatedTime) {
  SimulatorOptions options;
  options.seed = 3;
  Simulator sim(CorridorWithWalker(), options);
  LaserOptions exact = sim.world().sensors.laser;
  const LaserSimulator laser(exact);
  // The robot at (1, 1) looks along +x at the walker's line (between the legs: the nearest of ±10 beams).
  const auto ahead = [&]() {
    const LaserScan scan = laser.CastExact(sim.world(), sim.true_pose());
    return *std::min_element(scan.ranges_m.begin() + 170, scan.ranges_m.begin() + 191);
  };
  const double at_start = ahead();
  for (int i = 0; i < 300; ++i) sim.Step();  // 3 s
  sim.Scan();                               // moves the people to 3 s
  const double later = ahead();
  EXPECT_LT(at_start, 1.2);         // legs at x ≈ 2
  EXPECT_GT(later, at_start + 2.0); // legs near x ≈ 5
  EXPECT_LT(later, 4.5);
}

TEST(People, GroundTruthGridLeavesPeopleOut) {
  World world = CorridorWithWalker();
  const OccupancyGrid empty = RasterizeWorld(world, 0.05, 0.25);
  PlacePeople(world, 0.0);
  ASSERT_GT(world.surfaces.size(), world.num_static_surfaces);
  const OccupancyGrid with_people = RasterizeWorld(world, 0.05, 0.25);
  EXPECT_EQ(with_people.cells, empty.cells);
  int x = 0, y = 0;
  with_people.WorldToCell({2.0, 1.09}, &x, &y);  // a leg's centre
  EXPECT_EQ(with_people.At(x, y), OccupancyGrid::kFree);
}

TEST(People, PlacePeopleKeepsTheStaticSurfaces) {
  World world = CorridorWithWalker();
  const std::size_t n = world.surfaces.size();
  PlacePeople(world, 1.0);
  PlacePeople(world, 2.0);
  EXPECT_EQ(world.surfaces.size(), n + 24u);
  EXPECT_EQ(world.num_static_surfaces, n);
}

}  // namespace
}  // namespace doorplate_localization

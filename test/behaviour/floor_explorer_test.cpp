#include "doorplate_localization/behaviour/floor_explorer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "../sim/test_worlds.h"
#include "doorplate_localization/sim/simulator.h"

namespace doorplate_localization {
namespace {

// Plates every `spacing_m` along every wall, `clear_m` clear of its ends (doors are not built into the
// square where two corridors meet; the end wall of a dead end gets none: the camera turns away from it);
// texts 101, 102, ...
void AddPlates(World& world, double spacing_m, double clear_m) {
  int number = 101;
  for (int w = 0; w < static_cast<int>(world.walls.size()); ++w) {
    const double length = world.walls[w].segment.Length();
    for (double offset = clear_m; offset <= length - clear_m + 1e-9; offset += spacing_m) {
      TextSign plate;
      plate.text = std::to_string(number++);
      plate.wall_index = w;
      plate.offset_m = offset;
      plate.corridor_side_left = world.walls[w].corridor_side_left;
      world.signs.push_back(plate);
    }
  }
  BuildSurfaces(world);
}

// An L: a 14 m leg along x and a 10 m leg north at its east end, both 2 m wide (a tree: no loop).
World LWorld() {
  World world = test::LCorridor(14.0, 12.0);
  world.start_pose = {1.0, 0.6, 0.0};
  AddPlates(world, 3.0, 1.5);  // plates 1.5 m from the dead end's wall
  return world;
}

// A ring of 2 m corridors round a 12 m × 8 m block, with a 6 m dead-end branch off the outer south wall.
World RingWorld() {
  World world;
  test::AddWallPolygon(world, {{0, 0}, {6, 0}, {6, -6}, {8, -6}, {8, 0}, {16, 0}, {16, 12}, {0, 12}}, "outer");
  test::AddWallPolygon(world, {{2, 2}, {2, 10}, {14, 10}, {14, 2}}, "block");
  world.start_pose = {1.5, 0.6, 0.0};
  AddPlates(world, 3.0, 3.0);  // 1 m clear of where the corridors meet
  return world;
}

struct ExploreRun {
  std::vector<int> reads;           // per plate (world.signs order): times read
  std::vector<PassEnd> pass_ends;   // why each pass ended
  bool done = false;
  bool bumped = false;
  double distance_m = 0.0;
  Pose2D end_pose;
};

// Closed loop in the Simulator (physics 100 Hz, laser and explorer 10 Hz, odometry as the pose). A plate
// counts as read when its projection crosses the image's centre column within 4 m, as the tracker does; the
// explorer hears of it `read_delay_s` later (the text extractor's latency), stamped with the crossing time.
ExploreRun Explore(const World& world, FloorExplorerOptions options, double max_time_s = 1500.0,
                   double read_delay_s = 0.0) {
  Simulator sim(world, SimulatorOptions{});
  FloorExplorer explorer(options);
  ExploreRun run;
  run.reads.assign(world.signs.size(), 0);
  std::vector<double> last_dx(world.signs.size(), NAN);
  const CameraIntrinsics& k = sim.camera().intrinsics();
  int last_pass = 1;
  std::deque<std::pair<double, std::string>> reported;  // (crossing time, text), in order
  for (int step = 0; sim.time_s() < max_time_s; ++step) {
    while (!reported.empty() && reported.front().first + read_delay_s <= sim.time_s() + 1e-9) {
      explorer.OnPlateRead(reported.front().second, reported.front().first);
      reported.pop_front();
    }
    if (step % 10 == 0) {
      const LaserScan scan = sim.Scan();
      const VelocityCommand cmd = explorer.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad,
                                                sim.odom_pose(), sim.time_s());
      if (explorer.pass() != last_pass || explorer.phase() == ExplorePhase::kDone) {
        if (run.pass_ends.size() < static_cast<std::size_t>(explorer.pass() - (explorer.phase() == ExplorePhase::kDone ? 0 : 1))) {
          run.pass_ends.push_back(explorer.last_pass_end());
        }
        last_pass = explorer.pass();
      }
      if (explorer.phase() == ExplorePhase::kDone) break;
      sim.SetCommand(cmd.linear_mps, cmd.angular_rps);
      for (std::size_t i = 0; i < world.signs.size(); ++i) {
        const TextSign& sign = world.signs[i];
        const Vec2 p = world.SignPosition(sign);
        cv::Point2d px;
        const bool visible = Norm(p - sim.true_pose().Position()) < 4.0 &&
                             sim.camera().Project(sim.true_pose(), {p.x, p.y, sign.center_height_m}, &px) &&
                             px.y >= 0 && px.y < k.height_px && px.x >= 0 && px.x < k.width_px;
        const double dx = visible ? px.x - k.cx_px : NAN;
        if (std::isfinite(dx) && std::isfinite(last_dx[i]) && (dx >= 0) != (last_dx[i] >= 0)) {
          ++run.reads[i];
          reported.emplace_back(sim.time_s(), sign.text);
        }
        last_dx[i] = dx;
      }
    }
    sim.Step();
    run.bumped = run.bumped || sim.bumped();
  }
  run.done = explorer.phase() == ExplorePhase::kDone;
  run.distance_m = explorer.distance_m();
  run.end_pose = sim.true_pose();
  return run;
}

// Plates never read, as "text@wall" for the failure message.
std::string UnreadPlates(const World& world, const ExploreRun& run) {
  std::string out;
  for (std::size_t i = 0; i < run.reads.size(); ++i) {
    if (run.reads[i] == 0) out += world.signs[i].text + "@" + world.walls[world.signs[i].wall_index].id + " ";
  }
  return out;
}

int Unread(const ExploreRun& run) {
  int n = 0;
  for (const int r : run.reads) n += r == 0;
  return n;
}

// Done without bumping, every plate read, and both passes ended because known plates were read again.
void ExpectCoveredAndEndedByPlates(const World& world, const ExploreRun& run) {
  ASSERT_TRUE(run.done);
  EXPECT_FALSE(run.bumped);
  EXPECT_EQ(Unread(run), 0) << UnreadPlates(world, run);
  ASSERT_EQ(run.pass_ends.size(), 2u);
  EXPECT_EQ(run.pass_ends[0], PassEnd::kPlatesRevisited);
  EXPECT_EQ(run.pass_ends[1], PassEnd::kPlatesRevisited);
}

TEST(FloorExplorer, OnAnLShapedFloorReadsEveryPlateAndEndsBecauseThePlatesRepeat) {
  const World world = LWorld();
  const ExploreRun run = Explore(world, FloorExplorerOptions{});
  ASSERT_NO_FATAL_FAILURE(ExpectCoveredAndEndedByPlates(world, run));
  // Pass 1 is both legs out and back (~2 × 22 m); pass 2 stops once it re-reads known plates.
  EXPECT_GT(run.distance_m, 40.0);
  EXPECT_LT(run.distance_m, 90.0);
}

TEST(FloorExplorer, RoundARingWithABranchReadsBothWallsOfEveryCorridorAndClosesTheLoopTwice) {
  const World world = RingWorld();
  const ExploreRun run = Explore(world, FloorExplorerOptions{});
  ASSERT_NO_FATAL_FAILURE(ExpectCoveredAndEndedByPlates(world, run));
  int read_twice = 0;
  for (const int r : run.reads) read_twice += r >= 2;
  EXPECT_GE(read_twice, 4);  // the first plates of each pass, re-read where the loop closes
  EXPECT_LT(Norm(run.end_pose.Position() - world.start_pose.Position()), 8.0);
}

TEST(FloorExplorer, APlateReportedSecondsLateStillEndsThePassInTheCorridorItStartedIn) {
  // The branch leaves the start corridor just after the plates that close pass 1: reported late, they end
  // the pass while the robot is already in the branch, where turning round would re-trace pass 1.
  const World world = RingWorld();
  for (const double delay_s : {2.0, 5.0}) {
    const ExploreRun run = Explore(world, FloorExplorerOptions{}, 1500.0, delay_s);
    SCOPED_TRACE("read delay " + std::to_string(delay_s) + " s");
    ASSERT_NO_FATAL_FAILURE(ExpectCoveredAndEndedByPlates(world, run));
  }
}

TEST(FloorExplorer, TurnsInTheStartCorridorDespiteTheOdometrysHeadingDrift) {
  // 0.01 rad of heading drift per metre: the odometry's heading is ~0.7 rad off after pass 1, so the start
  // corridor's heading as first measured is no longer where to turn; the re-read plates show the drift.
  World world = RingWorld();
  world.sensors.odometry.heading_drift_rad_per_m = 0.01;
  const ExploreRun run = Explore(world, FloorExplorerOptions{}, 1500.0, 3.0);
  ASSERT_NO_FATAL_FAILURE(ExpectCoveredAndEndedByPlates(world, run));
}

TEST(FloorExplorer, OnePassFollowsOnlyOneWallOfTheRing) {
  const World world = RingWorld();
  FloorExplorerOptions options;
  options.passes = 1;
  const ExploreRun run = Explore(world, options);
  ASSERT_TRUE(run.done);
  // The outer walls' plates face the corridor from the right of a robot following them: unread.
  EXPECT_GT(Unread(run), 5);
}

TEST(FloorExplorer, WithoutPlatesAPassEndsWhereItStarted) {
  FloorExplorerOptions options;
  options.passes = 1;
  const ExploreRun run = Explore(test::RectangleCorridor(12, 2), options);
  ASSERT_TRUE(run.done);
  ASSERT_EQ(run.pass_ends.size(), 1u);
  EXPECT_EQ(run.pass_ends[0], PassEnd::kPoseRevisited);
  EXPECT_GT(run.distance_m, 18.0);  // out along one wall, back along the other
  EXPECT_LT(run.distance_m, 30.0);
}

TEST(FloorExplorer, APlateReadAgainSoonAfterIsNotARevisit) {
  FloorExplorerOptions options;
  options.revisit_plates = 1;
  FloorExplorer explorer(options);
  const World world = test::RectangleCorridor(40, 2);
  const LaserScan scan = LaserSimulator(LaserOptions{}).CastExact(world, {5, 0.6, 0});
  explorer.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, {0, 0, 0});
  explorer.OnPlateRead("E14-295");
  explorer.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, {5, 0, 0});
  explorer.OnPlateRead("e14 295");  // the same room, 5 m later: the tracker's second look
  EXPECT_EQ(explorer.phase(), ExplorePhase::kFollow);
  explorer.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, {25, 0, 0});
  EXPECT_EQ(explorer.last_pass_end(), PassEnd::kNotEnded);
  explorer.OnPlateRead("E14295");
  EXPECT_EQ(explorer.last_pass_end(), PassEnd::kPlatesRevisited);
  EXPECT_EQ(explorer.pass(), 1);  // the turn round waits for a straight stretch
  EXPECT_EQ(explorer.plates_known(), 1);
}

// Scans of a 40 m corridor seen along it (the steering drives straight on) and at 0.5 rad to it (the
// steering turns, as in a corner); Drive feeds one of them at every 0.1 m, 0.4 m/s, as the pose goes along x.
struct ScanFixture {
  LaserScan straight = LaserSimulator(LaserOptions{}).CastExact(test::RectangleCorridor(40, 2), {5, 0.6, 0});
  LaserScan corner = LaserSimulator(LaserOptions{}).CastExact(test::RectangleCorridor(40, 2), {5, 0.6, 0.5});
  void Drive(FloorExplorer& explorer, const LaserScan& scan, double from_m, double to_m, double t0_s) const {
    for (double x = from_m; x <= to_m + 1e-9; x += 0.1) {
      explorer.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad, {x, 0, 0}, t0_s + x / 0.4);
    }
  }
};

TEST(FloorExplorer, KnownPlatesSeenWhileTurningACornerDoNotEndThePass) {
  const ScanFixture f;
  FloorExplorer explorer(FloorExplorerOptions{});
  f.Drive(explorer, f.straight, 0.0, 2.0, 0.0);
  explorer.OnPlateRead("201");
  explorer.OnPlateRead("202");
  f.Drive(explorer, f.straight, 2.1, 30.0, 0.0);
  f.Drive(explorer, f.corner, 30.1, 31.0, 0.0);  // the camera sweeps over the plates of the way in
  explorer.OnPlateRead("201");
  explorer.OnPlateRead("202");
  EXPECT_EQ(explorer.last_pass_end(), PassEnd::kNotEnded);
}

TEST(FloorExplorer, APlateIsJudgedWhereTheCameraSawItNotWhereItsReportArrives) {
  const ScanFixture f;
  FloorExplorer seen_on_straight(FloorExplorerOptions{});
  FloorExplorer seen_in_corner(FloorExplorerOptions{});
  for (FloorExplorer* e : {&seen_on_straight, &seen_in_corner}) {
    f.Drive(*e, f.straight, 0.0, 2.0, 0.0);
    e->OnPlateRead("201");
    e->OnPlateRead("202");
    f.Drive(*e, f.straight, 2.1, 30.0, 0.0);
  }
  // Seen at 30 m on the straight, reported after the robot has reached a corner.
  f.Drive(seen_on_straight, f.corner, 30.1, 32.0, 0.0);
  seen_on_straight.OnPlateRead("201", 29.9 / 0.4);
  seen_on_straight.OnPlateRead("202", 30.0 / 0.4);
  EXPECT_EQ(seen_on_straight.last_pass_end(), PassEnd::kPlatesRevisited);
  // Seen in a corner at 31 m, reported once the robot drives straight again.
  f.Drive(seen_in_corner, f.corner, 30.1, 31.0, 0.0);
  f.Drive(seen_in_corner, f.straight, 31.1, 34.0, 0.0);
  seen_in_corner.OnPlateRead("201", 30.9 / 0.4);
  seen_in_corner.OnPlateRead("202", 31.0 / 0.4);
  EXPECT_EQ(seen_in_corner.last_pass_end(), PassEnd::kNotEnded);
}

TEST(FloorExplorer, RejectsInvalidOptionsNamingTheField) {
  FloorExplorerOptions o;
  o.passes = 0;
  try {
    FloorExplorer e(o);
    FAIL() << "accepted passes = 0";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("passes"), std::string::npos);
  }
  o = {};
  o.steering.look_ahead_m = -1;
  EXPECT_THROW(FloorExplorer e(o), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/slam/slam_back_end.h"

#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "slam_back_end_test_fixtures.h"
#include "slam_test_worlds.h"

namespace doorplate_localization {
namespace {

using test::PointsAt;
using test::RoomRun;

// A 2 m wide, 40 m long corridor along x (0 to 40 m), closed at both ends.
std::vector<Segment> Corridor40() {
  return {{{-0.025, -1.025}, {40.025, -1.025}}, {{-0.025, 1.025}, {40.025, 1.025}},
          {{-0.025, -1.025}, {-0.025, 1.025}}, {{40.025, -1.025}, {40.025, 1.025}}};
}

// A straight run down Corridor40 from x = 1 m to 39 m, a node every 0.5 m, whose odometry measures
// every distance 2% too long; the front end is fed the odometry. Returns the true poses.
std::vector<Pose2D> FeedLongOdometryRun(SlamBackEnd& back_end) {
  std::vector<Pose2D> truth;
  for (double x = 1.0; x <= 39.0 + 1e-9; x += 0.5) truth.push_back({x, 0, 0});
  for (const Pose2D& pose : truth) {
    const Pose2D odometry{1.0 + 1.02 * (pose.x_m - 1.0), 0, 0};
    back_end.AddNode(PointsAt(Corridor40(), pose), odometry, odometry);
  }
  return truth;
}

TEST(SlamBackEnd, ACorridorRunWithTooLongOdometryIsRescaledByTheEndWalls) {
  SlamBackEnd back_end{SlamBackEndOptions{}};
  const std::vector<Pose2D> truth = FeedLongOdometryRun(back_end);
  ASSERT_EQ(back_end.num_nodes(), 77);
  const SlamBackEndResult result = back_end.Optimize();
  ASSERT_EQ(result.poses.size(), truth.size());
  EXPECT_TRUE(result.summary.solver_ok);
  EXPECT_GE(result.alignment_edges, 76 + 75);  // at least offsets 1 and 2 everywhere
  EXPECT_EQ(result.loop_closures, 0);         // a straight run never comes back
  EXPECT_NEAR(result.odometry_scale, 1.0 / 1.02, 0.005);
  const double error_m = std::abs(result.poses.back().x_m - truth.back().x_m);
  EXPECT_LT(error_m, 0.15);  // dead reckoning: 0.76 m
  for (const Pose2D& pose : result.poses) EXPECT_NEAR(pose.y_m, 0.0, 0.02);

  SlamBackEndOptions fixed_scale;
  fixed_scale.graph.estimate_odometry_scale = false;
  SlamBackEnd without_scale(fixed_scale);
  FeedLongOdometryRun(without_scale);
  const SlamBackEndResult unscaled = without_scale.Optimize();
  EXPECT_NEAR(unscaled.odometry_scale, 1.0, 1e-6);
  const double unscaled_error_m = std::abs(unscaled.poses.back().x_m - truth.back().x_m);
  EXPECT_GT(unscaled_error_m, 0.15);
  EXPECT_GT(unscaled_error_m, 2 * error_m);
}

TEST(SlamBackEnd, NodePointsCanBeReplacedUntilAnAlignmentUsedThem) {
  SlamBackEnd back_end(SlamBackEndOptions{});
  back_end.AddNode(PointsAt(Corridor40(), {1, 0, 0}), {1, 0, 0}, {1, 0, 0});
  back_end.AddNode({}, {1.5, 0, 0}, {1.5, 0, 0});  // no echoes yet: the node cannot be aligned
  EXPECT_THROW(back_end.ReplaceNodePoints(2, {}), std::invalid_argument);
  back_end.ReplaceNodePoints(1, PointsAt(Corridor40(), {1.5, 0, 0}));  // now it can
  const SlamBackEndResult solved = back_end.Optimize();
  EXPECT_GE(solved.alignment_edges, 1);
  EXPECT_NEAR(solved.poses.at(1).x_m, 1.5, 0.01);
  EXPECT_THROW(back_end.ReplaceNodePoints(1, {}), std::logic_error);
}

// A solve in the middle of a run leaves a node whose points are still being refined (pending_node) out of
// the alignments: its points can still be replaced, and the next solve aligns it.
TEST(SlamBackEnd, APendingNodeTakesNoAlignmentUntilTheNextSolve) {
  SlamBackEnd back_end(SlamBackEndOptions{});
  back_end.AddNode(PointsAt(Corridor40(), {1, 0, 0}), {1, 0, 0}, {1, 0, 0});
  back_end.AddNode(PointsAt(Corridor40(), {1.5, 0.02, 0}), {1.5, 0, 0}, {1.5, 0, 0});  // rough points
  const SlamBackEndResult first = back_end.Optimize({}, /*pending_node=*/1);
  EXPECT_EQ(first.alignment_edges, 0);
  ASSERT_EQ(first.poses.size(), 2u);  // in the graph all the same (odometry holds it)
  EXPECT_NEAR(first.poses[1].x_m, 1.5, 1e-6);
  back_end.ReplaceNodePoints(1, PointsAt(Corridor40(), {1.5, 0, 0}));  // refined: no logic_error
  const SlamBackEndResult second = back_end.Optimize();
  EXPECT_GE(second.alignment_edges, 1);
  EXPECT_NEAR(second.poses[1].y_m, 0.0, 0.005);  // aligned with the refined points
  EXPECT_THROW(back_end.ReplaceNodePoints(1, {}), std::logic_error);
  EXPECT_THROW(back_end.Optimize({}, /*pending_node=*/1), std::invalid_argument);  // aligned already
  EXPECT_THROW(back_end.Optimize({}, /*pending_node=*/2), std::invalid_argument);  // no such node
}

TEST(SlamBackEnd, APlateReadFromTwoNodesBecomesOneLandmarkAtItsPlace) {
  SlamBackEnd back_end{SlamBackEndOptions{}};
  const std::vector<Pose2D> truth = RoomRun();
  for (const Pose2D& pose : truth) back_end.AddNode(PointsAt(test::Room(), pose), pose, pose);
  const Vec2 plate{-3.0, 0.5};  // on the west wall
  back_end.AddPlateReading(2, 0, truth[0].Inverse().TransformPoint(plate));
  back_end.AddPlateReading(2, 3, truth[3].Inverse().TransformPoint(plate));

  const SlamBackEndResult result = back_end.Optimize();
  EXPECT_EQ(result.plate_readings, 2);
  ASSERT_EQ(result.plates.size(), 3u);  // indexed by plate id
  EXPECT_FALSE(result.plates[0].has_value());
  EXPECT_FALSE(result.plates[1].has_value());
  ASSERT_TRUE(result.plates[2].has_value());
  EXPECT_NEAR(result.plates[2]->x, plate.x, 0.02);
  EXPECT_NEAR(result.plates[2]->y, plate.y, 0.02);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    EXPECT_LT(Norm(result.poses[i].Position() - truth[i].Position()), 0.02) << "node " << i;
  }
}

// Two nodes 1 m apart in the featureless corridor (the laser fixes only y and heading), whose noisy
// odometry says 1.3 m; a plate on the left wall at x = 0.5 m read from `readers` of them.
SlamBackEndResult DriftedPairReading(const std::vector<int>& readers) {
  SlamBackEndOptions options;
  options.odometry_trans_m2_per_m = 0.1;  // σ ≈ 0.36 m over 1.3 m, the readings' 5 cm far surer
  options.plate_sigma_m = 0.05;
  options.graph.estimate_odometry_scale = false;
  SlamBackEnd back_end(options);
  const std::vector<Pose2D> truth = {{0, 0, 0}, {1, 0, 0}}, odometry = {{0, 0, 0}, {1.3, 0, 0}};
  for (int i = 0; i < 2; ++i) back_end.AddNode(PointsAt(test::Corridor(), truth[i]), odometry[i], odometry[i]);
  const Vec2 plate{0.5, 1};
  for (int i : readers) back_end.AddPlateReading(0, i, truth[i].Inverse().TransformPoint(plate));
  return back_end.Optimize();
}

TEST(SlamBackEnd, TwoReadingsOfAPlatePullADriftedOdometryTogether) {
  const SlamBackEndResult both = DriftedPairReading({1, 0});  // the first reading starts the landmark off
  EXPECT_EQ(both.alignment_edges, 1);
  ASSERT_EQ(both.plates.size(), 1u);
  ASSERT_TRUE(both.plates[0].has_value());
  EXPECT_NEAR(both.poses[1].x_m, 1.0, 0.03);  // information 200 (plates) against 7.7 (odometry)
  EXPECT_NEAR(both.poses[1].y_m, 0.0, 0.01);
  EXPECT_LT(Norm(*both.plates[0] - Vec2{0.5, 1}), 0.03);
  // Read once, the plate says nothing about node 1, which stays where the odometry put it.
  EXPECT_NEAR(DriftedPairReading({0}).poses[1].x_m, 1.3, 0.01);
}

TEST(SlamBackEnd, AnAlignmentFarFromItsOdometryIsDroppedAsAFalseMatch) {
  // The odometry says 0.3 m forward; the scans were taken 0.8 m apart. In the room the alignment finds the
  // 0.8 m, 0.5 m from its odometry guess: far outside the gate (5σ ≈ 0.12 m over 0.3 m), so it is dropped.
  const std::vector<Pose2D> truth = {{0, 0, 0}, {0.8, 0, 0}};
  const std::vector<Pose2D> odometry = {{0, 0, 0}, {0.3, 0, 0}};
  const auto run = [&](double gate_sigmas) {
    SlamBackEndOptions options;
    options.sequential_gate_sigmas = gate_sigmas;
    // Ungated, the consistency check would drop it as well (the odometry contradicts it by ~11σ of its own
    // information): off here, to show what the gate prevents.
    if (gate_sigmas == 0.0) options.sequential_max_residual_sigmas = 0.0;
    SlamBackEnd back_end(options);
    for (int i = 0; i < 2; ++i) back_end.AddNode(PointsAt(test::Room(), truth[i]), odometry[i], odometry[i]);
    return back_end.Optimize();
  };
  const SlamBackEndResult gated = run(5.0);
  EXPECT_EQ(gated.alignment_edges, 0);
  EXPECT_NEAR(gated.poses[1].x_m, 0.3, 0.05);  // odometry alone
  const SlamBackEndResult ungated = run(0.0);
  EXPECT_EQ(ungated.alignment_edges, 1);
  // The laser's 0.8 m then pulls the node off the odometry's 0.3 m, as far as its Huber kernel lets it (here
  // the laser was right; on real logs such disagreements were mostly false matches: flipped or slid scans,
  // docs/slam.md).
  EXPECT_GT(ungated.poses[1].x_m, 0.38);
}

// 30 nodes that leave node 0's place and come back to it; only the first and the last have a scan (no
// sequential alignment links them), the odometry ends 2 m off (beyond loop_closure_radius_m), the front
// end's poses are right.
// `pinned(i)`: whether node i's front-end pose was pinned by its scan match.
SlamBackEndResult RunLoopWithLostOdometry(const std::function<bool(int)>& pinned) {
  SlamBackEnd back_end{SlamBackEndOptions{}};
  constexpr int kNodes = 30;
  for (int i = 0; i < kNodes; ++i) {
    const double t = 2 * M_PI * i / (kNodes - 1);
    const Pose2D truth{std::sin(t), 1 - std::cos(t), 0};
    const Pose2D odometry{truth.x_m + 2.0 * i / (kNodes - 1), truth.y_m, 0};
    const bool ends = i == 0 || i == kNodes - 1;
    back_end.AddNode(ends ? PointsAt(test::Room(), truth) : std::vector<Vec2>{}, odometry, truth, pinned(i));
  }
  return back_end.Optimize();
}

TEST(SlamBackEnd, TheFrontEndsPosesProposeTheLoopClosuresTheOdometryLost) {
  const SlamBackEndResult pinned = RunLoopWithLostOdometry([](int) { return true; });
  EXPECT_EQ(pinned.loop_closures, 1);
  EXPECT_LT(std::hypot(pinned.poses.back().x_m, pinned.poses.back().y_m), 0.05);
  // A front end whose matches were degenerate (its poses came from odometry) proposes none...
  const SlamBackEndResult unpinned = RunLoopWithLostOdometry([](int) { return false; });
  EXPECT_EQ(unpinned.loop_closures, 0);
  EXPECT_GT(std::hypot(unpinned.poses.back().x_m, unpinned.poses.back().y_m), 1.5);
  // ...nor does one pinned scan amid degenerate ones (front_end_pinned_neighbours: 1 on each side).
  const SlamBackEndResult isolated = RunLoopWithLostOdometry([](int i) { return i == 0 || i == 29; });
  EXPECT_EQ(isolated.loop_closures, 0);
  const SlamBackEndResult stretches = RunLoopWithLostOdometry([](int i) { return i <= 3 || i >= 26; });
  EXPECT_EQ(stretches.loop_closures, 1);
}

// Down Corridor40 and back (x 1 -> 21 m, a node every 0.5 m, turning round at the far end) with exact
// odometry and 2 cm range noise (seeded). The front end's poses are right on the way out and
// `return_offset_m` off along the corridor on the way back (-4: a laser-only filter that shrank the
// corridor puts the robot 4 m nearer the start), so the loop closures it proposes start from a guess that
// far off, where an alignment cannot tell the places apart and keeps the guess.
void FeedOutAndBack(double return_offset_m, SlamBackEnd* back_end) {
  std::mt19937 random(7);
  std::normal_distribution<double> noise_m(0.0, 0.02);
  std::vector<Pose2D> truth;
  for (double x = 1.0; x <= 21.0 + 1e-9; x += 0.5) truth.push_back({x, -0.3, 0});
  for (double turn = M_PI / 4; turn <= M_PI + 1e-9; turn += M_PI / 4) truth.push_back({21.0, 0.0, turn});
  for (double x = 20.5; x >= 1.0 - 1e-9; x -= 0.5) truth.push_back({x, 0.3, M_PI});
  const int out_nodes = 41;
  for (int i = 0; i < static_cast<int>(truth.size()); ++i) {
    LaserScan scan = test::Scan(Corridor40(), truth[i], test::kBackEndBeams, test::kBackEndMaxRangeM);
    for (float& r : scan.ranges_m) r += static_cast<float>(noise_m(random));
    const double offset_m = i < out_nodes ? 0.0 : return_offset_m;
    back_end->AddNode(test::Points(scan), truth[i], {truth[i].x_m + offset_m, truth[i].y_m, truth[i].theta_rad});
  }
}

SlamBackEndResult OutAndBackWithTheReturnOffBy(double return_offset_m) {
  SlamBackEnd back_end{SlamBackEndOptions{}};
  FeedOutAndBack(return_offset_m, &back_end);
  return back_end.Optimize();
}

TEST(SlamBackEnd, LoopClosuresProposedMetresOffAlongACorridorAreMeasuredAgainFromTheSolution) {
  // The same scans and odometry: where the front end thought the robot was on the way back must not
  // matter once the graph has solved it (the closures are aligned again from the solution). Measured
  // where they were proposed, the closures carried the metres along the corridor into the graph, and the
  // little information left along it turned the map (here up to 0.018 rad; paper corridor seed 4: 0.009 rad).
  const SlamBackEndResult exact = OutAndBackWithTheReturnOffBy(0.0);
  const SlamBackEndResult shrunk = OutAndBackWithTheReturnOffBy(-4.0);
  ASSERT_EQ(exact.poses.size(), shrunk.poses.size());
  EXPECT_GT(exact.loop_closures, 20);
  EXPECT_GT(shrunk.loop_closures, 20);
  for (size_t i = 0; i < exact.poses.size(); ++i) {
    SCOPED_TRACE("node " + std::to_string(i));
    EXPECT_NEAR(shrunk.poses[i].x_m, exact.poses[i].x_m, 0.01);
    EXPECT_NEAR(shrunk.poses[i].y_m, exact.poses[i].y_m, 0.01);
    EXPECT_NEAR(NormalizeAngle(shrunk.poses[i].theta_rad - exact.poses[i].theta_rad), 0.0, 0.001);
  }
}

TEST(SlamBackEnd, ASecondSolveOfTheSameNodesReusesItsLoopAlignmentsAndGivesTheSameResult) {
  SlamBackEnd back_end{SlamBackEndOptions{}};
  FeedOutAndBack(-4.0, &back_end);
  const SlamBackEndResult first = back_end.Optimize();
  EXPECT_GT(first.loop_alignments_computed, 20);
  EXPECT_EQ(first.loop_alignments_reused, 0);
  const SlamBackEndResult second = back_end.Optimize();  // same nodes: the same guesses, to the bit
  EXPECT_EQ(second.loop_alignments_computed, 0);
  EXPECT_EQ(second.loop_alignments_reused, first.loop_alignments_computed);
  EXPECT_EQ(second.loop_closures, first.loop_closures);
  ASSERT_EQ(second.poses.size(), first.poses.size());
  for (size_t i = 0; i < first.poses.size(); ++i) {
    EXPECT_EQ(second.poses[i].x_m, first.poses[i].x_m) << "node " << i;
    EXPECT_EQ(second.poses[i].y_m, first.poses[i].y_m) << "node " << i;
    EXPECT_EQ(second.poses[i].theta_rad, first.poses[i].theta_rad) << "node " << i;
  }
}

// Two look-alike rooms 10 m apart (test::Room and a copy shifted along x): 30 nodes drive from the first
// room's centre to the second's with exact odometry; only the first and the last have a scan, and they are
// the same scan. The front end confused the rooms: it put the last node back at the first (pinned), so its
// poses propose a loop closure that ICP confirms (identical scans) and the odometry contradicts.
SlamBackEndResult RunIntoALookAlikeRoom(double max_residual_sigmas) {
  SlamBackEndOptions options;
  options.loop_closure_max_residual_sigmas = max_residual_sigmas;
  // With no scans in between, a free odometry scale would shrink the 10 m to nothing (nothing else
  // measures distance here) and so agree with the closure.
  options.graph.estimate_odometry_scale = false;
  SlamBackEnd back_end(options);
  std::vector<Segment> second = test::Room();
  for (Segment& wall : second) wall = {{wall.a.x + 10, wall.a.y}, {wall.b.x + 10, wall.b.y}};
  constexpr int kNodes = 30;
  for (int i = 0; i < kNodes; ++i) {
    const Pose2D truth{10.0 * i / (kNodes - 1), 0, 0};
    const bool last = i == kNodes - 1;
    const std::vector<Vec2> points = i == 0 ? PointsAt(test::Room(), truth) : last ? PointsAt(second, truth)
                                                                                   : std::vector<Vec2>{};
    back_end.AddNode(points, truth, last ? Pose2D{0, 0, 0} : truth);
  }
  return back_end.Optimize();
}

TEST(SlamBackEnd, ALoopClosureTheRestOfTheGraphContradictsIsDroppedAsAFalseMatch) {
  const SlamBackEndResult checked = RunIntoALookAlikeRoom(9.0);
  EXPECT_EQ(checked.loop_closures, 0);
  EXPECT_EQ(checked.loop_closures_dropped, 1);
  EXPECT_NEAR(checked.poses.back().x_m, 10.0, 0.05);
  // Unchecked, the closure's Huber kernel bounds its pull but does not remove it: the odometry's 10 m bend.
  const SlamBackEndResult unchecked = RunIntoALookAlikeRoom(0.0);
  EXPECT_EQ(unchecked.loop_closures, 1);
  EXPECT_EQ(unchecked.loop_closures_dropped, 0);
  EXPECT_LT(unchecked.poses.back().x_m, 9.5);
}

TEST(SlamBackEnd, APlateReadingAtANodeThatDoesNotExistThrows) {
  SlamBackEnd back_end{SlamBackEndOptions{}};
  EXPECT_THROW(back_end.AddPlateReading(0, 0, {1, 1}), std::invalid_argument);  // no node yet
  back_end.AddNode(PointsAt(test::Room(), {0, 0, 0}), {0, 0, 0}, {0, 0, 0});
  back_end.AddNode(PointsAt(test::Room(), {0.2, 0, 0}), {0.2, 0, 0}, {0.2, 0, 0});
  EXPECT_NO_THROW(back_end.AddPlateReading(0, 1, {1, 1}));
  EXPECT_THROW(back_end.AddPlateReading(0, 2, {1, 1}), std::invalid_argument);
  EXPECT_THROW(back_end.AddPlateReading(0, -1, {1, 1}), std::invalid_argument);
  EXPECT_THROW(back_end.AddPlateReading(-1, 0, {1, 1}), std::invalid_argument);
  EXPECT_EQ(back_end.Optimize().plate_readings, 1);
}

// FeedLongOdometryRun's corridor run (odometry 2% long), the front end's pose at each node the truth and
// pinned as `pinned` says, solved with edges from a front-end history that puts every node at
// x = 1 + 0.99 (x_true - 1): the history's own shape, 1% shorter than the truth.
SlamBackEndResult CorridorRunWithAShortHistory(bool pinned, std::vector<Pose2D>* history) {
  SlamBackEndOptions options;
  options.front_end_history_sigma_m = 0.005;
  options.front_end_history_sigma_rad = 0.0025;
  SlamBackEnd back_end(options);
  history->clear();
  for (double x = 1.0; x <= 39.0 + 1e-9; x += 0.5) {
    const Pose2D truth{x, 0, 0};
    const Pose2D odometry{1.0 + 1.02 * (x - 1.0), 0, 0};
    back_end.AddNode(PointsAt(Corridor40(), truth), odometry, truth, pinned);
    history->push_back({1.0 + 0.99 * (x - 1.0), 0, 0});
  }
  return back_end.Optimize(*history);
}

TEST(SlamBackEnd, HistoryEdgesHoldConsecutivePinnedNodesToTheFrontEndsTrajectory) {
  std::vector<Pose2D> history;
  const SlamBackEndResult pinned = CorridorRunWithAShortHistory(true, &history);
  ASSERT_EQ(pinned.poses.size(), history.size());
  // The solve keeps the history's shape (its 37.62 m from the first node to the last), not the scans' 38 m.
  const double solved_length = pinned.poses.back().x_m - pinned.poses.front().x_m;
  EXPECT_NEAR(solved_length, history.back().x_m - history.front().x_m, 0.02);
  // Unpinned nodes (a degenerate front end) take no history edge: the end walls and odometry decide.
  const SlamBackEndResult unpinned = CorridorRunWithAShortHistory(false, &history);
  EXPECT_NEAR(unpinned.poses.back().x_m - unpinned.poses.front().x_m, 38.0, 0.15);
}

TEST(SlamBackEnd, AHistoryWithoutOnePosePerNodeThrows) {
  SlamBackEndOptions options;
  options.front_end_history_sigma_m = 0.005;
  options.front_end_history_sigma_rad = 0.0025;
  SlamBackEnd back_end(options);
  back_end.AddNode(PointsAt(test::Room(), {0, 0, 0}), {0, 0, 0}, {0, 0, 0});
  back_end.AddNode(PointsAt(test::Room(), {0.3, 0, 0}), {0.3, 0, 0}, {0.3, 0, 0});
  try {
    back_end.Optimize({{0, 0, 0}});
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("front_end_history has 1 poses for 2 nodes"), std::string::npos) << e.what();
  }
  // With the option off the history is not used and need not be given.
  SlamBackEnd plain{SlamBackEndOptions{}};
  plain.AddNode(PointsAt(test::Room(), {0, 0, 0}), {0, 0, 0}, {0, 0, 0});
  EXPECT_NO_THROW(plain.Optimize());
}

}  // namespace
}  // namespace doorplate_localization

// MappingSession's solves: periodic ones (map_update_interval_s, map_update_max_solve_share) and what they
// may not change. A second test file of mapping_session.cpp (mapping_session_test.cpp holds the other rules).
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "doorplate_localization/slam/mapping_session.h"
#include "slam_test_worlds.h"

namespace doorplate_localization {
namespace {

TEST(MappingSession, MapUpdateIntervalSolvesAfterProcessedScansThatFarApartInStampTime) {
  MappingSessionOptions o;  // few particles: these tests are about solves, not the filter
  o.slam.slam.num_particles = 3;
  o.map_update_interval_s = 4.0;
  MappingSession session(o);
  int solves = 0;
  double t = 0.0;
  for (const Pose2D& p : test::PosesAlongX(0.0, 5.0, 0.5)) {  // one processed scan per second, 0..10 s
    const MappingUpdate u = session.AddScan(t, p, test::Scan(test::ClosedCorridor(), p, 360, 16.0));
    ASSERT_TRUE(u.scan_processed);
    if (u.solved) {
      ++solves;
      EXPECT_TRUE(t == 0.0 || t == 4.0 || t == 8.0) << t;
      EXPECT_EQ(session.slam().nodes_since_solve(), 0);
    }
    t += 1.0;
  }
  EXPECT_EQ(solves, 3);
  ASSERT_TRUE(session.Map().has_value());
}

TEST(MappingSession, ASolveShareDefersPeriodicSolvesByWallClockAndLeavesTheFinalSolveAsIs) {
  MappingSessionOptions o;  // few particles: these tests are about solves, not the filter
  o.slam.slam.num_particles = 3;
  o.map_update_interval_s = 4.0;
  MappingSession free_running(o);
  o.map_update_max_solve_share = 0.25;
  MappingSession shared(o);
  double now = 0.0;
  shared.SetWallClock([&now] { return now++; });  // every reading of the clock takes 1 s: a solve takes 1 s
  std::vector<double> solved_at;
  double t = 0.0;
  for (const Pose2D& p : test::PosesAlongX(0.0, 5.0, 0.5)) {  // one processed scan per second, 0..10 s
    const LaserScan scan = test::Scan(test::ClosedCorridor(), p, 360, 16.0);
    free_running.AddScan(t, p, scan);
    if (shared.AddScan(t, p, scan).solved) solved_at.push_back(t);
    t += 1.0;
  }
  // t = 0 solves (1 s), so the next waits 3 s of wall clock: due at t = 4 and 5 but deferred, solved at 6;
  // due again at 10, deferred.
  EXPECT_EQ(solved_at, (std::vector<double>{0.0, 6.0}));
  EXPECT_EQ(shared.counters().solves_deferred, 3);
  EXPECT_EQ(shared.counters().last_solve_wall_s, 1.0);
  EXPECT_EQ(free_running.counters().solves, 3);
  // The filter never saw the solves: the final solve gives the same map either way.
  ASSERT_TRUE(free_running.Solve().solved && shared.Solve().solved);
  EXPECT_EQ(free_running.Map()->cells, shared.Map()->cells);
  EXPECT_EQ(free_running.Trajectory().back().x_m, shared.Trajectory().back().x_m);
}

// The solves of a live run, periodic (after nearly every processed scan) or asked for (the nodelet's
// ~save_maps, here every 2 s), against none: after Flush() the final Solve() is the same to the bit. Scans every
// 0.1 m with 1 cm range noise, so node fusion (3 scans before and after within 0.3 m) refines every node; a
// solve that finished the newest node's fusion early (with the scans before it only, as before 2026-12-07)
// gave that node other points and the map another turn.
TEST(MappingSession, SolvesDuringTheRunLeaveTheFinalSolveAsWithoutThem) {
  MappingSessionOptions o;  // few particles: these tests are about solves, not the filter
  o.slam.slam.num_particles = 5;
  MappingSession final_only(o), saved(o);
  o.map_update_interval_s = 0.5;
  MappingSession periodic(o);
  std::mt19937 rng(7);
  std::normal_distribution<float> noise(0.0f, 0.01f);
  double t = 0.0;
  int step = 0;
  for (const Pose2D& truth : test::PosesAlongX(0.0, 10.0, 0.1)) {
    LaserScan scan = test::Scan(test::ClosedCorridor(), truth, 360, 16.0);
    for (float& r : scan.ranges_m) r += noise(rng);
    const Pose2D odometry{1.02 * truth.x_m, 0.0, 0.0};
    for (MappingSession* session : {&final_only, &saved, &periodic}) session->AddScan(t, odometry, scan);
    if (++step % 20 == 7) saved.Solve();
    t += 0.1;
  }
  ASSERT_GE(periodic.counters().solves, 10);
  ASSERT_GE(saved.counters().solves, 4);
  ASSERT_EQ(final_only.counters().solves, 0);
  for (MappingSession* session : {&final_only, &saved, &periodic}) {
    session->Flush();
    ASSERT_TRUE(session->Solve().solved);
  }
  const std::vector<Pose2D> a = final_only.Trajectory();
  ASSERT_GE(a.size(), 15u);
  for (const MappingSession* session : {&saved, &periodic}) {
    const std::vector<Pose2D> b = session->Trajectory();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].x_m, b[i].x_m) << "node " << i;
      EXPECT_EQ(a[i].y_m, b[i].y_m) << "node " << i;
      EXPECT_EQ(a[i].theta_rad, b[i].theta_rad) << "node " << i;
    }
    EXPECT_EQ(final_only.Map()->cells, session->Map()->cells);
  }
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/slam/mapping_session.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "slam_test_worlds.h"

namespace doorplate_localization {
namespace {

MappingSessionOptions FewParticles(int n) {
  MappingSessionOptions o;
  o.slam.slam.num_particles = n;
  return o;
}

PlateReading Sighting(const std::string& text, double bearing_rad, std::optional<double> range_m = std::nullopt) {
  PlateReading s;
  s.text = text;
  s.confidence = 0.9;
  s.bearing_rad = bearing_rad;
  s.range_m = range_m;
  return s;
}

// Drives the closed corridor (odometry 2 % long), one scan per 0.5 m and 1 s, a plate read half-way.
// `between` is called after every input (to poke getters in).
template <typename Between>
void DriveCorridor(MappingSession* session, Between between) {
  double t = 0.0;
  for (const Pose2D& truth : test::PosesAlongX(0.0, 20.0, 0.5)) {
    const Pose2D odometry{1.02 * truth.x_m, 0.0, 0.0};
    session->AddScan(t, odometry, test::Scan(test::ClosedCorridor(), truth, 360, 16.0));
    between();
    if (truth.x_m == 10.0) {
      session->AddPlates(t + 0.1, odometry, {Sighting("120", M_PI / 2)});
      between();
    }
    t += 1.0;
  }
}

TEST(MappingSession, ProcessesAScanOnlyOnceTheRobotMovedOrTurnedTheUpdateThreshold) {
  MappingSessionOptions o = FewParticles(3);
  o.slam.slam.linear_update_m = 0.5;
  o.slam.slam.angular_update_rad = 0.25;
  MappingSession session(o);
  const auto scan_at = [&](double t, const Pose2D& p) {
    return session.AddScan(t, p, test::Scan(test::Room(), p)).scan_processed;
  };
  EXPECT_TRUE(scan_at(0.0, {0, 0, 0}));     // the first scan starts the map
  EXPECT_FALSE(scan_at(0.1, {0.2, 0, 0}));
  EXPECT_FALSE(scan_at(0.2, {0.4, 0, 0}));
  EXPECT_TRUE(scan_at(0.3, {0.6, 0, 0}));   // 0.6 m since the last processed scan
  EXPECT_FALSE(scan_at(0.4, {0.6, 0, 0.2}));
  EXPECT_TRUE(scan_at(0.5, {0.6, 0, 0.3}));  // turned 0.3 rad
  EXPECT_EQ(session.counters().scans_processed, 3);
  EXPECT_EQ(session.processed_scan_indices(), (std::vector<int>{0, 3, 5}));
  EXPECT_EQ(session.Trajectory().size(), 3u);
}

TEST(MappingSession, ThrottleScansTakesEveryNthScanGiven) {
  MappingSessionOptions o = FewParticles(3);
  o.throttle_scans = 3;
  o.slam.slam.linear_update_m = 0.0;  // every taken scan is processed
  MappingSession session(o);
  int taken = 0;
  for (int i = 0; i < 7; ++i) {
    const Pose2D p{0.1 * i, 0, 0};
    taken += session.AddScan(0.1 * i, p, test::Scan(test::Room(), p)).scan_taken ? 1 : 0;
  }
  EXPECT_EQ(taken, 3);  // calls 0, 3, 6
  EXPECT_EQ(session.processed_scan_indices(), (std::vector<int>{0, 3, 6}));
  EXPECT_EQ(session.slam().slam().stats().scans_seen, 3);
}

TEST(MappingSession, TemporalUpdateProcessesAStandingRobotsScansThatOften) {
  for (const double temporal_s : {-1.0, 1.0}) {
    MappingSessionOptions o = FewParticles(3);
    o.temporal_update_s = temporal_s;
    MappingSession session(o);
    for (int i = 0; i <= 8; ++i) session.AddScan(0.25 * i, {}, test::Scan(test::Room(), {}));
    if (temporal_s > 0) {
      EXPECT_EQ(session.processed_scan_indices(), (std::vector<int>{0, 4, 8})) << "at 0, 1 and 2 s";
    } else {
      EXPECT_EQ(session.processed_scan_indices(), (std::vector<int>{0})) << "off: a standing robot maps once";
    }
  }
}

TEST(MappingSession, AScanNotAfterThePreviousOneIsRefusedAndChangesNothing) {
  MappingSession session(FewParticles(3));
  session.AddScan(1.0, {}, test::Scan(test::Room(), {}));
  for (const double stamp : {1.0, 0.5}) {
    const MappingUpdate u = session.AddScan(stamp, {1, 0, 0}, test::Scan(test::Room(), {1, 0, 0}));
    EXPECT_FALSE(u.scan_taken);
    EXPECT_FALSE(u.scan_processed);
    EXPECT_NE(u.scan_refused_reason.find("not after the previous scan"), std::string::npos) << u.scan_refused_reason;
  }
  EXPECT_EQ(session.counters().scans_refused, 2);
  EXPECT_EQ(session.slam().slam().stats().scans_seen, 1);
  EXPECT_TRUE(session.AddScan(2.0, {1, 0, 0}, test::Scan(test::Room(), {1, 0, 0})).scan_processed);
  EXPECT_THROW(session.AddScan(NAN, {}, test::Scan(test::Room(), {})), std::invalid_argument);
  EXPECT_THROW(session.AddScan(3.0, {NAN, 0, 0}, test::Scan(test::Room(), {})), std::invalid_argument);
  EXPECT_THROW(session.AddScan(3.0, {}, LaserScan{}), std::invalid_argument);
  EXPECT_EQ(session.slam().slam().stats().scans_seen, 2);
}

// Two scans 0.5 m apart across the room (y = 0, then y = 0.5): the south wall is 2.025 m, then 2.525 m away.
TEST(MappingSession, ASightingTakesItsRangeFromTheScanNearestItsStampEvenWhenItArrivesLate) {
  MappingSession session(FewParticles(3));
  session.AddScan(0.0, {0, 0, 0}, test::Scan(test::Room(), {0, 0, 0}));
  session.AddScan(1.0, {0, 0.5, 0}, test::Scan(test::Room(), {0, 0.5, 0}));
  // Read at 0.1 s (arriving after the 1 s scan), when the robot was still at y = 0.
  const MappingUpdate late = session.AddPlates(0.1, {0, 0, 0}, {Sighting("201", -M_PI / 2)});
  ASSERT_EQ(late.plates.size(), 1u);
  ASSERT_TRUE(late.plates[0].result.used()) << late.plates[0].result.reason;
  EXPECT_NEAR(*late.plates[0].sighting.range_m, 2.025, 0.01);
  // Placed where the robot was at its stamp: on the south wall below x = 0.
  const std::vector<SlamLandmark> plates = session.slam().BestLandmarks();
  ASSERT_EQ(plates.size(), 1u);
  EXPECT_NEAR(plates[0].position.y, -2.025, 0.05);
  // Read at 0.9 s: the newer scan is nearer in time.
  const MappingUpdate on_time = session.AddPlates(0.9, {0, 0.5, 0}, {Sighting("203", -M_PI / 2)});
  EXPECT_NEAR(*on_time.plates[0].sighting.range_m, 2.525, 0.01);
  // Read at 6 s, 5 s after the newest scan: the scans near its stamp have not arrived yet, so it waits...
  const MappingUpdate held = session.AddPlates(6.0, {0, 0.5, 0}, {Sighting("205", -M_PI / 2)});
  EXPECT_TRUE(held.plates.empty());
  EXPECT_EQ(held.plates_held, 1);
  EXPECT_EQ(session.held_plates(), 1u);
  // ...for the first scan at or after its stamp; this one is 4 s later: no scan is close enough in time for a
  // range, and the reason says which rule failed, with the stamps (a scan late behind a solve vs. no echo).
  const MappingUpdate decided = session.AddScan(10.0, {0, 0.5, 0}, test::Scan(test::Room(), {0, 0.5, 0}));
  ASSERT_EQ(decided.plates.size(), 1u);
  EXPECT_EQ(session.held_plates(), 0u);
  EXPECT_EQ(decided.plates[0].result.outcome, PlateOutcome::kNoRange);
  EXPECT_NE(decided.plates[0].result.reason.find("no scan within 0.50 s of the reading's stamp 6.00 s (nearest 10.00 s"),
            std::string::npos)
      << decided.plates[0].result.reason;
  // Read at 1.0 s looking straight up at nothing (an open side beyond the laser's range): no echo there.
  MappingSession open_side(FewParticles(3));
  open_side.AddScan(0.0, {0, 0, 0}, test::Scan({{{-3, -2}, {3, -2}}}, {0, 0, 0}));
  const MappingUpdate no_echo = open_side.AddPlates(0.0, {0, 0, 0}, {Sighting("209", M_PI / 2)});
  EXPECT_EQ(no_echo.plates[0].result.outcome, PlateOutcome::kNoRange);
  EXPECT_NE(no_echo.plates[0].result.reason.find("no echo within"), std::string::npos) << no_echo.plates[0].result.reason;
  // A given range is kept.
  const MappingUpdate given = session.AddPlates(6.0, {0, 0.5, 0}, {Sighting("207", -M_PI / 2, 1.5)});
  EXPECT_EQ(*given.plates[0].sighting.range_m, 1.5);
  EXPECT_EQ(session.counters().plates_used, 3);
}

// A person stands between the robot and the plate when it is read: the echoes along the bearing hit the
// person; the plate hangs on the wall behind, whose line the echoes either side trace.
TEST(MappingSession, APlateReadPastSomeoneStandingBeforeItTakesTheWallsRange) {
  std::vector<Segment> world = test::Corridor();
  const std::vector<Segment> person = {{{-0.25, -0.4}, {0.25, -0.4}}, {{0.25, -0.4}, {0.25, -0.7}},
                                       {{0.25, -0.7}, {-0.25, -0.7}}, {{-0.25, -0.7}, {-0.25, -0.4}}};
  world.insert(world.end(), person.begin(), person.end());
  const auto read_with = [&](double margin_m) {
    MappingSessionOptions o = FewParticles(3);
    o.slam.plate_range.occluded_margin_m = margin_m;
    MappingSession session(o);
    session.AddScan(0.0, {0, 0, 0}, test::Scan(world, {0, 0, 0}));
    const MappingUpdate u = session.AddPlates(0.0, {0, 0, 0}, {Sighting("201", -M_PI / 2)});
    EXPECT_TRUE(u.plates.at(0).result.used()) << u.plates.at(0).result.reason;
    return std::make_pair(*u.plates.at(0).sighting.range_m, session.counters().plate_ranges_from_wall);
  };
  const auto [wall_range, from_wall] = read_with(0.15);
  EXPECT_NEAR(wall_range, 1.025, 0.01);
  EXPECT_EQ(from_wall, 1);
  const auto [person_range, off] = read_with(0.0);  // the rule off: the echoes along the bearing
  EXPECT_NEAR(person_range, 0.4, 0.01);
  EXPECT_EQ(off, 0);
  // No one before the plate: the echoes along the bearing, and the count stays 0.
  MappingSession clear(FewParticles(3));
  clear.AddScan(0.0, {0, 0, 0}, test::Scan(test::Corridor(), {0, 0, 0}));
  EXPECT_NEAR(*clear.AddPlates(0.0, {0, 0, 0}, {Sighting("201", -M_PI / 2)}).plates.at(0).sighting.range_m, 1.025, 0.01);
  EXPECT_EQ(clear.counters().plate_ranges_from_wall, 0);
}

// Live, the laser callbacks can fall behind (queued behind a back-end solve) while a detection arrives on
// time; a bag replays them in that recorded order. The sighting must still get its range from the scan
// nearest its stamp once that scan arrives.
TEST(MappingSession, ASightingArrivingBeforeTheScansNearItsStampWaitsForThemAndGetsItsRange) {
  MappingSession session(FewParticles(3));
  session.AddScan(0.0, {0, 0, 0}, test::Scan(test::Room(), {0, 0, 0}));
  const MappingUpdate held = session.AddPlates(0.9, {0, 0.5, 0}, {Sighting("203", -M_PI / 2)});
  EXPECT_TRUE(held.plates.empty());
  EXPECT_EQ(held.plates_held, 1);
  // A scan before its stamp does not decide it (a nearer one may follow)...
  EXPECT_TRUE(session.AddScan(0.5, {0, 0.25, 0}, test::Scan(test::Room(), {0, 0.25, 0})).plates.empty());
  EXPECT_EQ(session.held_plates(), 1u);
  // ...the first at or after it does; the range comes from the scan nearest its stamp (1.0 s, at y = 0.5).
  const MappingUpdate applied = session.AddScan(1.0, {0, 0.5, 0}, test::Scan(test::Room(), {0, 0.5, 0}));
  ASSERT_EQ(applied.plates.size(), 1u);
  ASSERT_TRUE(applied.plates[0].result.used()) << applied.plates[0].result.reason;
  EXPECT_EQ(applied.plates[0].stamp_s, 0.9);
  EXPECT_NEAR(*applied.plates[0].sighting.range_m, 2.525, 0.01);
  const std::vector<SlamLandmark> plates = session.slam().BestLandmarks();
  ASSERT_EQ(plates.size(), 1u);
  EXPECT_NEAR(plates[0].position.y, -2.025, 0.05);
  EXPECT_EQ(session.held_plates(), 0u);
  EXPECT_EQ(session.counters().plates_held, 1);
  EXPECT_EQ(session.counters().plates_used, 1);
}

TEST(MappingSession, HeldSightingsAreBoundedTheOldestIsAppliedWhenTheBoundIsReached) {
  MappingSession session(FewParticles(3));
  session.AddScan(0.0, {0, 0, 0}, test::Scan(test::Room(), {0, 0, 0}));
  for (std::size_t i = 0; i < MappingSession::kMaxHeldPlates; ++i) {
    ASSERT_EQ(session.AddPlates(5.0 + static_cast<double>(i), {0, 0, 0}, {Sighting("201", -M_PI / 2)}).plates_held, 1);
  }
  const MappingUpdate over = session.AddPlates(1000.0, {0, 0, 0}, {Sighting("203", -M_PI / 2)});
  ASSERT_EQ(over.plates.size(), 1u);  // the oldest (5 s) waits no longer: no scan near it
  EXPECT_EQ(over.plates[0].stamp_s, 5.0);
  EXPECT_EQ(over.plates[0].result.outcome, PlateOutcome::kNoRange);
  EXPECT_EQ(session.held_plates(), MappingSession::kMaxHeldPlates);
}

TEST(MappingSession, AMalformedSightingRefusesTheWholeCallNamingTheField) {
  MappingSession session(FewParticles(3));
  session.AddScan(0.0, {}, test::Scan(test::Room(), {}));
  try {
    session.AddPlates(0.0, {}, {Sighting("201", M_PI / 2), Sighting("203", NAN)});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("PlateReading.bearing_rad"), std::string::npos) << e.what();
  }
  EXPECT_EQ(session.slam().num_landmarks(), 0);
  EXPECT_EQ(session.counters().plate_sightings, 0);
}

TEST(MappingSession, GettersDoNotSolveTheBackEndOnlySolveDoes) {
  MappingSession session(FewParticles(5));
  DriveCorridor(&session, [] {});
  EXPECT_FALSE(session.BackEndResult().has_value());
  EXPECT_FALSE(session.Map().has_value());
  (void)session.slam().BuildOccupancyGrid();
  (void)session.slam().BuildTextMap();
  (void)session.Trajectory();
  EXPECT_FALSE(session.BackEndResult().has_value()) << "a getter solved the graph";
  EXPECT_EQ(session.slam().nodes_since_solve(), 41);
  const MappingUpdate u = session.Solve();
  EXPECT_TRUE(u.solved);
  EXPECT_EQ(session.slam().nodes_since_solve(), 0);
  EXPECT_EQ(session.counters().solves, 1);
}

TEST(MappingSession, AfterSolveTheGettersReturnTheSolve) {
  MappingSession session(FewParticles(5));
  DriveCorridor(&session, [] {});
  session.Solve();
  const SlamBackEndResult& solve = *session.BackEndResult();
  ASSERT_EQ(solve.poses.size(), 41u);
  const std::vector<Pose2D> trajectory = session.Trajectory();
  ASSERT_EQ(trajectory.size(), 41u);
  for (std::size_t i = 0; i < trajectory.size(); ++i) EXPECT_EQ(trajectory[i].x_m, solve.poses[i].x_m);
  ASSERT_EQ(session.GetTextMap().landmarks.size(), 1u);
  ASSERT_TRUE(solve.plates.at(0).has_value());
  EXPECT_EQ(session.GetTextMap().landmarks[0].pose.x_m, solve.plates[0]->x);
  EXPECT_NEAR(solve.plates[0]->x, 10.0, 0.2);
  // map -> odom takes the odometry at the last scan onto the solve's last pose.
  const Pose2D in_map = session.MapToOdom()->Compose(session.LastProcessedOdometry());
  EXPECT_NEAR(in_map.x_m, solve.poses.back().x_m, 1e-9);
  EXPECT_NEAR(in_map.theta_rad, solve.poses.back().theta_rad, 1e-9);
  // The stored map is the one the solve renders.
  const OccupancyGrid again = session.slam().BuildOccupancyGrid();
  EXPECT_EQ(session.Map()->cells, again.cells);
}

TEST(MappingSession, GettersCalledInAnyOrderAndNumberChangeNoResult) {
  MappingSession quiet(FewParticles(5)), poked(FewParticles(5));
  DriveCorridor(&quiet, [] {});
  int round = 0;
  DriveCorridor(&poked, [&] {
    // A different mix every time, up to three calls each.
    for (int k = 0; k <= round % 3; ++k) {
      if (poked.started()) (void)poked.PoseAtOdometry({1, 0, 0});
      (void)poked.slam().BuildTextMap();
      (void)poked.Trajectory();
      if (round % 2 == 0 && poked.started()) (void)poked.slam().BuildOccupancyGrid();
      (void)poked.slam().BestLandmarks();
      (void)poked.BackEndResult();
    }
    ++round;
  });
  quiet.Solve();
  poked.Solve();
  const std::vector<Pose2D> a = quiet.Trajectory(), b = poked.Trajectory();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x_m, b[i].x_m);
    EXPECT_EQ(a[i].y_m, b[i].y_m);
    EXPECT_EQ(a[i].theta_rad, b[i].theta_rad);
  }
  EXPECT_EQ(quiet.Map()->cells, poked.Map()->cells);
  EXPECT_EQ(TextMapToYaml(quiet.GetTextMap()), TextMapToYaml(poked.GetTextMap()));
  EXPECT_EQ(quiet.MapToOdom()->x_m, poked.MapToOdom()->x_m);
}

TEST(MappingSession, BadOptionsThrowNamingTheField) {
  MappingSessionOptions o;
  o.throttle_scans = 0;
  try {
    MappingSession s(o);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("MappingSessionOptions.throttle_scans"), std::string::npos) << e.what();
  }
  o = MappingSessionOptions{};
  o.map_update_interval_s = -1.0;
  EXPECT_THROW(MappingSession{o}, std::invalid_argument);
  o = MappingSessionOptions{};
  o.map_update_max_solve_share = 1.0;
  EXPECT_THROW(MappingSession{o}, std::invalid_argument);
  o = MappingSessionOptions{};
  o.slam.plate_sigma_m = 0.0;
  EXPECT_THROW(MappingSession{o}, std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/mcl/text_amcl_session.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "mcl_fixtures.h"

namespace doorplate_localization {
namespace {

// A 20 m symmetric corridor with its plates; the robot mid-corridor heading +x, a plate on its left.
struct Fixture {
  test::SymmetricCorridor corridor = test::MakeSymmetricCorridor(20.0);
  const TextLandmark& plate() const { return corridor.text_map->landmarks[corridor.NorthPlate(1)]; }
  Pose2D robot() const { return {plate().pose.x_m - 0.5, 1.0, 0.0}; }

  TextAmclSessionOptions Options() const {
    TextAmclSessionOptions o;
    o.setup.filter.max_particles = 500;
    o.setup.filter.random_seed = 7;
    o.initial_pose = robot();
    o.initial_covariance = Eigen::Vector3d(0.01, 0.01, 0.001).asDiagonal();
    return o;
  }
  TextAmclSession Make(const TextAmclSessionOptions& o, bool with_text_map = true) const {
    return TextAmclSession(o, corridor.occupancy, with_text_map ? corridor.text_map : nullptr);
  }
  LaserScan ScanAt(const Pose2D& p) const { return test::SyntheticScan(*corridor.grid, p); }
};

TEST(TextAmclSession, APlateReadBeforeAnyScanWaitsUntilOdometryReachesItsStampAndIsWeighedThere) {
  const Fixture f;
  TextAmclSession session = f.Make(f.Options());
  const PlateReading reading = test::ReadingOf(f.plate(), f.robot());
  const SessionUpdate queued = session.AddPlates(1.0, {reading});
  EXPECT_TRUE(queued.plates.empty());
  EXPECT_EQ(queued.plates_pending, 1);
  EXPECT_EQ(session.AddOdometry(0.5, {0.0, 0.0, 0.0}).plates_pending, 1);  // not yet at its stamp
  const SessionUpdate applied = session.AddOdometry(1.5, {1.0, 0.0, 0.0});
  ASSERT_EQ(applied.plates.size(), 1u);
  EXPECT_EQ(applied.plates[0].disposition, PlateDisposition::kWeighed);
  EXPECT_TRUE(applied.plates[0].result.used);
  EXPECT_EQ(applied.plates_pending, 0);
  EXPECT_EQ(session.Status().plate_updates, 1);
  // Weighed at the odometry interpolated at 1.0 s (x = 0.5), which map -> odom now refers to.
  ASSERT_TRUE(session.MapToOdom().has_value());
  const Pose2D at_reading = session.PoseAtOdometry({0.5, 0.0, 0.0});
  EXPECT_NEAR(at_reading.x_m, session.Estimate().pose.x_m, 1e-9);
  EXPECT_NEAR(at_reading.y_m, session.Estimate().pose.y_m, 1e-9);
}

TEST(TextAmclSession, APlateIsWeighedAfterTheFilterMovedToItsStampNotWhereTheLastScanLeftIt) {
  const Fixture f;
  TextAmclSession session = f.Make(f.Options());
  const Pose2D start = f.robot();
  ASSERT_TRUE(session.AddScan(0.0, {0.0, 0.0, 0.0}, f.ScanAt(start)).laser_used);
  // 0.15 m later (below update_min_d: no scan would move the filter) the plate is read.
  const Pose2D there = start.Compose({0.15, 0.0, 0.0});
  EXPECT_FALSE(session.AddScan(0.1, {0.15, 0.0, 0.0}, f.ScanAt(there)).laser_used);
  session.AddOdometry(0.15, {0.15, 0.0, 0.0});
  const SessionUpdate update = session.AddPlates(0.15, {test::ReadingOf(f.plate(), there)});
  ASSERT_EQ(update.plates.size(), 1u);
  EXPECT_NEAR(session.Estimate().pose.x_m, there.x_m, 0.08);
  // The next scan is weighed at its own stamp even without update_min_d of motion.
  EXPECT_TRUE(session.AddScan(0.2, {0.17, 0.0, 0.0}, f.ScanAt(start.Compose({0.17, 0.0, 0.0}))).laser_used);
}

TEST(TextAmclSession, AnUnknownRoomIsDroppedOnArrivalCountedAndReportedOnce) {
  const Fixture f;
  TextAmclSession session = f.Make(f.Options());  // no odometry yet: dropped all the same, not queued
  PlateReading unknown = test::ReadingOf(f.plate(), f.robot());
  unknown.text = "999";
  const SessionUpdate first = session.AddPlates(0.0, {unknown});
  const SessionUpdate second = session.AddPlates(0.0, {unknown});
  ASSERT_EQ(first.plates.size(), 1u);
  ASSERT_EQ(second.plates.size(), 1u);
  EXPECT_EQ(first.plates[0].disposition, PlateDisposition::kUnknownRoomFirst);
  EXPECT_EQ(second.plates[0].disposition, PlateDisposition::kUnknownRoom);
  EXPECT_EQ(session.counters().unknown_room_readings, 2);
  EXPECT_EQ(session.unknown_rooms().size(), 1u);
  EXPECT_EQ(first.plates_pending, 0);
  EXPECT_EQ(session.Status().plate_updates, 0);
  EXPECT_FALSE(first.estimate_changed);
}

// Issue 18: OCR garbage over a long run must not grow the remembered rooms without bound; past
// limits::kMaxRememberedUnknownRooms they are still counted (and reported as already seen), and a text
// longer than limits::kMaxPlateTextBytes is refused as invalid before it is matched or remembered.
TEST(TextAmclSession, RemembersAtMostTheLimitOfUnknownRoomsAndRefusesOverlongTexts) {
  const Fixture f;
  TextAmclSession session = f.Make(f.Options());
  PlateReading unknown = test::ReadingOf(f.plate(), f.robot());
  int first = 0;
  for (int i = 0; i < 1005; ++i) {
    unknown.text = std::to_string(900000 + i);
    const SessionUpdate u = session.AddPlates(0.0, {unknown});
    ASSERT_EQ(u.plates.size(), 1u);
    first += u.plates[0].disposition == PlateDisposition::kUnknownRoomFirst;
  }
  EXPECT_EQ(first, 1000);
  EXPECT_EQ(session.unknown_rooms().size(), 1000u);
  EXPECT_EQ(session.counters().unknown_room_readings, 1005);
  unknown.text.assign(1 << 20, '1');
  const SessionUpdate huge = session.AddPlates(0.0, {unknown});
  ASSERT_EQ(huge.plates.size(), 1u);
  EXPECT_EQ(huge.plates[0].disposition, PlateDisposition::kInvalid);
  EXPECT_NE(huge.plates[0].detail.find("1048576 bytes, more than the limit of 64"), std::string::npos);
  EXPECT_EQ(session.unknown_rooms().size(), 1000u);
}

TEST(TextAmclSession, ALaserOnlySessionDropsEveryReading) {
  const Fixture f;
  TextAmclSession session = f.Make(f.Options(), /*with_text_map=*/false);
  EXPECT_FALSE(session.has_text_map());
  session.AddOdometry(0.0, {});
  const SessionUpdate update = session.AddPlates(0.0, {test::ReadingOf(f.plate(), f.robot())});
  ASSERT_EQ(update.plates.size(), 1u);
  EXPECT_EQ(update.plates[0].disposition, PlateDisposition::kNoTextMap);
}

TEST(TextAmclSession, NoLaserUpdateBeforeUpdateMinDOrUpdateMinA) {
  const Fixture f;
  TextAmclSessionOptions o = f.Options();
  o.setup.filter.update_min_d_m = 0.2;
  o.setup.filter.update_min_a_rad = 0.5;
  TextAmclSession session = f.Make(o);
  const Pose2D start = f.robot();
  EXPECT_TRUE(session.AddScan(0.0, {}, f.ScanAt(start)).laser_used);  // the first scan after a start
  EXPECT_FALSE(session.AddScan(0.1, {0.1, 0.0, 0.0}, f.ScanAt(start.Compose({0.1, 0.0, 0.0}))).laser_used);
  EXPECT_FALSE(session.AddScan(0.2, {0.19, 0.0, 0.4}, f.ScanAt(start.Compose({0.19, 0.0, 0.4}))).laser_used);
  EXPECT_TRUE(session.AddScan(0.3, {0.21, 0.0, 0.4}, f.ScanAt(start.Compose({0.21, 0.0, 0.4}))).laser_used);
  EXPECT_EQ(session.counters().scans, 4);
  EXPECT_EQ(session.counters().laser_updates, 2);
  session.RequestNoMotionUpdate();
  EXPECT_TRUE(session.AddScan(0.4, {0.21, 0.0, 0.4}, f.ScanAt(start.Compose({0.21, 0.0, 0.4}))).laser_used);
}

TEST(TextAmclSession, ResamplesEveryResampleIntervalLaserUpdates) {
  const Fixture f;
  TextAmclSessionOptions o = f.Options();
  o.setup.filter.resample_interval = 3;
  TextAmclSession session = f.Make(o);
  for (int i = 0; i < 6; ++i) {
    session.RequestNoMotionUpdate();
    ASSERT_TRUE(session.AddScan(0.1 * i, {}, f.ScanAt(f.robot())).laser_used);
    EXPECT_EQ(session.Status().resamples, (i + 1) / 3) << "after update " << i + 1;
  }
}

TEST(TextAmclSession, MapToOdomComposesWithOdomToBaseToTheEstimate) {
  const Fixture f;
  TextAmclSession session = f.Make(f.Options());
  EXPECT_FALSE(session.MapToOdom().has_value());  // nothing weighed yet
  const Pose2D odom{5.0, -2.0, 1.0};              // odometry started elsewhere, turned
  ASSERT_TRUE(session.AddScan(0.0, odom, f.ScanAt(f.robot())).laser_used);
  ASSERT_TRUE(session.MapToOdom().has_value());
  const Pose2D composed = session.MapToOdom()->Compose(odom);
  const Pose2D estimate = session.Estimate().pose;
  EXPECT_NEAR(composed.x_m, estimate.x_m, 1e-9);
  EXPECT_NEAR(composed.y_m, estimate.y_m, 1e-9);
  EXPECT_NEAR(NormalizeAngle(composed.theta_rad - estimate.theta_rad), 0.0, 1e-9);
  EXPECT_NEAR(estimate.x_m, f.robot().x_m, 0.1);
  session.GlobalLocalization();
  EXPECT_FALSE(session.MapToOdom().has_value());
}

TEST(TextAmclSession, ThePlateRangeIsTheLaserRangeAlongItsBearingFromARecentScanOnly) {
  const Fixture f;
  TextAmclSession session = f.Make(f.Options());
  session.AddScan(0.0, {}, f.ScanAt(f.robot()));
  const PlateReading reading = test::ReadingOf(f.plate(), f.robot(), 0.9, /*with_range=*/false);
  const SessionUpdate now = session.AddPlates(0.0, {reading});
  ASSERT_EQ(now.plates.size(), 1u);
  ASSERT_TRUE(now.plates[0].reading.range_m.has_value());
  EXPECT_NEAR(*now.plates[0].reading.range_m, std::hypot(0.5, 1.0), 0.05);
  session.AddOdometry(2.0, {});
  const SessionUpdate later = session.AddPlates(2.0, {reading});  // the scan is 2 s old
  ASSERT_EQ(later.plates.size(), 1u);
  EXPECT_FALSE(later.plates[0].reading.range_m.has_value());
}

TEST(TextAmclSession, AScanOlderThanThePreviousIsIgnoredAndTheSessionContinuesFromIt) {
  const Fixture f;
  TextAmclSession session = f.Make(f.Options());
  session.AddScan(5.0, {}, f.ScanAt(f.robot()));
  const SessionUpdate back = session.AddScan(1.0, {}, f.ScanAt(f.robot()));
  EXPECT_NE(back.scan_ignored_reason.find("backwards"), std::string::npos) << back.scan_ignored_reason;
  EXPECT_FALSE(back.laser_used);
  session.RequestNoMotionUpdate();
  const SessionUpdate next = session.AddScan(1.1, {}, f.ScanAt(f.robot()));
  EXPECT_TRUE(next.scan_ignored_reason.empty());
  EXPECT_TRUE(next.laser_used);
}

TEST(TextAmclSession, AReadingOlderThanTheOdometryKeptIsDroppedAsStale) {
  const Fixture f;
  TextAmclSessionOptions o = f.Options();
  o.odometry_history_s = 1.0;
  TextAmclSession session = f.Make(o);
  session.AddOdometry(0.0, {});
  session.AddOdometry(5.0, {});
  const SessionUpdate update = session.AddPlates(2.0, {test::ReadingOf(f.plate(), f.robot())});
  ASSERT_EQ(update.plates.size(), 1u);
  EXPECT_EQ(update.plates[0].disposition, PlateDisposition::kStale);
  EXPECT_EQ(session.counters().stale_readings, 1);
}

bool SameParticles(const std::vector<Particle>& a, const std::vector<Particle>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].pose.x_m != b[i].pose.x_m || a[i].pose.y_m != b[i].pose.y_m ||
        a[i].pose.theta_rad != b[i].pose.theta_rad || a[i].weight != b[i].weight) {
      return false;
    }
  }
  return true;
}

// dynamic_reconfigure (issue 19): a session continued under the same options runs on exactly as the
// original (particles, random stream, odometry reference, resampling count all carried over); under new
// options it keeps the particles, map -> odom and the odometry, and the new gating and KLD bounds apply.
TEST(TextAmclSession, ContinuedUnderNewOptionsItKeepsTheParticlesAndUnderTheSameOnesRunsOnUnchanged) {
  const Fixture f;
  auto step = [&f](TextAmclSession& s, double t, double x) {
    const Pose2D robot{f.robot().x_m + x, f.robot().y_m, 0.0};
    return s.AddScan(t, {x, 0.0, 0.0}, f.ScanAt(robot));
  };
  TextAmclSession original = f.Make(f.Options());
  for (int i = 0; i < 3; ++i) step(original, i, 0.3 * i);
  const TextAmclSession same(f.Options(), f.corridor.occupancy, original);
  EXPECT_TRUE(SameParticles(same.particles(), original.particles()));
  EXPECT_EQ(same.Estimate().pose.x_m, original.Estimate().pose.x_m);
  ASSERT_TRUE(same.MapToOdom().has_value());
  EXPECT_EQ(same.MapToOdom()->x_m, original.MapToOdom()->x_m);
  EXPECT_EQ(same.counters().laser_updates, original.counters().laser_updates);
  TextAmclSessionOptions wide = f.Options();
  wide.setup.filter.update_min_d_m = 1.0;
  wide.setup.filter.max_particles = 200;
  wide.setup.filter.min_particles = 50;
  TextAmclSession reconfigured(wide, f.corridor.occupancy, original);
  EXPECT_TRUE(SameParticles(reconfigured.particles(), original.particles()));
  EXPECT_EQ(reconfigured.options().setup.filter.max_particles, 200);
  TextAmclSession continued(f.Options(), f.corridor.occupancy, original);
  for (int i = 3; i < 6; ++i) {
    const SessionUpdate a = step(original, i, 0.3 * i);
    const SessionUpdate b = step(continued, i, 0.3 * i);
    EXPECT_EQ(a.laser_used, b.laser_used);
    EXPECT_TRUE(SameParticles(original.particles(), continued.particles())) << "step " << i;
    // 0.3 m per step: below the new update_min_d (1 m), the reconfigured filter does not move.
    EXPECT_FALSE(step(reconfigured, i, 0.3 * i).laser_used) << "step " << i;
  }
  EXPECT_EQ(reconfigured.particles().size(), 500u) << "kept until the next resampling";
  for (int i = 0; i < 2; ++i) EXPECT_TRUE(step(reconfigured, 10 + i, 0.9 + 1.1 * (i + 1)).laser_used);
  EXPECT_LE(reconfigured.particles().size(), 200u) << "resampled into the new KLD bounds";
}

TEST(TextAmclSession, RefusesBadOptionsNamingTheField) {
  const Fixture f;
  TextAmclSessionOptions o = f.Options();
  o.text_range_max_scan_age_s = -1.0;
  try {
    f.Make(o);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("text_range_max_scan_age_s"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace doorplate_localization

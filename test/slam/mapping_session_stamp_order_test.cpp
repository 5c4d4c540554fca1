// MappingSession's stamp order (camera_wait_s > 0): scans wait for the camera's reports, so scans and
// plate sightings reach the filter in stamp order whatever order they arrive in. A second test file of
// mapping_session.cpp (mapping_session_test.cpp holds the other rules).
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "doorplate_localization/slam/mapping_session.h"
#include "slam_test_worlds.h"

namespace doorplate_localization {
namespace {

MappingSessionOptions Ordered(double camera_wait_s) {
  MappingSessionOptions o;
  o.slam.slam.num_particles = 10;
  o.slam.slam.linear_update_m = 0.3;
  o.camera_wait_s = camera_wait_s;
  return o;
}

PlateReading Sighting(const std::string& text, double bearing_rad) {
  PlateReading s;
  s.text = text;
  s.confidence = 0.9;
  s.bearing_rad = bearing_rad;
  return s;
}

// One input: a scan, or the camera's array for one image (sightings, or none).
struct Input {
  double stamp_s;
  Pose2D odometry;
  bool scan;
  std::vector<PlateReading> sightings;
};

// 20 m of a corridor (odometry 3 % long): scans at 10 Hz, camera arrays at 5 Hz, a plate every 4 m on
// alternate walls, each read twice (0.8 s apart: the second reading re-weighs the particles), in stamp order.
std::vector<Input> CorridorDrive() {
  std::vector<Input> inputs;
  const double speed_mps = 0.5;
  for (int i = 0; i <= 400; ++i) {
    const double t = 0.1 * i;
    const Pose2D odometry{1.03 * speed_mps * t, 0.0, 0.0};
    inputs.push_back({t, odometry, true, {}});
    if (i % 2 == 1) {
      std::vector<PlateReading> read;
      // Plate k hangs at x = 2 + 4 k (true metres), passed at t = 4 + 8 k s.
      const int plate = (i - 41) / 80, since = (i - 41) % 80;
      if (i >= 41 && (since == 0 || since == 8)) {
        const double side_m = plate % 2 ? 1.025 : -1.025, true_x = speed_mps * (t + 0.05);
        read.push_back(Sighting(std::to_string(200 + plate), std::atan2(side_m, 2.0 + 4.0 * plate - true_x)));
      }
      inputs.push_back({t + 0.05, odometry, false, read});
    }
  }
  return inputs;
}

// The same inputs as they arrive when every camera array comes `lag_s` after its image (OCR time): each
// array is moved behind the scans stamped up to `lag_s` after it.
std::vector<Input> ArrivingLate(const std::vector<Input>& in_stamp_order, double lag_s) {
  std::vector<Input> scans, arrays, out;
  for (const Input& i : in_stamp_order) (i.scan ? scans : arrays).push_back(i);
  std::size_t a = 0;
  for (const Input& s : scans) {
    while (a < arrays.size() && arrays[a].stamp_s + lag_s <= s.stamp_s) out.push_back(arrays[a++]);
    out.push_back(s);
  }
  while (a < arrays.size()) out.push_back(arrays[a++]);
  return out;
}

struct Outcome {
  std::vector<Pose2D> trajectory;
  std::vector<SlamLandmark> landmarks;
};

Outcome MapDrive(const MappingSessionOptions& options, const std::vector<Input>& inputs) {
  MappingSession session(options);
  for (const Input& i : inputs) {
    const Pose2D truth{i.odometry.x_m / 1.03, 0.0, 0.0};
    if (i.scan) session.AddScan(i.stamp_s, i.odometry, test::Scan(test::Corridor(), truth, 180, 16.0));
    else session.AddPlates(i.stamp_s, i.odometry, i.sightings);
  }
  session.Flush();
  EXPECT_EQ(session.waiting_scans(), 0u);
  EXPECT_EQ(session.held_plates(), 0u);
  return {session.Trajectory(), session.slam().BestLandmarks()};
}

void ExpectSame(const Outcome& a, const Outcome& b) {
  ASSERT_EQ(a.trajectory.size(), b.trajectory.size());
  for (std::size_t k = 0; k < a.trajectory.size(); ++k) {
    EXPECT_EQ(a.trajectory[k].x_m, b.trajectory[k].x_m) << "pose " << k;
    EXPECT_EQ(a.trajectory[k].theta_rad, b.trajectory[k].theta_rad) << "pose " << k;
  }
  ASSERT_EQ(a.landmarks.size(), b.landmarks.size());
  for (std::size_t k = 0; k < a.landmarks.size(); ++k) {
    EXPECT_EQ(a.landmarks[k].text, b.landmarks[k].text);
    EXPECT_EQ(a.landmarks[k].position.x, b.landmarks[k].position.x) << a.landmarks[k].text;
  }
}

TEST(MappingSessionStampOrder, ScansAndPlatesArrivingInAnyOrderWithinTheWaitMapTheSameBitForBit) {
  const std::vector<Input> drive = CorridorDrive();
  const Outcome in_order = MapDrive(Ordered(2.0), drive);
  ASSERT_EQ(in_order.landmarks.size(), 5u);
  ExpectSame(in_order, MapDrive(Ordered(2.0), ArrivingLate(drive, 0.35)));
  ExpectSame(in_order, MapDrive(Ordered(2.0), ArrivingLate(drive, 1.5)));
}

// A tf filter hands on the scan whose odometry came first: now and then a scan arrives after a newer one.
TEST(MappingSessionStampOrder, AScanArrivingAfterANewerOneWaitsInItsPlace) {
  const std::vector<Input> drive = CorridorDrive();
  std::vector<Input> swapped = ArrivingLate(drive, 0.35);
  int swaps = 0;
  for (std::size_t k = 1; k < swapped.size(); ++k) {
    if (swapped[k].scan && swapped[k - 1].scan && k % 7 == 0) {
      std::swap(swapped[k], swapped[k - 1]);
      ++swaps;
    }
  }
  ASSERT_GT(swaps, 10);
  ExpectSame(MapDrive(Ordered(2.0), drive), MapDrive(Ordered(2.0), swapped));
  // Once a scan went to the filter, an older one is refused, saying why.
  MappingSession session(Ordered(2.0));
  session.AddScan(0.0, {0, 0, 0}, test::Scan(test::Room(), {0, 0, 0}));
  session.AddPlates(1.0, {0, 0, 0}, {});  // the camera is past it: it goes
  const MappingUpdate old = session.AddScan(-0.1, {0, 0, 0}, test::Scan(test::Room(), {0, 0, 0}));
  EXPECT_FALSE(old.scan_taken);
  EXPECT_NE(old.scan_refused_reason.find("is not after the last scan mapped"), std::string::npos)
      << old.scan_refused_reason;
  EXPECT_EQ(session.counters().scans_refused, 1);
}

TEST(MappingSessionStampOrder, WithoutWaitingTheArrivalOrderChangesTheFiltersDraws) {
  const std::vector<Input> drive = CorridorDrive();
  const Outcome in_order = MapDrive(Ordered(0.0), drive), late = MapDrive(Ordered(0.0), ArrivingLate(drive, 1.5));
  ASSERT_EQ(in_order.trajectory.size(), late.trajectory.size());
  bool differ = false;
  for (std::size_t k = 0; k < late.trajectory.size(); ++k) {
    differ = differ || in_order.trajectory[k].x_m != late.trajectory[k].x_m;
  }
  EXPECT_TRUE(differ) << "the test drive must show the order dependence the waiting removes";
}

TEST(MappingSessionStampOrder, AScanWaitsForTheCameraAtMostCameraWaitSOfScanTime) {
  MappingSession session(Ordered(1.0));
  const auto scan_at = [&](double t) {
    return session.AddScan(t, {t, 0, 0}, test::Scan(test::Corridor(), {t, 0, 0}));
  };
  EXPECT_FALSE(scan_at(0.0).scan_processed);  // waits for the camera
  EXPECT_FALSE(scan_at(0.5).scan_processed);
  EXPECT_EQ(session.waiting_scans(), 2u);
  EXPECT_TRUE(scan_at(1.0).scan_processed);  // the 0 s scan waited 1 s: it goes on without the camera
  EXPECT_EQ(session.waiting_scans(), 2u);
  EXPECT_EQ(session.counters().scans_camera_wait_expired, 1);
  // The camera reports up to 0.7 s (an empty array): the 0.5 s scan goes, the 1 s one waits on.
  session.AddPlates(0.7, {0.7, 0, 0}, {});
  EXPECT_EQ(session.waiting_scans(), 1u);
  EXPECT_EQ(session.counters().scans_camera_wait_expired, 1);
  EXPECT_EQ(session.processed_scan_indices(), (std::vector<int>{0, 1}));
  session.Flush();
  EXPECT_EQ(session.waiting_scans(), 0u);
  EXPECT_EQ(session.counters().scans_camera_wait_expired, 1);  // a flush is not a wait that ran out
}

TEST(MappingSessionStampOrder, ASightingIsAppliedJustBeforeTheFirstScanAfterItsStamp) {
  MappingSession session(Ordered(5.0));
  session.AddScan(0.0, {0, 0, 0}, test::Scan(test::Room(), {0, 0, 0}));
  session.AddScan(1.0, {0, 0.5, 0}, test::Scan(test::Room(), {0, 0.5, 0}));
  // Read at 0.9 s: held while the 1 s scan waits for the camera, then applied before it goes, with the range
  // of the scan nearest its stamp (1 s, at y = 0.5: the south wall 2.525 m away).
  const MappingUpdate u = session.AddPlates(0.9, {0, 0.5, 0}, {Sighting("203", -M_PI / 2)});
  EXPECT_EQ(u.plates_held, 1);
  EXPECT_TRUE(u.plates.empty());
  EXPECT_EQ(session.waiting_scans(), 1u);
  const MappingUpdate go = session.AddPlates(1.2, {0, 0.5, 0}, {});
  ASSERT_EQ(go.plates.size(), 1u);
  ASSERT_TRUE(go.plates[0].result.used()) << go.plates[0].result.reason;
  EXPECT_NEAR(*go.plates[0].sighting.range_m, 2.525, 0.01);
  EXPECT_EQ(session.waiting_scans(), 0u);
  EXPECT_EQ(session.counters().plates_late, 0);
}

TEST(MappingSessionStampOrder, ASightingLaterThanTheWaitIsAppliedAtOnceAndCounted) {
  MappingSession session(Ordered(0.5));
  for (int i = 0; i <= 10; ++i) session.AddScan(0.1 * i, {0, 0, 0}, test::Scan(test::Room(), {0, 0, 0}));
  // The camera was silent: the scans up to 0.5 s went on after waiting 0.5 s. A sighting of 0.2 s now comes
  // after scans stamped later went to the filter: applied at once, counted.
  const MappingUpdate late = session.AddPlates(0.2, {0, 0, 0}, {Sighting("201", -M_PI / 2)});
  ASSERT_EQ(late.plates.size(), 1u);
  EXPECT_TRUE(late.plates[0].result.used()) << late.plates[0].result.reason;
  EXPECT_EQ(session.counters().plates_late, 1);
}

TEST(MappingSessionStampOrder, FlushAppliesASightingNoLaterScanCameFor) {
  MappingSession session(Ordered(5.0));
  session.AddScan(0.0, {0, 0, 0}, test::Scan(test::Room(), {0, 0, 0}));
  session.AddPlates(0.1, {0, 0, 0}, {Sighting("201", -M_PI / 2)});  // the end of the log
  EXPECT_EQ(session.held_plates(), 1u);
  EXPECT_EQ(session.waiting_scans(), 0u);  // the camera reported past the scan: it went on
  const MappingUpdate flushed = session.Flush();
  ASSERT_EQ(flushed.plates.size(), 1u);
  EXPECT_TRUE(flushed.plates[0].result.used()) << flushed.plates[0].result.reason;
  EXPECT_NEAR(*flushed.plates[0].sighting.range_m, 2.025, 0.01);  // the 0 s scan is 0.1 s away
}

TEST(MappingSessionStampOrder, ACameraWaitOutsideZeroToSixtySecondsIsRefusedByName) {
  for (const double bad : {-1.0, 61.0, std::nan("")}) {
    MappingSessionOptions o;
    o.camera_wait_s = bad;
    try {
      MappingSession session(o);
      ADD_FAILURE() << "accepted camera_wait_s = " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("MappingSessionOptions.camera_wait_s"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace doorplate_localization

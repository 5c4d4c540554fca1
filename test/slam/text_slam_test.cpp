#include "doorplate_localization/slam/text_slam.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <gtest/gtest.h>

#include "doorplate_localization/slam/rbpf_slam_options.h"
#include "slam_test_worlds.h"

namespace doorplate_localization {
namespace {

TextSlamOptions FewParticles(int n) {
  TextSlamOptions o;
  o.slam.num_particles = n;
  return o;
}

PlateReading Sighting(const std::string& text, double bearing_rad, std::optional<double> range_m = 1.0) {
  PlateReading s;
  s.text = text;
  s.confidence = 0.9;
  s.bearing_rad = bearing_rad;
  s.range_m = range_m;
  return s;
}

TEST(TextSlam, APlateBeforeTheFirstScanIsIgnored) {
  TextSlam slam(FewParticles(3));
  const TextSlamPlateResult r = slam.AddPlate(Sighting("201", M_PI / 2), {});
  EXPECT_EQ(r.outcome, PlateOutcome::kNoScanYet);
  EXPECT_FALSE(r.used());
  EXPECT_EQ(r.landmark_index, -1);
}

TEST(TextSlam, APlateIsPlacedAtThePoseComposedWithBearingAndRangeFacingTheRobot) {
  TextSlam slam(FewParticles(3));
  slam.AddScan(test::Scan(test::Room(), {0, 0, 0}), {0, 0, 0}, 0);
  // Read 0.2 m of odometry after the scan, on the left at 1.5 m.
  const TextSlamPlateResult r = slam.AddPlate(Sighting("201", M_PI / 2, 1.5), {0.2, 0, 0});
  EXPECT_EQ(r.outcome, PlateOutcome::kNewLandmark);
  EXPECT_EQ(r.landmark_index, 0);
  const std::vector<SlamLandmark> plates = slam.BestLandmarks();
  ASSERT_EQ(plates.size(), 1u);
  EXPECT_NEAR(plates[0].position.x, 0.2, 1e-9);
  EXPECT_NEAR(plates[0].position.y, 1.5, 1e-9);
  EXPECT_NEAR(plates[0].yaw_rad, -M_PI / 2, 1e-9);  // faces back into the corridor
  EXPECT_EQ(plates[0].side, 1);
  EXPECT_EQ(slam.num_landmarks(), 1);
}

TEST(TextSlam, WithoutARangeAReadingIsIgnored) {
  TextSlam slam(FewParticles(3));
  slam.AddScan(test::Scan(test::Room(), {0, 0, 0}), {0, 0, 0}, 0);
  const TextSlamPlateResult r = slam.AddPlate(Sighting("201", -M_PI / 2, std::nullopt), {0, 0, 0});
  EXPECT_EQ(r.outcome, PlateOutcome::kNoRange);
  EXPECT_EQ(slam.num_landmarks(), 0);
}

TEST(TextSlam, UnusableReadingsAreIgnoredWithTheReason) {
  TextSlamOptions o = FewParticles(3);
  o.min_confidence = 0.5;
  TextSlam slam(o);
  slam.AddScan(test::Scan(test::Corridor(), {0, 0, 0}), {0, 0, 0}, 0);
  PlateReading unsure = Sighting("201", M_PI / 2);
  unsure.confidence = 0.3;
  EXPECT_EQ(slam.AddPlate(unsure, {}).outcome, PlateOutcome::kLowConfidence);
  EXPECT_EQ(slam.AddPlate(Sighting("201", M_PI / 2, 9.0), {}).outcome, PlateOutcome::kRangeOutOfBounds);
  EXPECT_EQ(slam.AddPlate(Sighting("201", 0.0, std::nullopt), {}).outcome, PlateOutcome::kNoRange);
  EXPECT_EQ(slam.AddPlate(Sighting("201", M_PI / 2), {5.0, 0, 0}).outcome, PlateOutcome::kTooFarFromLastScan);
  EXPECT_EQ(slam.num_landmarks(), 0);
}

TEST(TextSlam, ANonFiniteOdometryPoseIsRefusedAndLeavesTheFilterAsItWas) {
  TextSlam slam(FewParticles(5));
  ASSERT_TRUE(slam.AddScan(test::Scan(test::Corridor(), {0, 0, 0}), {0, 0, 0}, 0));
  EXPECT_THROW(slam.AddScan(test::Scan(test::Corridor(), {1, 0, 0}), {NAN, 0, 0}, 1), std::invalid_argument);
  EXPECT_EQ(slam.slam().stats().scans_seen, 1);
  EXPECT_EQ(slam.Trajectory().size(), 1u);
  EXPECT_NO_THROW(slam.BuildOccupancyGrid());
}

TEST(TextSlam, BadFieldsThrowNamingTheField) {
  TextSlam slam(FewParticles(2));
  slam.AddScan(test::Scan(test::Room(), {0, 0, 0}), {0, 0, 0}, 0);
  PlateReading s = Sighting("201", NAN);
  try {
    slam.AddPlate(s, {});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("PlateReading.bearing_rad"), std::string::npos) << e.what();
  }
  EXPECT_THROW(slam.AddPlate(Sighting("", 1.0), {}), std::invalid_argument);
  EXPECT_THROW(slam.AddPlate(Sighting("201", 1.0, -1.0), {}), std::invalid_argument);
  s = Sighting("201", 1.0);
  s.confidence = 1.5;
  EXPECT_THROW(slam.AddPlate(s, {}), std::invalid_argument);
  EXPECT_THROW(slam.AddPlate(Sighting("201", 1.0), {NAN, 0, 0}), std::invalid_argument);
  TextSlamOptions bad = FewParticles(2);
  bad.plate_sigma_m = 0.0;
  EXPECT_THROW({ TextSlam t(bad); }, std::invalid_argument);
}

TEST(TextSlam, ReadingTheSamePlateAgainReobservesItAndAveragesThePosition) {
  TextSlam slam(FewParticles(4));
  slam.AddScan(test::Scan(test::Room(), {0, 0, 0}), {0, 0, 0}, 0);
  EXPECT_EQ(slam.AddPlate(Sighting("201", M_PI / 2, 1.0), {}).outcome, PlateOutcome::kNewLandmark);
  const TextSlamPlateResult again = slam.AddPlate(Sighting("201", M_PI / 2, 1.2), {});
  EXPECT_EQ(again.outcome, PlateOutcome::kReobserved);
  EXPECT_EQ(again.landmark_index, 0);
  // Another text at the same place, and the same text on the other wall, are other landmarks.
  EXPECT_EQ(slam.AddPlate(Sighting("203", M_PI / 2, 1.0), {}).outcome, PlateOutcome::kNewLandmark);
  EXPECT_EQ(slam.AddPlate(Sighting("201", -M_PI / 2, 1.0), {}).outcome, PlateOutcome::kNewLandmark);
  const std::vector<SlamLandmark> plates = slam.BestLandmarks();
  ASSERT_EQ(plates.size(), 3u);
  EXPECT_EQ(plates[0].observations, 2);
  EXPECT_NEAR(plates[0].position.y, 1.1, 1e-9);
  for (const SlamParticle& p : slam.slam().particles()) {
    ASSERT_TRUE(p.landmarks);
    EXPECT_EQ(p.landmarks->size(), 3u);
  }
}

// Out 4 m along a featureless corridor and back; on the way back odometry reads 20 % long, and the
// scans cannot tell (degenerate along x), so the particles end near the odometry's x = -0.8 m. Re-reading
// the plate first read at x = 0 pulls the best particle back to it, unless text weighting is off.
double BestXAfterReturningToThePlate(double text_likelihood_gain) {
  TextSlamOptions o = FewParticles(30);
  o.text_likelihood_gain = text_likelihood_gain;
  TextSlam slam(o);
  slam.AddScan(test::Scan(test::Corridor(), {0, 0, 0}), {0, 0, 0}, 0);
  EXPECT_EQ(slam.AddPlate(Sighting("201", M_PI / 2, 1.0), {}).outcome, PlateOutcome::kNewLandmark);
  int index = 1;
  for (double x = 0.5; x <= 4.01; x += 0.5) slam.AddScan(test::Scan(test::Corridor(), {x, 0, 0}), {x, 0, 0}, index++);
  Pose2D odometry{4, 0, M_PI};
  for (double x = 3.5; x >= -0.01; x -= 0.5) {
    odometry = {4 - 1.2 * (4 - x), 0, M_PI};
    slam.AddScan(test::Scan(test::Corridor(), {x, 0, M_PI}), odometry, index++);
  }
  EXPECT_EQ(slam.AddPlate(Sighting("201", -M_PI / 2, 1.0), odometry).outcome, PlateOutcome::kReobserved);
  return slam.BestPose().x_m;
}

TEST(TextSlam, ReobservingAPlateFavoursTheParticlesThatPutItBackInPlace) {
  const double without_text = BestXAfterReturningToThePlate(0.0);  // laser and odometry alone
  const double with_text = BestXAfterReturningToThePlate(1.0);
  std::printf("best x without text %.3f, with text %.3f\n", without_text, with_text);
  EXPECT_GT(std::abs(without_text), 0.3);
  EXPECT_LT(std::abs(with_text), 0.5 * std::abs(without_text));
}

// A 40 m corridor with end walls, driven with odometry 2 % long, a plate read half-way on the left wall.
// After Solve(), the map, the plates and the trajectory all come from the back end's solve, and the pose
// after it agrees with that solve.
TEST(TextSlam, MapPlatesAndTrajectoryComeFromTheBackEndSolve) {
  const std::vector<Segment> walls = {{{-0.525, -1.025}, {40.525, -1.025}}, {{-0.525, 1.025}, {40.525, 1.025}},
                                      {{-0.525, -1.025}, {-0.525, 1.025}}, {{40.525, -1.025}, {40.525, 1.025}}};
  TextSlam slam(FewParticles(10));
  int index = 0;
  for (const Pose2D& truth : test::PosesAlongX(0.0, 40.0, 0.5)) {
    const Pose2D odometry{1.02 * truth.x_m, 0.0, 0.0};
    ASSERT_TRUE(slam.AddScan(test::Scan(walls, truth, 360, 16.0), odometry, index++));
    if (truth.x_m == 20.0) {
      ASSERT_TRUE(slam.AddPlate(Sighting("120", M_PI / 2, 1.025), odometry).used());
    }
  }
  EXPECT_FALSE(slam.BackEndResult().has_value()) << "only Solve() solves";
  slam.Solve();
  const OccupancyGrid grid = slam.BuildOccupancyGrid();
  const std::optional<SlamBackEndResult> solve = slam.BackEndResult();
  ASSERT_TRUE(solve.has_value());
  ASSERT_EQ(solve->poses.size(), 81u);
  const std::vector<Pose2D> trajectory = slam.Trajectory();
  ASSERT_EQ(trajectory.size(), solve->poses.size());
  EXPECT_EQ(trajectory.back().x_m, solve->poses.back().x_m);
  EXPECT_NEAR(trajectory.back().x_m, 40.0, 0.15);
  EXPECT_NEAR(solve->odometry_scale, 1 / 1.02, 0.005);
  const std::vector<SlamLandmark> plates = slam.BestLandmarks();
  ASSERT_EQ(plates.size(), 1u);
  ASSERT_TRUE(solve->plates.at(0).has_value());
  EXPECT_EQ(plates[0].position.x, solve->plates[0]->x);
  EXPECT_NEAR(plates[0].position.x, 20.0, 0.15);
  EXPECT_NEAR(plates[0].position.y, 1.025, 0.05);
  // The far end wall is rendered where it is (40.525 m), not 2 % further out.
  int cx = 0, cy = 0;
  ASSERT_TRUE(grid.WorldToCell({40.525, 0.0}, &cx, &cy));
  EXPECT_EQ(grid.At(cx, cy), OccupancyGrid::kOccupied);
  const Pose2D after = slam.EstimatedPose({1.02 * 40.0 + 0.2, 0.0, 0.0});
  EXPECT_NEAR(after.x_m, solve->poses.back().x_m + 0.2, 1e-6);
}

TEST(TextSlam, NodePointsFusedWithNeighbouringScansGiveTheSameCorridor) {
  // A 10 Hz laser at 0.4 m/s: a node every 0.5 m and a dozen scans between; with node fusion every node
  // takes its neighbours' echoes too, and the solve still puts the corridor where it is.
  const std::vector<Segment> walls = {{{-0.525, -1.025}, {20.525, -1.025}}, {{-0.525, 1.025}, {20.525, 1.025}},
                                      {{-0.525, -1.025}, {-0.525, 1.025}}, {{20.525, -1.025}, {20.525, 1.025}}};
  TextSlamOptions options = FewParticles(10);
  options.back_end.node_fusion.scans_before = 3;
  options.back_end.node_fusion.scans_after = 3;
  TextSlam slam(options);
  int index = 0, processed = 0;
  Pose2D last_node_truth;
  for (const Pose2D& truth : test::PosesAlongX(0.0, 20.0, 0.04)) {
    if (slam.AddScan(test::Scan(walls, truth, 360, 16.0), {1.02 * truth.x_m, 0.0, 0.0}, index++)) {
      ++processed;
      last_node_truth = truth;
    }
  }
  slam.FinishInput();
  slam.Solve();
  const std::optional<SlamBackEndResult> solve = slam.BackEndResult();
  ASSERT_TRUE(solve.has_value());
  ASSERT_EQ(static_cast<int>(solve->poses.size()), processed);
  EXPECT_GT(solve->alignment_edges, processed);
  EXPECT_NEAR(solve->poses.back().x_m, last_node_truth.x_m, 0.05);
  EXPECT_NEAR(solve->poses.back().y_m, 0.0, 0.03);
}

TEST(TextSlam, PatrolsOverMappedGroundKeepNoScansButEveryPoseAndPlate) {
  const std::vector<Segment> walls = {{{-0.525, -1.025}, {20.525, -1.025}}, {{-0.525, 1.025}, {20.525, 1.025}},
                                      {{-0.525, -1.025}, {-0.525, 1.025}}, {{20.525, -1.025}, {20.525, 1.025}}};
  // East, west (turning on the spot at the end) and east again, a scan every 0.5 m or 0.4 rad, exact
  // odometry. The first two passes fill every place (place_radius_m 0.5 m: about two nodes each way); the
  // third finds them full.
  std::vector<Pose2D> truths;
  for (int pass = 0; pass < 3; ++pass) {
    const double heading = pass % 2 == 0 ? 0.0 : M_PI;
    for (const Pose2D& p : test::PosesAlongX(0.0, 20.0, 0.5)) {
      truths.push_back({pass % 2 == 0 ? p.x_m : 20.0 - p.x_m, 0.0, heading});
    }
    for (double turn = 0.4; turn < M_PI; turn += 0.4) {
      truths.push_back({truths.back().x_m, 0.0, NormalizeAngle(heading + turn)});
    }
  }
  TextSlamOptions options = FewParticles(10);
  options.back_end.max_nodes_per_place = 2;
  TextSlam slam(options);
  for (std::size_t i = 0; i < truths.size(); ++i) {
    ASSERT_TRUE(slam.AddScan(test::Scan(walls, truths[i], 360, 16.0), truths[i], static_cast<int>(i), true));
    if (truths[i].x_m == 10.0 && truths[i].theta_rad == 0.0) {  // read on both eastward passes
      ASSERT_TRUE(slam.AddPlate(Sighting("110", M_PI / 2, 1.025), truths[i]).used());
    }
  }
  slam.Solve();
  const SlamBackEndResult& solve = *slam.BackEndResult();
  EXPECT_GT(solve.nodes_on_mapped_ground, 30);
  EXPECT_GT(solve.mapped_ground_alignments, 30);
  EXPECT_EQ(solve.plate_readings, 2);
  const std::vector<Pose2D> trajectory = slam.Trajectory();
  ASSERT_EQ(trajectory.size(), truths.size()) << "one pose per processed scan, scan kept or not";
  for (std::size_t i = 0; i < truths.size(); ++i) {
    EXPECT_NEAR(trajectory[i].x_m, truths[i].x_m, 0.1) << "scan " << i;
    EXPECT_NEAR(trajectory[i].y_m, truths[i].y_m, 0.05) << "scan " << i;
  }
  const std::vector<SlamLandmark> plates = slam.BestLandmarks();
  ASSERT_EQ(plates.size(), 1u);
  EXPECT_NEAR(plates[0].position.x, 10.0, 0.15);
  const OccupancyGrid grid = slam.BuildOccupancyGrid();
  int cx = 0, cy = 0;
  ASSERT_TRUE(grid.WorldToCell({20.525, 0.0}, &cx, &cy));
  EXPECT_EQ(grid.At(cx, cy), OccupancyGrid::kOccupied);
}

TEST(TextSlam, TheTextMapListsPlatesByWallWithDistancesFromTheMapAndFromOdometry) {
  TextSlam slam(FewParticles(3));
  slam.AddScan(test::Scan(test::Corridor(), {0, 0, 0}), {0, 0, 0}, 0);
  slam.AddPlate(Sighting("201", M_PI / 2, 1.0), {0, 0, 0});
  slam.AddScan(test::Scan(test::Corridor(), {1, 0, 0}), {1, 0, 0}, 1);
  slam.AddPlate(Sighting("203", M_PI / 2, 1.0), {1.2, 0, 0});
  slam.AddPlate(Sighting("202", -M_PI / 2, 1.0), {1.2, 0, 0});
  const TextMap map = slam.BuildTextMap();
  ASSERT_EQ(map.landmarks.size(), 3u);
  EXPECT_EQ(map.landmarks[0].wall, map.landmarks[1].wall);
  EXPECT_NE(map.landmarks[0].wall, map.landmarks[2].wall);
  ASSERT_EQ(map.adjacent.size(), 2u);  // 201-203 from the map and from odometry
  EXPECT_EQ(map.adjacent[0].source, "map");
  EXPECT_EQ(map.adjacent[1].source, "odometry");
  EXPECT_NEAR(map.adjacent[1].distance_m, 1.2, 1e-9);
  EXPECT_NEAR(map.adjacent[0].distance_m, 1.2, 0.15);
}

TEST(TextSlam, AReadingWithOrWithoutSeparatorsReobservesTheSamePlate) {
  TextSlam slam(FewParticles(4));
  slam.AddScan(test::Scan(test::Room(), {0, 0, 0}), {0, 0, 0}, 0);
  EXPECT_EQ(slam.AddPlate(Sighting("E14-295", M_PI / 2, 1.0), {}).outcome, PlateOutcome::kNewLandmark);
  EXPECT_EQ(slam.AddPlate(Sighting("E14295", M_PI / 2, 1.1), {}).outcome, PlateOutcome::kReobserved);
  EXPECT_EQ(slam.AddPlate(Sighting("e14 295", M_PI / 2, 1.0), {}).outcome, PlateOutcome::kReobserved);
  const std::vector<SlamLandmark> plates = slam.BestLandmarks();
  ASSERT_EQ(plates.size(), 1u);
  EXPECT_EQ(plates[0].text, "E14-295");  // the first printed form
  EXPECT_EQ(plates[0].observations, 3);
}

TEST(TextSlam, LookAlikeReadingsAtTheSamePlaceAreOtherLandmarks) {
  TextSlam slam(FewParticles(4));
  slam.AddScan(test::Scan(test::Room(), {0, 0, 0}), {0, 0, 0}, 0);
  EXPECT_EQ(slam.AddPlate(Sighting("312A", M_PI / 2, 1.0), {}).outcome, PlateOutcome::kNewLandmark);
  EXPECT_EQ(slam.AddPlate(Sighting("312B", M_PI / 2, 1.0), {}).outcome, PlateOutcome::kNewLandmark);
  EXPECT_EQ(slam.AddPlate(Sighting("32-076", -M_PI / 2, 1.0), {}).outcome, PlateOutcome::kNewLandmark);
  EXPECT_EQ(slam.AddPlate(Sighting("32-069T", -M_PI / 2, 1.0), {}).outcome, PlateOutcome::kNewLandmark);
  EXPECT_EQ(slam.BestLandmarks().size(), 4u);
}

TEST(TextSlam, ReadingsOutsideTheBuildingsRoomPatternAreIgnoredAndThePatternIsMapped) {
  TextSlamOptions o = FewParticles(3);
  o.room_pattern = "[0-9]{3}";
  TextSlam slam(o);
  slam.AddScan(test::Scan(test::Room(), {0, 0, 0}), {0, 0, 0}, 0);
  const TextSlamPlateResult exit = slam.AddPlate(Sighting("EXIT", M_PI / 2, 1.0), {});
  EXPECT_EQ(exit.outcome, PlateOutcome::kNotARoomId);
  EXPECT_FALSE(exit.used());
  EXPECT_NE(exit.reason.find("room_pattern"), std::string::npos) << exit.reason;
  EXPECT_EQ(slam.AddPlate(Sighting("E14-295", M_PI / 2, 1.0), {}).outcome, PlateOutcome::kNotARoomId);
  EXPECT_EQ(slam.AddPlate(Sighting("201", M_PI / 2, 1.0), {}).outcome, PlateOutcome::kNewLandmark);
  const TextMap map = slam.BuildTextMap();
  EXPECT_EQ(map.room_pattern, "[0-9]{3}");
  ASSERT_EQ(map.landmarks.size(), 1u);
  EXPECT_EQ(ParseTextMap(TextMapToYaml(map), "mem").room_pattern, "[0-9]{3}");  // it saves and loads
  TextSlamOptions bad = FewParticles(3);
  bad.room_pattern = "[0-9";
  try {
    TextSlam t(bad);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("TextSlamOptions.room_pattern"), std::string::npos) << e.what();
  }
}

TEST(TextSlam, TextOptionsHaveNamesInTheSharedTable) {
  TextSlamOptions o;
  SetTextSlamOption("text.plate_sigma_m", 0.3, &o);
  SetTextSlamOption("num_particles", 7, &o);
  EXPECT_EQ(o.plate_sigma_m, 0.3);
  EXPECT_EQ(o.slam.num_particles, 7);
  EXPECT_EQ(GetTextSlamOption("text.plate_sigma_m", o), 0.3);
  EXPECT_THROW(SetTextSlamOption("text.nope", 1, &o), std::invalid_argument);
  const std::vector<std::string> names = TextSlamOptionNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "text.min_confidence"), names.end());
  for (const std::string& name : names) EXPECT_NO_THROW(GetTextSlamOption(name, o)) << name;
}

}  // namespace
}  // namespace doorplate_localization

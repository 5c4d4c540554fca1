#include "doorplate_localization/slam/rbpf_slam.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/slam/carmen_reader.h"
#include "slam_test_worlds.h"

namespace doorplate_localization {
namespace {

RbpfSlamOptions FewParticles(int n) {
  RbpfSlamOptions o;
  o.num_particles = n;
  return o;
}

// RMSE of positions after the best rigid 2D alignment of `estimate` onto `reference` (the protocol's ATE).
double AbsoluteTrajectoryError(const std::vector<Vec2>& estimate, const std::vector<Vec2>& reference) {
  const double n = static_cast<double>(estimate.size());
  Vec2 me, mr;
  for (std::size_t i = 0; i < estimate.size(); ++i) me = me + (1 / n) * estimate[i], mr = mr + (1 / n) * reference[i];
  double sxx = 0, sxy = 0;  // optimal rotation angle from the cross-covariance
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    const Vec2 e = estimate[i] - me, r = reference[i] - mr;
    sxx += Dot(e, r), sxy += Cross(e, r);
  }
  const double angle = std::atan2(sxy, sxx), c = std::cos(angle), s = std::sin(angle);
  double sum = 0;
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    const Vec2 e = estimate[i] - me;
    const Vec2 aligned{c * e.x - s * e.y + mr.x, s * e.x + c * e.y + mr.y};
    sum += std::pow(Norm(aligned - reference[i]), 2);
  }
  return std::sqrt(sum / n);
}

TEST(RbpfSlam, TheFirstScanStartsTheMapAtTheOdometryPose) {
  RbpfSlam slam(FewParticles(5));
  const Pose2D start{2, 1, 0.5};
  EXPECT_TRUE(slam.AddScan(test::Scan(test::Room(), {0, 0, 0}), start, 7));
  ASSERT_EQ(slam.particles().size(), 5u);
  EXPECT_EQ(slam.BestParticle().pose.x_m, 2.0);
  const std::vector<TrajectoryPoint> trajectory = slam.BestTrajectory();
  ASSERT_EQ(trajectory.size(), 1u);
  EXPECT_EQ(trajectory[0].scan_index, 7);
  EXPECT_GT(slam.BestParticle().map.TileCount(), 0u);
}

TEST(RbpfSlam, ScansBelowTheUpdateThresholdsAreNotProcessed) {
  RbpfSlamOptions o = FewParticles(3);
  o.linear_update_m = 0.5;
  o.angular_update_rad = 0.25;
  RbpfSlam slam(o);
  slam.AddScan(test::Scan(test::Room(), {0, 0, 0}), {0, 0, 0}, 0);
  EXPECT_FALSE(slam.AddScan(test::Scan(test::Room(), {0.2, 0, 0}), {0.2, 0, 0}, 1));
  EXPECT_FALSE(slam.AddScan(test::Scan(test::Room(), {0.4, 0, 0.2}), {0.4, 0, 0.2}, 2));
  EXPECT_TRUE(slam.AddScan(test::Scan(test::Room(), {0.6, 0, 0.2}), {0.6, 0, 0.2}, 3));
  EXPECT_EQ(slam.stats().scans_seen, 4);
  EXPECT_EQ(slam.stats().scans_processed, 2);
  EXPECT_EQ(slam.BestTrajectory().back().scan_index, 3);
}

TEST(RbpfSlam, FollowsADriveThroughARoomDespiteBiasedOdometry) {
  RbpfSlam slam(FewParticles(10));
  // True path: a loop in the room; odometry reads 5 % long and turns 0.05 rad too far per step.
  std::vector<Pose2D> path;
  for (int i = 0; i <= 24; ++i) {
    const double a = i * 2 * M_PI / 24;
    path.push_back({1.2 * std::cos(a) - 0.8, 1.0 * std::sin(a) - 0.4, a + M_PI / 2});
  }
  Pose2D odometry = path[0];
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (i > 0) {
      Pose2D step = path[i - 1].Between(path[i]);
      step = {1.05 * step.x_m, 1.05 * step.y_m, step.theta_rad + 0.05};
      odometry = odometry.Compose(step);
    }
    slam.AddScan(test::Scan(test::Room(), path[i]), odometry, static_cast<int>(i));
  }
  const Pose2D end = slam.BestParticle().pose;
  EXPECT_LT(std::hypot(end.x_m - path.back().x_m, end.y_m - path.back().y_m), 0.05);
  EXPECT_LT(std::abs(NormalizeAngle(end.theta_rad - path.back().theta_rad)), 0.02);
  EXPECT_GT(std::abs(NormalizeAngle(odometry.theta_rad - path.back().theta_rad)), 1.0);  // odometry alone is lost
}

TEST(RbpfSlam, ReweightingFavoursAParticleAndResamplingCopiesItsMapByPointer) {
  RbpfSlam slam(FewParticles(8));
  slam.AddScan(test::Scan(test::Room(), {0, 0, 0}), {0, 0, 0}, 0);
  slam.AddScan(test::Scan(test::Room(), {0.6, 0, 0}), {0.6, 0, 0}, 1);
  const std::size_t bytes_before = slam.MapMemoryBytes();
  const SlamParticle* favoured = &slam.particles()[3];
  const TrajectoryNode* favoured_history = favoured->trajectory.get();
  const Pose2D favoured_pose = favoured->pose;
  const int resamplings = slam.stats().resamplings;
  // Evidence (as a text landmark would give) that only particle 3 explains.
  slam.ReweightParticles([&](const SlamParticle& p) { return &p == favoured ? 0.0 : -50.0; });
  EXPECT_EQ(slam.stats().resamplings, resamplings + 1);
  for (const SlamParticle& p : slam.particles()) {
    EXPECT_EQ(p.trajectory.get(), favoured_history);  // all are copies of particle 3
    EXPECT_EQ(p.pose.x_m, favoured_pose.x_m);
    EXPECT_EQ(p.log_weight, 0.0);
    EXPECT_TRUE(p.map.SharesTileWith(slam.particles()[0].map, p.map.CellOf({0, 0})));
  }
  EXPECT_LT(slam.MapMemoryBytes(), bytes_before);  // the copies share one set of tiles
}

TEST(RbpfSlam, MapsASliceOfTheRealIntelLogWithinTheMeasuredError) {
  const std::string base = std::string(DOORPLATE_SOURCE_DIR) + "/test/data/slam/intel_noisy_seed1_first120";
  const CarmenLog log = ReadCarmenLogFile(base + ".log");
  ASSERT_EQ(log.scans.size(), 120u);
  std::ifstream gt_file(base + ".gt");
  std::vector<Vec2> reference_all;
  double t, x, y, theta;
  while (gt_file >> t >> x >> y >> theta) reference_all.push_back({x, y});
  ASSERT_EQ(reference_all.size(), 120u);

  RbpfSlamOptions options = FewParticles(10);
  options.seed = 1;
  RbpfSlam slam(options);
  for (const CarmenScan& s : log.scans) slam.AddScan(s.scan, s.odometry_pose, s.scan_index);
  std::vector<Vec2> estimate, reference, odometry;
  for (const TrajectoryPoint& p : slam.MeanTrajectory()) {
    estimate.push_back(p.pose.Position());
    reference.push_back(reference_all[p.scan_index]);
    odometry.push_back(log.scans[p.scan_index].odometry_pose.Position());
  }
  EXPECT_GT(estimate.size(), 110u);
  // Measured on this slice with 10 particles (mean trajectory): 0.050-0.099 m over filter seeds 1-10
  // (0.070 m for seed 1); odometry alone: 4.5 m.
  EXPECT_LT(AbsoluteTrajectoryError(estimate, reference), 0.2);
  EXPECT_GT(AbsoluteTrajectoryError(odometry, reference), 3.0);
}

TEST(RbpfSlam, TheMeanTrajectoryIsTheWeightedMeanOfTheParticlesHistories) {
  RbpfSlamOptions options = FewParticles(6);
  options.mean_trajectory_radius_m = 1e6;  // one mode: every particle counts
  RbpfSlam slam(options);
  Pose2D odometry;
  for (int i = 0; i < 5; ++i) {
    const Pose2D truth{-1.5 + 0.6 * i, 0.1 * i, 0.05 * i};
    odometry = {truth.x_m * 1.1, truth.y_m, truth.theta_rad};
    slam.AddScan(test::Scan(test::Room(), truth), odometry, i);
  }
  double max_lw = -1e300;
  for (const SlamParticle& p : slam.particles()) max_lw = std::max(max_lw, p.log_weight);
  double sum_w = 0, sum_x = 0, sum_y = 0;
  for (const SlamParticle& p : slam.particles()) {
    const double w = std::exp(p.log_weight - max_lw);
    sum_w += w, sum_x += w * p.pose.x_m, sum_y += w * p.pose.y_m;
  }
  const std::vector<TrajectoryPoint> mean = slam.MeanTrajectory();
  const std::vector<TrajectoryPoint> best = slam.BestTrajectory();
  ASSERT_EQ(mean.size(), best.size());
  EXPECT_EQ(mean.back().scan_index, best.back().scan_index);
  EXPECT_NEAR(mean.back().pose.x_m, sum_x / sum_w, 1e-9);
  EXPECT_NEAR(mean.back().pose.y_m, sum_y / sum_w, 1e-9);
}

TEST(RbpfSlam, TheMeanTrajectoryLeavesOtherModesOut) {
  RbpfSlamOptions options = FewParticles(6);
  options.mean_trajectory_radius_m = 0.0;  // only histories identical to the best one
  RbpfSlam slam(options);
  for (int i = 0; i < 4; ++i) slam.AddScan(test::Scan(test::Room(), {-1.0 + 0.6 * i, 0, 0}), {-1.0 + 0.6 * i, 0, 0}, i);
  const std::vector<TrajectoryPoint> mean = slam.MeanTrajectory();
  const std::vector<TrajectoryPoint> best = slam.BestTrajectory();
  for (std::size_t i = 0; i < best.size(); ++i) {
    EXPECT_NEAR(mean[i].pose.x_m, best[i].pose.x_m, 1e-9);
    EXPECT_NEAR(mean[i].pose.theta_rad, best[i].pose.theta_rad, 1e-9);
  }
}

TEST(RbpfSlam, RejectsOptionsItCannotRun) {
  RbpfSlamOptions o;
  o.num_particles = 0;
  EXPECT_THROW(RbpfSlam{o}, std::invalid_argument);
  o = RbpfSlamOptions{};
  o.likelihood_gain = 0.0;
  EXPECT_THROW(RbpfSlam{o}, std::invalid_argument);
}

// doorplate_map_log --particles 1e9 ended in std::bad_alloc (issue 18): refused by name with the limit.
TEST(RbpfSlam, RefusesMoreParticlesThanTheLimitNamingIt) {
  RbpfSlamOptions o;
  o.num_particles = 1'000'000'000;
  try {
    RbpfSlam slam(o);
    FAIL() << "accepted 1e9 particles";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "RbpfSlamOptions.num_particles: must be in [1, 1000000] (limits::kMaxParticles), got "
                           "1000000000");
  }
  o.num_particles = limits::kMaxParticles;
  EXPECT_NO_THROW(RbpfSlam{o});
}

TEST(RbpfSlam, RejectsAScanWithoutGeometry) {
  RbpfSlam slam(FewParticles(2));
  LaserScan scan;
  scan.ranges_m = {1.0f, 2.0f};
  EXPECT_THROW(slam.AddScan(scan, {}, 0), std::invalid_argument);
}

TEST(RbpfSlam, TheDegeneracyAwareProposalFindsTheCorridorAxisAndLeavesPositionAlongItToOdometry) {
  // A featureless corridor: every scan is degenerate along x. Odometry reads exactly; the proposal's
  // position along x must stay the particle's odometry sample, so the best particle ends within the
  // motion model's spread of the true 6 m (not where a flat likelihood would leave it).
  RbpfSlamOptions options = FewParticles(10);
  options.degenerate_min_points = 10.0;
  options.motion.trans_noise_from_trans = 0.02;
  RbpfSlam slam(options);
  for (int i = 0; i <= 12; ++i) {
    const Pose2D pose{0.5 * i, 0.0, 0.0};
    slam.AddScan(test::Scan(test::Corridor(), pose), pose, i);
  }
  EXPECT_EQ(slam.stats().scans_processed, 13);
  EXPECT_EQ(slam.stats().degenerate_scans, 12);  // all but the first
  EXPECT_NEAR(slam.BestParticle().pose.x_m, 6.0, 0.25);
  EXPECT_NEAR(slam.BestParticle().pose.y_m, 0.0, 0.05);  // across the corridor the walls decide
}

TEST(RbpfSlam, AScanOfARoomIsNotDegenerate) {
  RbpfSlamOptions options = FewParticles(3);
  options.degenerate_min_points = 10.0;
  RbpfSlam slam(options);
  for (int i = 0; i <= 4; ++i) {
    const Pose2D pose{-1.0 + 0.5 * i, 0.0, 0.0};
    slam.AddScan(test::Scan(test::Room(), pose), pose, i);
  }
  EXPECT_EQ(slam.stats().scans_processed, 5);
  EXPECT_EQ(slam.stats().degenerate_scans, 0);
}

TEST(RbpfSlam, BeamsWithoutEchoDoNotClearFreeSpaceThroughAWallTheMapHolds) {
  // The first scan maps the room's walls; the second one, 0.6 m on, loses the echoes of every beam
  // towards the +y wall (laser dropouts, +inf). They may clear the room up to that wall, not the 10 m
  // (no_return_clear_range_m) behind it.
  RbpfSlam slam(FewParticles(1));
  slam.AddScan(test::Scan(test::Room(), {0, 0, 0}), {0, 0, 0}, 0);
  const Pose2D pose{0.6, 0, 0};
  LaserScan scan = test::Scan(test::Room(), pose);
  int dropouts = 0;
  for (int i = 0; i < static_cast<int>(scan.ranges_m.size()); ++i) {
    const double a = scan.BeamAngle(i);
    if (a > 1.3 && a < 1.8) scan.ranges_m[i] = std::numeric_limits<float>::infinity(), ++dropouts;
  }
  ASSERT_GT(dropouts, 20);
  ASSERT_TRUE(slam.AddScan(scan, pose, 1));
  const TiledGrid& map = slam.BestParticle().map;
  EXPECT_LT(map.LogOdds(map.CellOf({0.6, 1.5})), 0.0);  // inside the room: cleared
  int observed_behind = 0;  // cells beyond the wall (y > 2.05) in front of the dropouts
  for (int cx = map.CellOf({-0.2, 0}).x; cx <= map.CellOf({1.4, 0}).x; ++cx) {
    for (int cy = map.CellOf({0, 2.15}).y; cy <= map.CellOf({0, 5.0}).y; ++cy) observed_behind += map.Observed({cx, cy});
  }
  EXPECT_EQ(observed_behind, 0);
}

TEST(RbpfSlam, WhereTheScanFixesPositionTheDegeneracyAwareProposalKeepsTheWholeCorrection) {
  // In a room every scan constrains position in both directions (λ far above 2·degenerate_min_points),
  // so the degeneracy-aware proposal must not hold back any of the match's correction of 10 %-long
  // odometry: the filter ends exactly where the plain filter does.
  RbpfSlamOptions plain = FewParticles(5);
  RbpfSlamOptions aware = plain;
  aware.degenerate_min_points = 10.0;
  RbpfSlam a(plain), b(aware);
  for (int i = 0; i <= 6; ++i) {
    const Pose2D truth{-1.5 + 0.5 * i, 0.2 * std::sin(i), 0.0};
    const Pose2D odometry{1.1 * truth.x_m, 1.1 * truth.y_m, 0.0};
    a.AddScan(test::Scan(test::Room(), truth), odometry, i);
    b.AddScan(test::Scan(test::Room(), truth), odometry, i);
  }
  EXPECT_EQ(b.stats().degenerate_scans, 0);
  EXPECT_EQ(a.BestParticle().pose.x_m, b.BestParticle().pose.x_m);
  EXPECT_EQ(a.BestParticle().pose.y_m, b.BestParticle().pose.y_m);
  // The map frame is the odometry frame at the first scan (x = -1.65): 3 m later the truth is at 1.35,
  // the odometry at 1.65.
  EXPECT_NEAR(b.BestParticle().pose.x_m, 1.35, 0.1);
}

}  // namespace
}  // namespace doorplate_localization

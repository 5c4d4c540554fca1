#include "doorplate_localization/mcl/text_amcl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "amcl_drive.h"

namespace doorplate_localization {
namespace {

class TextAmclTest : public ::testing::Test {
 protected:
  std::shared_ptr<LocalizationGrid> room_ = std::make_shared<LocalizationGrid>(test::AsymmetricRoom());
  std::shared_ptr<TextMap> no_plates_ = std::make_shared<TextMap>();
  test::FilterSetup setup_;
  std::mt19937_64 rng_{17};

  Eigen::Matrix3d Covariance(double sd_xy, double sd_theta) const {
    return Eigen::Vector3d(sd_xy * sd_xy, sd_xy * sd_xy, sd_theta * sd_theta).asDiagonal();
  }
};

TEST_F(TextAmclTest, RejectsMissingModelsAndBadOptionsNamingTheField) {
  TextAmclModels models;
  models.grid = room_;
  try {
    TextAmcl amcl({}, models);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("models.motion"), std::string::npos) << e.what();
  }
  setup_.amcl.resample_interval = 0;
  EXPECT_THROW(test::MakeFilter(room_, nullptr, setup_), std::invalid_argument);
  setup_ = test::FilterSetup();
  setup_.amcl.recovery_alpha_slow = 0.5;  // above recovery_alpha_fast
  EXPECT_THROW(test::MakeFilter(room_, nullptr, setup_), std::invalid_argument);
  setup_ = test::FilterSetup();
  setup_.amcl.min_particles = 0;
  EXPECT_THROW(test::MakeFilter(room_, nullptr, setup_), std::invalid_argument);
}

// Issue 18: absurd particle counts and maps without free space are refused when the filter is made, naming
// the limit or the grid, so that neither Initialize nor GlobalLocalization can fail later.
TEST_F(TextAmclTest, RefusesTooManyParticlesAndAGridWithoutFreeSpace) {
  setup_.amcl.max_particles = 1000000000;
  try {
    test::MakeFilter(room_, nullptr, setup_);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_particles: must be <= 1000000 (limits::kMaxParticles)"),
              std::string::npos)
        << e.what();
  }
  setup_ = test::FilterSetup();
  auto walls = std::make_shared<LocalizationGrid>(test::MakeGrid(0, 0, 2.0, 2.0, 0.1, OccupancyGrid::kOccupied));
  try {
    test::MakeFilter(walls, nullptr, setup_);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "TextAmcl: models.grid: no free cell: all 400 cells are occupied or unknown");
  }
}

// amcl_pose's covariance is amcl's: the whole particle set's, not the heaviest cluster's (kept beside it;
// pose_clusters_test shows the two apart for two hypotheses).
TEST_F(TextAmclTest, EstimateCarriesTheWholeSetsCovarianceAndTheHeaviestClustersBesideIt) {
  setup_.amcl.max_particles = 2000;
  auto amcl = test::MakeFilter(room_, nullptr, setup_);
  amcl->GlobalLocalization();
  const PoseEstimate e = amcl->Estimate();
  const PoseCluster all = SetStatistics(amcl->particles());
  const PoseCluster& best = amcl->Clusters().clusters.front();
  EXPECT_TRUE(e.covariance.isApprox(all.covariance, 1e-12)) << e.covariance;
  EXPECT_TRUE(e.cluster_covariance.isApprox(best.covariance, 1e-12)) << e.cluster_covariance;
  EXPECT_EQ(e.pose.x_m, best.mean.x_m);
  EXPECT_GT(e.covariance(0, 0), 1.0) << "spread over the room";
  // Converged on a known pose, both are small and close.
  amcl->Initialize({2.0, 1.5, 0.3}, Covariance(0.05, 0.02));
  const PoseEstimate tight = amcl->Estimate();
  EXPECT_NEAR(tight.covariance(0, 0), 0.05 * 0.05, 0.001);
  EXPECT_EQ(tight.covariance(0, 2), 0.0);  // x/y-heading terms 0, as amcl
}

TEST_F(TextAmclTest, InitializeDrawsMaxParticlesFromTheGivenGaussian) {
  setup_.amcl.max_particles = 4000;
  auto amcl = test::MakeFilter(room_, nullptr, setup_);
  EXPECT_FALSE(amcl->initialized());
  EXPECT_THROW(amcl->Estimate(), std::logic_error);
  amcl->Initialize({2.0, 3.0, 3.0}, Covariance(0.2, 0.1));
  ASSERT_EQ(amcl->particles().size(), 4000u);
  double mx = 0, my = 0, vx = 0;
  for (const Particle& p : amcl->particles()) mx += p.pose.x_m / 4000, my += p.pose.y_m / 4000;
  for (const Particle& p : amcl->particles()) vx += std::pow(p.pose.x_m - mx, 2) / 3999;
  EXPECT_NEAR(mx, 2.0, 0.02);
  EXPECT_NEAR(my, 3.0, 0.02);
  EXPECT_NEAR(std::sqrt(vx), 0.2, 0.01);
  const PoseEstimate e = amcl->Estimate();  // headings around 3.0 rad wrap past pi: circular mean
  EXPECT_NEAR(NormalizeAngle(e.pose.theta_rad - 3.0), 0.0, 0.01);
  Eigen::Matrix3d not_psd = Eigen::Matrix3d::Identity();
  not_psd(0, 0) = -1.0;
  EXPECT_THROW(amcl->Initialize({}, not_psd), std::invalid_argument);
}

TEST_F(TextAmclTest, OdometryAndScansAreGatedLikeAmcl) {
  auto amcl = test::MakeFilter(room_, nullptr, setup_);
  amcl->Initialize({1.5, 2.5, 0.0}, Covariance(0.1, 0.05));
  const LaserScan scan = test::SyntheticScan(*room_, {1.5, 2.5, 0.0});
  EXPECT_FALSE(amcl->UpdateOdometry({0.0, 0.0, 0.0}));   // first odometry: reference only
  EXPECT_TRUE(amcl->UpdateLaser(scan));                  // the first scan after initialization is used
  EXPECT_FALSE(amcl->UpdateLaser(scan));                 // no motion since: skipped
  EXPECT_FALSE(amcl->UpdateOdometry({0.15, 0.0, 0.0}));  // < update_min_d (0.2 m)
  EXPECT_FALSE(amcl->UpdateLaser(scan));
  EXPECT_TRUE(amcl->UpdateOdometry({0.21, 0.0, 0.0}));   // 0.21 m since the last update
  EXPECT_TRUE(amcl->UpdateLaser(scan));
  EXPECT_FALSE(amcl->UpdateOdometry({0.21, 0.0, 0.5}));  // 0.5 rad < pi/6
  EXPECT_TRUE(amcl->UpdateOdometry({0.21, 0.0, 0.53}));  // 0.53 rad >= pi/6
  EXPECT_TRUE(amcl->UpdateLaser(scan));
  amcl->ForceUpdate();                                   // request_nomotion_update
  EXPECT_TRUE(amcl->UpdateLaser(scan));
  EXPECT_FALSE(amcl->UpdateLaser(scan));
  EXPECT_EQ(amcl->Status().laser_updates, 4);
  EXPECT_EQ(amcl->Status().resamples, 2);  // resample_interval 2
  LaserScan bad = scan;
  bad.angle_increment_rad = 0.0;
  amcl->ForceUpdate();
  EXPECT_THROW(amcl->UpdateLaser(bad), std::invalid_argument);
}

TEST_F(TextAmclTest, InitializeRestartsFromTheNextOdometryReading) {
  auto amcl = test::MakeFilter(room_, nullptr, setup_);
  amcl->Initialize({1.5, 2.5, 0.0}, Covariance(0.05, 0.02));
  EXPECT_FALSE(amcl->UpdateOdometry({0.0, 0.0, 0.0}));
  EXPECT_TRUE(amcl->UpdateOdometry({0.5, 0.0, 0.0}));
  // A new initial pose: odometry keeps counting from 0.5 m, but the pose holds at the next reading.
  amcl->Initialize({3.0, 2.5, 0.0}, Covariance(0.05, 0.02));
  EXPECT_FALSE(amcl->UpdateOdometry({0.6, 0.0, 0.0}));
  EXPECT_NEAR(amcl->Estimate().pose.x_m, 3.0, 0.01);
  EXPECT_TRUE(amcl->UpdateOdometry({0.9, 0.0, 0.0}));
  EXPECT_NEAR(amcl->Estimate().pose.x_m, 3.3, 0.02);
}

TEST_F(TextAmclTest, TracksARobotDrivingAroundTheRoom) {
  auto amcl = test::MakeFilter(room_, nullptr, setup_);
  test::Robot robot{{1.0, 0.6, 0.0}, {}};
  amcl->Initialize({1.2, 0.5, 0.1}, Covariance(0.3, 0.15));
  amcl->UpdateOdometry(robot.odom);
  // A loop around the inner box: east 3.2 m, north 2 m, west 3.2 m, south 2 m, turning 2 × 45° at corners.
  for (int leg = 0; leg < 4; ++leg) {
    test::Drive(amcl.get(), *room_, *no_plates_, &robot, leg % 2 == 0 ? 3.2 : 2.0, false, rng_);
    for (int k = 0; k < 2; ++k) test::Turn(amcl.get(), *room_, &robot, M_PI / 4, rng_);
    test::Settle(amcl.get(), *room_, robot, rng_);
    const PoseEstimate e = amcl->Estimate();
    EXPECT_LT(test::PositionError(e.pose, robot.truth), 0.1) << "leg " << leg;
    EXPECT_LT(std::fabs(NormalizeAngle(e.pose.theta_rad - robot.truth.theta_rad)), 0.05) << "leg " << leg;
  }
  EXPECT_EQ(amcl->State(), LocalizationState::kConverged);
  const TextAmclStatus s = amcl->Status();
  EXPECT_GT(s.best_cluster_weight, 0.9);
  EXPECT_LT(s.position_stddev_m, 0.3);
  EXPECT_LT(s.particle_count, 2500);  // KLD shrank the set from max_particles (5000) once converged
}

TEST_F(TextAmclTest, IsDeterministicForAGivenSeed) {
  const auto run = [&](std::uint64_t seed) {
    setup_.amcl.random_seed = seed;
    setup_.amcl.max_particles = 500;
    auto amcl = test::MakeFilter(room_, nullptr, setup_);
    amcl->GlobalLocalization();
    test::Robot robot{{1.0, 0.6, 0.0}, {}};
    std::mt19937_64 scan_rng(1);
    amcl->UpdateOdometry(robot.odom);
    test::Drive(amcl.get(), *room_, *no_plates_, &robot, 2.0, false, scan_rng);
    return amcl->particles();
  };
  const auto a = run(5), b = run(5), c = run(6);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].pose.x_m, b[i].pose.x_m);
    ASSERT_EQ(a[i].weight, b[i].weight);
  }
  EXPECT_TRUE(a.size() != c.size() || a[0].pose.x_m != c[0].pose.x_m);
}

// dynamic_reconfigure (issue 19): a filter continuing from another takes its particles and running state;
// under the same options it runs on exactly as the original would, under new ones the new bounds apply.
TEST_F(TextAmclTest, ContinueFromTakesTheParticlesAndRunsOnAsTheOriginal) {
  setup_.amcl.max_particles = 1000;
  auto original = test::MakeFilter(room_, nullptr, setup_);
  original->Initialize({2.0, 2.0, 0.0}, Covariance(0.2, 0.1));
  test::Robot robot{{2.0, 2.0, 0.0}, {0.0, 0.0, 0.0}};
  std::mt19937_64 scan_rng(5);
  test::Drive(original.get(), *room_, *no_plates_, &robot, 0.6, false, scan_rng);
  auto same = test::MakeFilter(room_, nullptr, setup_);
  same->ContinueFrom(*original);
  test::FilterSetup fewer = setup_;
  fewer.amcl.max_particles = 150;
  fewer.amcl.min_particles = 100;
  auto reconfigured = test::MakeFilter(room_, nullptr, fewer);
  reconfigured->ContinueFrom(*original);
  ASSERT_EQ(same->particles().size(), original->particles().size());
  EXPECT_EQ(reconfigured->particles().size(), original->particles().size()) << "kept until a resampling";
  EXPECT_EQ(same->Status().laser_updates, original->Status().laser_updates);
  test::Robot robot_same = robot, robot_reconfigured = robot;
  std::mt19937_64 rng_same = scan_rng, rng_reconfigured = scan_rng;
  test::Drive(original.get(), *room_, *no_plates_, &robot, 0.6, false, scan_rng);
  test::Drive(same.get(), *room_, *no_plates_, &robot_same, 0.6, false, rng_same);
  test::Drive(reconfigured.get(), *room_, *no_plates_, &robot_reconfigured, 0.6, false, rng_reconfigured);
  ASSERT_EQ(same->particles().size(), original->particles().size());
  for (size_t i = 0; i < same->particles().size(); ++i) {
    ASSERT_EQ(same->particles()[i].pose.x_m, original->particles()[i].pose.x_m) << i;
    ASSERT_EQ(same->particles()[i].weight, original->particles()[i].weight) << i;
  }
  EXPECT_LE(reconfigured->particles().size(), 150u) << "resampled into the new KLD bounds";
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/mcl/pose_clusters.h"

#include <gtest/gtest.h>

#include <cmath>

namespace doorplate_localization {
namespace {

TEST(ClusterParticles, SeparatesTwoHypothesesAndRanksThemByWeight) {
  std::vector<Particle> ps;
  for (int i = 0; i < 30; ++i) ps.push_back({{1.0 + 0.01 * i, 1.0, 0.1}, 0.01});   // weight 0.3
  for (int i = 0; i < 70; ++i) ps.push_back({{9.0 + 0.01 * i, 1.0, -3.0}, 0.01});  // weight 0.7
  const ClusterResult r = ClusterParticles(ps, {});
  ASSERT_EQ(r.clusters.size(), 2u);
  EXPECT_NEAR(r.clusters[0].weight, 0.7, 1e-9);
  EXPECT_EQ(r.clusters[0].particle_count, 70);
  EXPECT_NEAR(r.clusters[0].mean.x_m, 9.345, 1e-9);
  EXPECT_NEAR(r.clusters[0].mean.theta_rad, -3.0, 1e-9);
  EXPECT_NEAR(r.clusters[1].weight, 0.3, 1e-9);
  EXPECT_EQ(r.particle_cluster[0], 1);
  EXPECT_EQ(r.particle_cluster[99], 0);
}

TEST(ClusterParticles, JoinsTouchingBinsIncludingAcrossPlusMinusPi) {
  std::vector<Particle> ps{{{0.1, 0.1, M_PI - 0.02}, 0.25}, {{0.1, 0.1, -M_PI + 0.02}, 0.25},
                           {{0.6, 0.1, M_PI - 0.02}, 0.25}, {{1.1, 0.6, -M_PI + 0.02}, 0.25}};
  const ClusterResult r = ClusterParticles(ps, {});
  ASSERT_EQ(r.clusters.size(), 1u);  // a chain of neighbouring bins
  EXPECT_NEAR(std::fabs(r.clusters[0].mean.theta_rad), M_PI, 1e-9);  // circular mean, not 0
}

TEST(ParticleStatistics, ComputesTheWeightedCovariance) {
  std::vector<Particle> ps{{{0.1, 0.0, 0.2}, 1.0}, {{-0.1, 0.0, -0.2}, 1.0}, {{0.0, 0.2, 0.2}, 1.0},
                           {{0.0, -0.2, -0.2}, 1.0}};
  const PoseCluster c = ParticleStatistics(ps, {0, 1, 2, 3});
  EXPECT_NEAR(c.weight, 4.0, 1e-12);
  EXPECT_NEAR(c.mean.x_m, 0.0, 1e-12);
  EXPECT_NEAR(c.covariance(0, 0), 0.005, 1e-12);
  EXPECT_NEAR(c.covariance(1, 1), 0.02, 1e-12);
  EXPECT_NEAR(c.covariance(0, 1), 0.0, 1e-12);
  // Headings ±0.2: mean resultant length cos(0.2), variance -2 ln cos(0.2) ≈ 0.0402 (≈ 0.2²).
  EXPECT_NEAR(c.covariance(2, 2), -2.0 * std::log(std::cos(0.2)), 1e-12);
  EXPECT_NEAR(PositionStddev(c), std::sqrt(0.02), 1e-12);  // the y spread dominates
  EXPECT_NEAR(HeadingStddev(c), std::sqrt(-2.0 * std::log(std::cos(0.2))), 1e-12);
}

// amcl's overall filter covariance (amcl_pose): two hypotheses 10 m apart with equal weight give a variance
// of 25 m² along x, whatever each cluster's own spread.
TEST(SetStatistics, IsTheWholeSetsWeightedCovarianceAboutItsMean) {
  std::vector<Particle> ps{{{0.0, 0.0, 0.0}, 0.25}, {{0.0, 0.0, 0.0}, 0.25}, {{10.0, 0.0, 0.0}, 0.5}};
  const PoseCluster all = SetStatistics(ps);
  EXPECT_NEAR(all.mean.x_m, 5.0, 1e-12);
  EXPECT_NEAR(all.covariance(0, 0), 25.0, 1e-12);
  EXPECT_NEAR(all.covariance(1, 1), 0.0, 1e-12);
  EXPECT_NEAR(all.weight, 1.0, 1e-12);
  const ClusterResult clusters = ClusterParticles(ps, {});
  ASSERT_EQ(clusters.clusters.size(), 2u);
  EXPECT_NEAR(clusters.clusters[0].covariance(0, 0), 0.0, 1e-12);  // each hypothesis alone is a point
}

TEST(PositionStddev, IsTheLargestSpreadOfACorrelatedCloud) {
  PoseCluster c;
  c.covariance(0, 0) = c.covariance(1, 1) = 0.05;
  c.covariance(0, 1) = c.covariance(1, 0) = 0.04;  // eigenvalues 0.09 and 0.01
  EXPECT_NEAR(PositionStddev(c), 0.3, 1e-12);
}

}  // namespace
}  // namespace doorplate_localization

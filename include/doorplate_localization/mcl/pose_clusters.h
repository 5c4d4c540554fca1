// Clusters of the particle set, for the pose estimate (like amcl's cluster statistics): particles are
// binned in the pose histogram, bins touching each other (26-neighbourhood, headings wrapping) form a
// cluster, and each cluster gets its weight, weighted mean and covariance. The estimate is the mean of
// the heaviest cluster, so two hypotheses (a symmetric corridor, a repeated room number) do not average
// into a pose between them.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "doorplate_localization/mcl/particle.h"
#include "doorplate_localization/mcl/pose_histogram.h"

namespace doorplate_localization {

struct PoseCluster {
  double weight = 0.0;        // sum of its particles' weights (of a normalized set: a probability)
  int particle_count = 0;
  Pose2D mean;                // weighted mean position; heading: circular mean
  // Covariance of (x_m, y_m, theta_rad): the weighted x/y block; theta variance from the circular spread
  // (-2 ln R, R the mean resultant length); x/y–theta terms 0 (as amcl).
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
};

struct ClusterResult {
  std::vector<PoseCluster> clusters;  // heaviest first
  std::vector<int> particle_cluster;  // per particle: its cluster's index in `clusters`
};

// Throws std::invalid_argument for a non-positive bin size.
ClusterResult ClusterParticles(const std::vector<Particle>& particles, const PoseBinSize& bin_size);

// Weighted statistics of a subset of particles (indexes), as for one cluster.
PoseCluster ParticleStatistics(const std::vector<Particle>& particles, const std::vector<int>& indexes);

// The same statistics over the whole set (every particle, its own weight): amcl's overall filter
// covariance, published on amcl_pose.
PoseCluster SetStatistics(const std::vector<Particle>& particles);

// A cluster's position spread: the square root of the largest eigenvalue of its x/y covariance (m),
// and its heading spread sqrt(covariance(2, 2)) (rad).
double PositionStddev(const PoseCluster& cluster);
double HeadingStddev(const PoseCluster& cluster);

}  // namespace doorplate_localization

#include "doorplate_localization/mcl/pose_clusters.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace doorplate_localization {
namespace {

int Find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

PoseCluster ParticleStatistics(const std::vector<Particle>& particles, const std::vector<int>& indexes) {
  PoseCluster c;
  c.particle_count = static_cast<int>(indexes.size());
  if (indexes.empty()) return c;
  double total = 0.0;
  for (int i : indexes) total += particles[i].weight;
  c.weight = total;
  // Zero total weight: fall back to equal weights so the statistics stay defined.
  const bool equal = !(total > 0.0);
  const auto w = [&](int i) { return equal ? 1.0 / indexes.size() : particles[i].weight / total; };
  double mx = 0.0, my = 0.0, mc = 0.0, ms = 0.0;
  for (int i : indexes) {
    const Pose2D& p = particles[i].pose;
    mx += w(i) * p.x_m;
    my += w(i) * p.y_m;
    mc += w(i) * std::cos(p.theta_rad);
    ms += w(i) * std::sin(p.theta_rad);
  }
  c.mean = {mx, my, std::atan2(ms, mc)};
  for (int i : indexes) {
    const double dx = particles[i].pose.x_m - mx, dy = particles[i].pose.y_m - my;
    c.covariance(0, 0) += w(i) * dx * dx;
    c.covariance(0, 1) += w(i) * dx * dy;
    c.covariance(1, 1) += w(i) * dy * dy;
  }
  c.covariance(1, 0) = c.covariance(0, 1);
  const double resultant = std::clamp(std::hypot(mc, ms), 1e-12, 1.0);
  c.covariance(2, 2) = -2.0 * std::log(resultant);
  return c;
}

PoseCluster SetStatistics(const std::vector<Particle>& particles) {
  std::vector<int> all(particles.size());
  std::iota(all.begin(), all.end(), 0);
  return ParticleStatistics(particles, all);
}

double PositionStddev(const PoseCluster& cluster) {
  // Largest eigenvalue of the symmetric 2 × 2 block, closed form.
  const double a = cluster.covariance(0, 0), b = cluster.covariance(0, 1), d = cluster.covariance(1, 1);
  const double largest = 0.5 * (a + d) + std::sqrt(0.25 * (a - d) * (a - d) + b * b);
  return std::sqrt(std::max(0.0, largest));
}

double HeadingStddev(const PoseCluster& cluster) { return std::sqrt(std::max(0.0, cluster.covariance(2, 2))); }

ClusterResult ClusterParticles(const std::vector<Particle>& particles, const PoseBinSize& bin_size) {
  if (!(bin_size.xy_m > 0.0) || !(bin_size.theta_rad > 0.0)) {
    throw std::invalid_argument("ClusterParticles: bin_size: xy_m and theta_rad must be > 0");
  }
  ClusterResult result;
  std::unordered_map<std::uint64_t, int> bin_index;
  std::vector<PoseBin> bins;
  std::vector<int> particle_bin(particles.size());
  for (size_t i = 0; i < particles.size(); ++i) {
    const PoseBin bin = BinOf(particles[i].pose, bin_size);
    const auto [it, inserted] = bin_index.emplace(BinKey(bin), static_cast<int>(bins.size()));
    if (inserted) bins.push_back(bin);
    particle_bin[i] = it->second;
  }
  // Union-find over touching bins (26-neighbourhood, heading bins wrap around).
  const int n_theta = ThetaBinCount(bin_size);
  std::vector<int> parent(bins.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t b = 0; b < bins.size(); ++b) {
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dt = -1; dt <= 1; ++dt) {
          const PoseBin nb{bins[b].x + dx, bins[b].y + dy, (bins[b].theta + dt + n_theta) % n_theta};
          const auto it = bin_index.find(BinKey(nb));
          if (it != bin_index.end()) parent[Find(parent, static_cast<int>(b))] = Find(parent, it->second);
        }
      }
    }
  }
  std::unordered_map<int, int> cluster_of_root;
  std::vector<std::vector<int>> members;
  std::vector<int> label(particles.size());
  for (size_t i = 0; i < particles.size(); ++i) {
    const int root = Find(parent, particle_bin[i]);
    const auto [it, inserted] = cluster_of_root.emplace(root, static_cast<int>(members.size()));
    if (inserted) members.emplace_back();
    members[it->second].push_back(static_cast<int>(i));
    label[i] = it->second;
  }
  std::vector<PoseCluster> clusters;
  for (const auto& m : members) clusters.push_back(ParticleStatistics(particles, m));
  std::vector<int> order(clusters.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return clusters[a].weight > clusters[b].weight; });
  std::vector<int> rank(clusters.size());
  for (size_t r = 0; r < order.size(); ++r) {
    rank[order[r]] = static_cast<int>(r);
    result.clusters.push_back(clusters[order[r]]);
  }
  result.particle_cluster.resize(particles.size());
  for (size_t i = 0; i < particles.size(); ++i) result.particle_cluster[i] = rank[label[i]];
  return result;
}

}  // namespace doorplate_localization

#include "doorplate_localization/slam/scan_icp.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace doorplate_localization {

IcpReference::IcpReference(const std::vector<Vec2>& points, const ScanIcpOptions& options)
    : cell_m_(std::max(0.05, options.start_correspondence_m)) {
  const int n = static_cast<int>(points.size());
  for (int i = 0; i < n; ++i) {
    const double range = Norm(points[i]);
    const double gap = std::max(options.normal_gap_m, options.normal_gap_per_m * range);
    // The point and its neighbours in beam order that are close to it.
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    std::vector<Eigen::Vector2d> used;
    for (int k = -options.normal_neighbours; k <= options.normal_neighbours; ++k) {
      const int j = i + k;
      if (j < 0 || j >= n || Norm(points[j] - points[i]) > gap) continue;
      used.emplace_back(points[j].x, points[j].y);
      mean += used.back();
    }
    if (used.size() < 3) continue;
    mean /= static_cast<double>(used.size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (const Eigen::Vector2d& u : used) cov += (u - mean) * (u - mean).transpose();
    cov /= static_cast<double>(used.size());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
    const double residual = std::sqrt(std::max(0.0, eig.eigenvalues()(0)));
    if (residual > std::max(options.max_line_residual_m, options.max_line_residual_per_m * range)) continue;
    const Eigen::Vector2d normal = eig.eigenvectors().col(0).normalized();
    points_.push_back(points[i]);
    normals_.push_back({normal.x(), normal.y()});
  }
  for (int i = 0; i < size(); ++i) {
    cells_[Key(static_cast<int>(std::floor(points_[i].x / cell_m_)), static_cast<int>(std::floor(points_[i].y / cell_m_)))]
        .push_back(i);
  }
}

int IcpReference::Nearest(const Vec2& p, double max_distance_m) const {
  const int cx = static_cast<int>(std::floor(p.x / cell_m_)), cy = static_cast<int>(std::floor(p.y / cell_m_));
  const int reach = static_cast<int>(std::ceil(max_distance_m / cell_m_));
  int best = -1;
  double best_d2 = max_distance_m * max_distance_m;
  for (int dx = -reach; dx <= reach; ++dx) {
    for (int dy = -reach; dy <= reach; ++dy) {
      const auto it = cells_.find(Key(cx + dx, cy + dy));
      if (it == cells_.end()) continue;
      for (int i : it->second) {
        const Vec2 d = points_[i] - p;
        const double d2 = Dot(d, d);
        if (d2 < best_d2) best_d2 = d2, best = i;
      }
    }
  }
  return best;
}

ScanIcpResult AlignScans(const IcpReference& reference, const std::vector<Vec2>& query, const Pose2D& initial,
                         const ScanIcpOptions& options) {
  ScanIcpResult result;
  result.relative = initial;
  if (reference.size() < 3 || query.size() < 3) return result;
  double gate = options.start_correspondence_m;
  Eigen::Matrix3d h_final = Eigen::Matrix3d::Zero();
  int inliers = 0;
  double sum_r2 = 0.0;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    const Pose2D& t = result.relative;
    const double c = std::cos(t.theta_rad), s = std::sin(t.theta_rad);
    Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    inliers = 0;
    sum_r2 = 0.0;
    for (const Vec2& p : query) {
      const Vec2 q = t.TransformPoint(p);
      const int k = reference.Nearest(q, gate);
      if (k < 0) continue;
      const Vec2& n = reference.normals()[k];
      const double r = Dot(n, q - reference.points()[k]);
      if (std::abs(r) > gate) continue;
      const Vec2 dq{-s * p.x - c * p.y, c * p.x - s * p.y};  // ∂(R p)/∂θ
      const Eigen::Vector3d j(n.x, n.y, Dot(n, dq));
      h += j * j.transpose();
      g += j * r;
      sum_r2 += r * r;
      ++inliers;
    }
    result.iterations = iteration + 1;
    if (inliers < 3) return result;
    h_final = h;
    // Damping proportional to the scale of H keeps an unconstrained direction (along a corridor) where it is.
    const Eigen::Matrix3d damped = h + 1e-6 * std::max(1.0, h.trace()) * Eigen::Matrix3d::Identity();
    const Eigen::Vector3d delta = damped.ldlt().solve(-g);
    result.relative = {t.x_m + delta(0), t.y_m + delta(1), NormalizeAngle(t.theta_rad + delta(2))};
    const bool small = std::abs(delta(0)) < 1e-4 && std::abs(delta(1)) < 1e-4 && std::abs(delta(2)) < 1e-5;
    if (gate <= options.final_correspondence_m && small) break;
    gate = std::max(options.final_correspondence_m, gate * 0.7);
  }
  result.inlier_fraction = static_cast<double>(inliers) / static_cast<double>(query.size());
  result.rms_m = inliers > 0 ? std::sqrt(sum_r2 / inliers) : 0.0;
  result.aligned = inliers >= 3 && result.inlier_fraction >= options.min_inlier_fraction;
  if (result.aligned) {
    result.information = h_final * (options.effective_points / static_cast<double>(inliers)) /
                         (options.point_sigma_m * options.point_sigma_m);
  }
  return result;
}

}  // namespace doorplate_localization

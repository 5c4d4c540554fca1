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
    if (used.size() < 3) {
      no_line_.push_back(points[i]);
      continue;
    }
    mean /= static_cast<double>(used.size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (const Eigen::Vector2d& u : used) cov += (u - mean) * (u - mean).transpose();
    cov /= static_cast<double>(used.size());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
    const double residual = std::sqrt(std::max(0.0, eig.eigenvalues()(0)));
    if (residual > std::max(options.max_line_residual_m, options.max_line_residual_per_m * range)) {
      no_line_.push_back(points[i]);
      continue;
    }
    const Eigen::Vector2d normal = eig.eigenvectors().col(0).normalized();
    points_.push_back(points[i]);
    normals_.push_back({normal.x(), normal.y()});
  }
  for (int i = 0; i < size(); ++i) {
    cells_[Key(static_cast<int>(std::floor(points_[i].x / cell_m_)), static_cast<int>(std::floor(points_[i].y / cell_m_)))]
        .push_back(i);
  }
  for (int i = 0; i < static_cast<int>(no_line_.size()); ++i) {
    no_line_cells_[Key(static_cast<int>(std::floor(no_line_[i].x / cell_m_)),
                       static_cast<int>(std::floor(no_line_[i].y / cell_m_)))]
        .push_back(i);
  }
}

int IcpReference::NearestIfLine(const Vec2& p, double max_distance_m) const {
  const int k = Nearest(p, max_distance_m);
  if (k < 0) return -1;
  const Vec2 d = points_[k] - p;
  const double d2 = Dot(d, d);
  // Is an echo without a line closer than the nearest one with a line?
  const int cx = static_cast<int>(std::floor(p.x / cell_m_)), cy = static_cast<int>(std::floor(p.y / cell_m_));
  const int reach = static_cast<int>(std::ceil(std::sqrt(d2) / cell_m_));
  for (int dx = -reach; dx <= reach; ++dx) {
    for (int dy = -reach; dy <= reach; ++dy) {
      const auto it = no_line_cells_.find(Key(cx + dx, cy + dy));
      if (it == no_line_cells_.end()) continue;
      for (int i : it->second) {
        const Vec2 e = no_line_[i] - p;
        if (Dot(e, e) < d2) return -1;
      }
    }
  }
  return k;
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

namespace {

// The columns span the pose directions the correspondences constrain: heading always, and each
// translational eigen-direction of H's translational information (heading marginalised: the Schur
// complement) that holds at least `min_fraction` of the inliers' weight (Σ (n·v)² ≥ min_fraction ×
// inliers; a normal along v counts 1). The remaining directions are degenerate (Zhang & Singh,
// "On degeneracy of optimization-based state estimation problems", ICRA 2016).
Eigen::MatrixXd ConstrainedBasis(const Eigen::Matrix3d& h, double inliers, double min_fraction) {
  Eigen::Matrix2d translational = h.topLeftCorner<2, 2>();
  if (h(2, 2) > 0) translational -= h.block<2, 1>(0, 2) * h.block<1, 2>(2, 0) / h(2, 2);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(translational);
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(3, 1);
  basis(2, 0) = 1.0;
  for (int k = 0; k < 2; ++k) {
    if (eig.eigenvalues()(k) < min_fraction * inliers) continue;
    basis.conservativeResize(3, basis.cols() + 1);
    basis.col(basis.cols() - 1) << eig.eigenvectors()(0, k), eig.eigenvectors()(1, k), 0.0;
  }
  return basis;
}

}  // namespace

ScanIcpResult AlignScans(const IcpReference& reference, const std::vector<Vec2>& query, const Pose2D& initial,
                         const ScanIcpOptions& options) {
  ScanIcpResult result;
  result.relative = initial;
  if (reference.size() < 3 || query.size() < 3) return result;
  double gate = options.start_correspondence_m;
  Eigen::Matrix3d h_final = Eigen::Matrix3d::Zero();
  int inliers = 0;
  double weight = 0.0;  // Σ of the inliers' weights (= inliers unless share_reference_points)
  double sum_r2 = 0.0;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    const Pose2D& t = result.relative;
    const double c = std::cos(t.theta_rad), s = std::sin(t.theta_rad);
    Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    inliers = 0;
    sum_r2 = 0.0;
    struct Correspondence {
      int k;
      Eigen::Vector3d j;
      double r;
    };
    std::vector<Correspondence> matched;
    matched.reserve(query.size());
    for (const Vec2& p : query) {
      const Vec2 q = t.TransformPoint(p);
      const int k = options.skip_points_nearest_no_line ? reference.NearestIfLine(q, gate) : reference.Nearest(q, gate);
      if (k < 0) continue;
      const Vec2& n = reference.normals()[k];
      const double r = Dot(n, q - reference.points()[k]);
      if (std::abs(r) > gate) continue;
      const Vec2 dq{-s * p.x - c * p.y, c * p.x - s * p.y};  // ∂(R p)/∂θ
      matched.push_back({k, Eigen::Vector3d(n.x, n.y, Dot(n, dq)), r});
    }
    // Shared reference points: the m query points on one reference point's line count 1/m each.
    std::vector<int> uses;
    if (options.share_reference_points) {
      uses.assign(reference.size(), 0);
      for (const Correspondence& m : matched) ++uses[m.k];
    }
    weight = 0.0;
    for (const Correspondence& m : matched) {
      const double w = options.share_reference_points ? 1.0 / uses[m.k] : 1.0;
      h += w * m.j * m.j.transpose();
      g += w * m.j * m.r;
      sum_r2 += m.r * m.r;
      weight += w;
      ++inliers;
    }
    result.iterations = iteration + 1;
    if (inliers < 3) return result;
    h_final = h;
    Eigen::Vector3d delta;
    if (options.degenerate_min_fraction > 0) {
      // Move only along the constrained directions: along a degenerate one the guess is kept.
      const Eigen::MatrixXd p = ConstrainedBasis(h, weight, options.degenerate_min_fraction);
      const Eigen::MatrixXd reduced = p.transpose() * h * p;
      delta = p * reduced.ldlt().solve(-p.transpose() * g);
    } else {
      // Damping proportional to the scale of H keeps an unconstrained direction where it is.
      const Eigen::Matrix3d damped = h + 1e-6 * std::max(1.0, h.trace()) * Eigen::Matrix3d::Identity();
      delta = damped.ldlt().solve(-g);
    }
    result.relative = {t.x_m + delta(0), t.y_m + delta(1), NormalizeAngle(t.theta_rad + delta(2))};
    const bool small = std::abs(delta(0)) < 1e-4 && std::abs(delta(1)) < 1e-4 && std::abs(delta(2)) < 1e-5;
    if (gate <= options.final_correspondence_m && small) break;
    gate = std::max(options.final_correspondence_m, gate * 0.7);
  }
  result.inlier_fraction = static_cast<double>(inliers) / static_cast<double>(query.size());
  result.rms_m = inliers > 0 ? std::sqrt(sum_r2 / inliers) : 0.0;
  result.aligned = inliers >= 3 && result.inlier_fraction >= options.min_inlier_fraction;
  if (result.aligned) {
    Eigen::Matrix3d h_used = h_final;
    if (options.degenerate_min_fraction > 0) {  // no information along a degenerate direction
      const Eigen::MatrixXd p = ConstrainedBasis(h_final, weight, options.degenerate_min_fraction);
      result.degenerate = p.cols() < 3;
      const Eigen::MatrixXd projector = p * p.transpose();
      h_used = projector * h_final * projector;
    }
    result.information = h_used * (options.effective_points / weight) /
                         (options.point_sigma_m * options.point_sigma_m);
  }
  return result;
}

}  // namespace doorplate_localization

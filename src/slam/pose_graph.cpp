#include "doorplate_localization/slam/pose_graph.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

namespace doorplate_localization {
namespace {

constexpr double kFixedNodeInformation = 1e12;  // node 0 defines the map frame

bool Finite(const Pose2D& p) { return std::isfinite(p.x_m) && std::isfinite(p.y_m) && std::isfinite(p.theta_rad); }

// R(θ)ᵀ and its derivative by θ.
Eigen::Matrix2d RotationTransposed(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d r;
  r << c, s, -s, c;
  return r;
}
Eigen::Matrix2d RotationTransposedDerivative(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d r;
  r << -s, c, -c, -s;
  return r;
}

// Huber: weight of the quadratic cost and the cost itself, for Mahalanobis distance m.
double HuberWeight(double m, double k) { return m <= k ? 1.0 : k / m; }
double HuberCost(double m, double k) { return m <= k ? 0.5 * m * m : k * m - 0.5 * k * k; }

struct PoseResidual {
  Eigen::Vector3d e;
  Eigen::Matrix3d d_from;   // ∂e/∂(x, y, θ) of the from node
  Eigen::Matrix3d d_to;     // ∂e/∂(x, y, θ) of the to node
  Eigen::Vector3d d_scale;  // ∂e/∂scale (zero unless odometry)
  Eigen::Vector3d d_drift;  // ∂e/∂heading drift (zero unless odometry)
};

PoseResidual Evaluate(const PoseEdge& edge, const Pose2D& a, const Pose2D& b, double scale, double drift) {
  const double s = edge.odometry ? scale : 1.0;
  const double distance = edge.odometry ? std::hypot(edge.measurement.x_m, edge.measurement.y_m) : 0.0;
  const Eigen::Vector2d d(b.x_m - a.x_m, b.y_m - a.y_m);
  const Eigen::Vector2d t(edge.measurement.x_m, edge.measurement.y_m);
  const Eigen::Matrix2d rt = RotationTransposed(a.theta_rad);
  PoseResidual r;
  r.e.head<2>() = rt * d - s * t;
  r.e(2) = NormalizeAngle(b.theta_rad - a.theta_rad - edge.measurement.theta_rad - drift * distance);
  r.d_from.setZero();
  r.d_from.topLeftCorner<2, 2>() = -rt;
  r.d_from.block<2, 1>(0, 2) = RotationTransposedDerivative(a.theta_rad) * d;
  r.d_from(2, 2) = -1.0;
  r.d_to.setZero();
  r.d_to.topLeftCorner<2, 2>() = rt;
  r.d_to(2, 2) = 1.0;
  r.d_scale.setZero();
  if (edge.odometry) r.d_scale.head<2>() = -t;
  r.d_drift.setZero();
  r.d_drift(2) = -distance;
  return r;
}

// Whether the step `delta` (3 per node: x, y, θ; 2 per landmark; then the scale and the drift) moves every
// position below options.min_step_m and every angle, the scale and the drift below options.min_step_rad.
bool StepIsBelow(const Eigen::VectorXd& delta, int nodes, int landmarks, const PoseGraphOptions& options) {
  for (int k = 0; k < delta.size(); ++k) {
    const bool position = k < 3 * nodes ? k % 3 != 2 : k < 3 * nodes + 2 * landmarks;
    if (std::abs(delta(k)) >= (position ? options.min_step_m : options.min_step_rad)) return false;
  }
  return true;
}

}  // namespace

int PoseGraph::AddNode(const Pose2D& initial_estimate) {
  if (!Finite(initial_estimate)) throw std::invalid_argument("PoseGraph::AddNode: non-finite pose");
  nodes_.push_back(initial_estimate);
  return num_nodes() - 1;
}

int PoseGraph::AddLandmark(const Vec2& initial_estimate) {
  if (!std::isfinite(initial_estimate.x) || !std::isfinite(initial_estimate.y)) {
    throw std::invalid_argument("PoseGraph::AddLandmark: non-finite position");
  }
  landmarks_.push_back(initial_estimate);
  return num_landmarks() - 1;
}

void PoseGraph::AddEdge(const PoseEdge& edge) {
  if (edge.from < 0 || edge.from >= num_nodes() || edge.to < 0 || edge.to >= num_nodes() || edge.from == edge.to) {
    throw std::invalid_argument("PoseGraph::AddEdge: node index " + std::to_string(edge.from) + " -> " +
                                std::to_string(edge.to) + " out of range or a self-loop");
  }
  if (!Finite(edge.measurement) || !edge.information.allFinite()) {
    throw std::invalid_argument("PoseGraph::AddEdge: non-finite measurement or information");
  }
  pose_edges_.push_back(edge);
}

void PoseGraph::AddEdge(const LandmarkEdge& edge) {
  if (edge.node < 0 || edge.node >= num_nodes() || edge.landmark < 0 || edge.landmark >= num_landmarks()) {
    throw std::invalid_argument("PoseGraph::AddEdge: landmark edge index out of range");
  }
  if (!std::isfinite(edge.measurement.x) || !std::isfinite(edge.measurement.y) || !edge.information.allFinite()) {
    throw std::invalid_argument("PoseGraph::AddEdge: non-finite landmark measurement or information");
  }
  landmark_edges_.push_back(edge);
}

double PoseGraph::SquaredResidual(const PoseEdge& edge) const {
  const PoseResidual r = Evaluate(edge, nodes_.at(edge.from), nodes_.at(edge.to), scale_, drift_);
  return r.e.dot(edge.information * r.e);
}

double PoseGraph::Cost(const PoseGraphOptions& options) const {
  double cost = 0.0;
  for (const PoseEdge& edge : pose_edges_) {
    const double m2 = SquaredResidual(edge);
    cost += edge.robust ? HuberCost(std::sqrt(std::max(0.0, m2)), options.huber_sigmas) : 0.5 * m2;
  }
  for (const LandmarkEdge& edge : landmark_edges_) {
    const Pose2D& p = nodes_[edge.node];
    const Eigen::Vector2d d(landmarks_[edge.landmark].x - p.x_m, landmarks_[edge.landmark].y - p.y_m);
    const Eigen::Vector2d e = RotationTransposed(p.theta_rad) * d - Eigen::Vector2d(edge.measurement.x, edge.measurement.y);
    cost += 0.5 * e.dot(edge.information * e);
  }
  if (options.estimate_odometry_scale) {
    cost += 0.5 * std::pow((scale_ - 1.0) / options.scale_prior_sigma, 2);
  }
  if (options.estimate_odometry_heading_drift) {
    cost += 0.5 * std::pow(drift_ / options.heading_drift_prior_sigma_rad_per_m, 2);
  }
  return cost;
}

PoseGraphSummary PoseGraph::Optimize(const PoseGraphOptions& options) {
  PoseGraphSummary summary;
  summary.initial_cost = summary.final_cost = Cost(options);
  if (nodes_.empty()) return summary;
  const int n_pose = 3 * num_nodes();
  // The drift is a variable of the system only when it is estimated (otherwise 0 and left out).
  const bool with_drift = options.estimate_odometry_heading_drift;
  const int scale_index = n_pose + 2 * num_landmarks(), drift_index = scale_index + 1;
  const int n = with_drift ? drift_index + 1 : scale_index + 1;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
    const auto add_block = [&](int row, int col, const Eigen::MatrixXd& block) {
      for (int r = 0; r < block.rows(); ++r) {
        for (int c = 0; c < block.cols(); ++c) {
          if (block(r, c) != 0.0) triplets.emplace_back(row + r, col + c, block(r, c));
        }
      }
    };
    for (const PoseEdge& edge : pose_edges_) {
      const PoseResidual r = Evaluate(edge, nodes_[edge.from], nodes_[edge.to], scale_, drift_);
      double w = 1.0;
      if (edge.robust) w = HuberWeight(std::sqrt(std::max(0.0, r.e.dot(edge.information * r.e))), options.huber_sigmas);
      const Eigen::Matrix3d omega = w * edge.information;
      Eigen::Matrix<double, 3, 8> j;
      j << r.d_from, r.d_to, r.d_scale, r.d_drift;
      const Eigen::Matrix<double, 8, 8> h = j.transpose() * omega * j;
      const Eigen::Matrix<double, 8, 1> g = j.transpose() * omega * r.e;
      const int index[4] = {3 * edge.from, 3 * edge.to, scale_index, drift_index};
      const int size[4] = {3, 3, 1, 1};
      const int offset[4] = {0, 3, 6, 7};
      const int blocks = edge.odometry ? (with_drift ? 4 : 3) : 2;
      for (int p = 0; p < blocks; ++p) {
        b.segment(index[p], size[p]) += g.segment(offset[p], size[p]);
        for (int q = 0; q < blocks; ++q) add_block(index[p], index[q], h.block(offset[p], offset[q], size[p], size[q]));
      }
    }
    for (const LandmarkEdge& edge : landmark_edges_) {
      const Pose2D& p = nodes_[edge.node];
      const Eigen::Vector2d d(landmarks_[edge.landmark].x - p.x_m, landmarks_[edge.landmark].y - p.y_m);
      const Eigen::Matrix2d rt = RotationTransposed(p.theta_rad);
      const Eigen::Vector2d e = rt * d - Eigen::Vector2d(edge.measurement.x, edge.measurement.y);
      Eigen::Matrix<double, 2, 5> j;
      j.block<2, 2>(0, 0) = -rt;
      j.block<2, 1>(0, 2) = RotationTransposedDerivative(p.theta_rad) * d;
      j.block<2, 2>(0, 3) = rt;
      const Eigen::Matrix<double, 5, 5> h = j.transpose() * edge.information * j;
      const Eigen::Matrix<double, 5, 1> g = j.transpose() * edge.information * e;
      const int node = 3 * edge.node, landmark = n_pose + 2 * edge.landmark;
      b.segment<3>(node) += g.head<3>();
      b.segment<2>(landmark) += g.tail<2>();
      add_block(node, node, h.topLeftCorner<3, 3>());
      add_block(node, landmark, h.topRightCorner<3, 2>());
      add_block(landmark, node, h.bottomLeftCorner<2, 3>());
      add_block(landmark, landmark, h.bottomRightCorner<2, 2>());
    }
    for (int k = 0; k < 3; ++k) triplets.emplace_back(k, k, kFixedNodeInformation);
    if (options.estimate_odometry_scale) {
      const double inv = 1.0 / (options.scale_prior_sigma * options.scale_prior_sigma);
      triplets.emplace_back(scale_index, scale_index, inv);
      b(scale_index) += inv * (scale_ - 1.0);
    } else {
      triplets.emplace_back(scale_index, scale_index, kFixedNodeInformation);
    }
    if (with_drift) {
      const double inv = 1.0 / (options.heading_drift_prior_sigma_rad_per_m * options.heading_drift_prior_sigma_rad_per_m);
      triplets.emplace_back(drift_index, drift_index, inv);
      b(drift_index) += inv * drift_;
    }
    // A touch of damping keeps landmarks seen once and weakly tied nodes well posed.
    for (int k = 0; k < n; ++k) triplets.emplace_back(k, k, 1e-9);
    Eigen::SparseMatrix<double> h(n, n);
    h.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> solver(h);
    if (solver.info() != Eigen::Success) {
      summary.solver_ok = false;
      break;
    }
    const Eigen::VectorXd delta = solver.solve(-b);
    if (solver.info() != Eigen::Success || !delta.allFinite()) {
      summary.solver_ok = false;
      break;
    }
    // Apply with step halving while the cost rises (Gauss-Newton can overshoot with robust edges).
    const std::vector<Pose2D> nodes_before = nodes_;
    const std::vector<Vec2> landmarks_before = landmarks_;
    const double scale_before = scale_, drift_before = drift_;
    const double cost_before = summary.final_cost;
    double step = 1.0, cost = cost_before;
    for (int halving = 0; halving < 8; ++halving, step *= 0.5) {
      for (int i = 0; i < num_nodes(); ++i) {
        nodes_[i] = {nodes_before[i].x_m + step * delta(3 * i), nodes_before[i].y_m + step * delta(3 * i + 1),
                     NormalizeAngle(nodes_before[i].theta_rad + step * delta(3 * i + 2))};
      }
      for (int i = 0; i < num_landmarks(); ++i) {
        landmarks_[i] = {landmarks_before[i].x + step * delta(n_pose + 2 * i),
                         landmarks_before[i].y + step * delta(n_pose + 2 * i + 1)};
      }
      scale_ = options.estimate_odometry_scale ? scale_before + step * delta(scale_index) : 1.0;
      drift_ = with_drift ? drift_before + step * delta(drift_index) : 0.0;
      cost = Cost(options);
      if (cost <= cost_before) break;
    }
    summary.iterations = iteration + 1;
    if (cost > cost_before) {  // no improvement at any step: keep the previous estimate
      nodes_ = nodes_before;
      landmarks_ = landmarks_before;
      scale_ = scale_before;
      drift_ = drift_before;
      break;
    }
    summary.final_cost = cost;
    if (StepIsBelow(step * delta, num_nodes(), num_landmarks(), options)) break;
  }
  return summary;
}

}  // namespace doorplate_localization

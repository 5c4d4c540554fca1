// A sparse 2D pose graph with point landmarks and one odometry scale factor, solved by Gauss-Newton
// with SuiteSparse CHOLMOD (Eigen's CholmodSupport) on the normal equations. The back end of text SLAM
// (slam_back_end.h): nodes are the processed scans' poses, edges come from odometry, scan alignment and
// doorplate readings (paper Sec. 3.3: the plates and the odometry between them, eqs. 13-14).
//
// Frames: node poses and landmark positions are in the map frame; every measurement is expressed in the
// frame of its `from` node. Units: metres, radians. Information matrices are inverse covariances in
// those units (translation x, y in the from-node's frame, then heading).
//
// Odometry scale (Kümmerle et al., "Simultaneous calibration, localization, and mapping", IROS 2011):
// wheel odometry with a wrong wheel radius measures every distance (1 + e) times the truth. An odometry
// edge predicts the translation `scale × measured`, and `scale` is one more unknown. Where the laser fixes
// motion along the corridor (an end wall in range) the alignment edges pin the true steps, so the scale
// is calibrated there and corrects the steps where nothing but odometry says how far the robot went.
// Odometry heading drift (the same paper's calibration, Borenstein's "unequal wheel diameters" error): wheels
// of slightly different radii turn the measured heading by a systematic `drift × distance` (rad per metre
// of measured translation). An odometry edge predicts the heading change `measured + drift × |measured
// translation|`, and `drift` is one more unknown, calibrated where the scans fix the heading.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct PoseGraphOptions {
  int max_iterations = 30;
  // Stop when a Gauss-Newton step moves no position (node or landmark) by min_step_m or more and no
  // heading, the odometry scale or the heading drift (rad/m) by min_step_rad or more. The robust (Huber)
  // edges make the convergence linear, ~4x per iteration near the end; a step of 0.1 mm is far below the
  // map's 5 cm cells (a 1e-7 stop took twice the iterations for nothing: docs/results/back-end-speed.md).
  double min_step_m = 1e-4;
  double min_step_rad = 1e-5;
  double huber_sigmas = 3.0;        // robust edges: Huber kernel beyond this Mahalanobis distance
  double scale_prior_sigma = 0.05;  // odometry scale ~ N(1, σ²) when it is estimated
  bool estimate_odometry_scale = true;
  double heading_drift_prior_sigma_rad_per_m = 0.01;  // heading drift ~ N(0, σ²) when it is estimated
  bool estimate_odometry_heading_drift = false;  // tried on the real logs: no gain (docs/slam.md)
};

// A measured pose of node `to` in the frame of node `from`.
struct PoseEdge {
  int from = 0;
  int to = 0;
  Pose2D measurement;
  Eigen::Matrix3d information = Eigen::Matrix3d::Identity();
  bool odometry = false;  // the translation is scaled by the odometry scale, the heading drift is added
  bool robust = false;    // Huber kernel (loop closures, which may be wrong)
};

// A measured position of landmark `landmark` in the frame of node `node`.
struct LandmarkEdge {
  int node = 0;
  int landmark = 0;
  Vec2 measurement;
  Eigen::Matrix2d information = Eigen::Matrix2d::Identity();
};

struct PoseGraphSummary {
  int iterations = 0;
  double initial_cost = 0.0;  // ½ Σ eᵀ Ω e (robust edges with the Huber cost)
  double final_cost = 0.0;
  bool solver_ok = true;      // false if CHOLMOD found the system not positive definite
};

class PoseGraph {
 public:
  // Returns the new node's index. The first node is held fixed (it defines the map frame).
  int AddNode(const Pose2D& initial_estimate);
  int AddLandmark(const Vec2& initial_estimate);
  // Throw std::invalid_argument for an index out of range or a non-finite value.
  void AddEdge(const PoseEdge& edge);
  void AddEdge(const LandmarkEdge& edge);

  PoseGraphSummary Optimize(const PoseGraphOptions& options);
  // eᵀ Ω e of `edge` at the current estimate (odometry edges with the current odometry scale); the edge
  // need not be in the graph, its node indices must be (std::out_of_range otherwise).
  double SquaredResidual(const PoseEdge& edge) const;

  int num_nodes() const { return static_cast<int>(nodes_.size()); }
  int num_landmarks() const { return static_cast<int>(landmarks_.size()); }
  const Pose2D& node(int i) const { return nodes_.at(i); }
  const Vec2& landmark(int i) const { return landmarks_.at(i); }
  // Estimated odometry distance ÷ true distance is 1 / scale; 1 when not estimated.
  double odometry_scale() const { return scale_; }
  // Estimated true heading change − measured heading change, per metre of measured translation (rad/m); 0
  // when not estimated.
  double odometry_heading_drift_rad_per_m() const { return drift_; }

 private:
  double Cost(const PoseGraphOptions& options) const;

  std::vector<Pose2D> nodes_;
  std::vector<Vec2> landmarks_;
  std::vector<PoseEdge> pose_edges_;
  std::vector<LandmarkEdge> landmark_edges_;
  double scale_ = 1.0;
  double drift_ = 0.0;  // rad per metre of measured odometry translation
};

}  // namespace doorplate_localization

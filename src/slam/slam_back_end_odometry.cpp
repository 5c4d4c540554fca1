// The back end's odometry: the noise of one odometry step, the odometry edges of the graph, and the gate
// that drops sequential alignments the odometry contradicts (slam_back_end.h).
#include <cmath>
#include <utility>

#include "doorplate_localization/slam/slam_back_end.h"

namespace doorplate_localization {

std::pair<double, double> SlamBackEnd::OdometryVariances(const Pose2D& step) const {
  const double d = std::hypot(step.x_m, step.y_m);
  const double turn = std::abs(step.theta_rad);
  return {options_.odometry_trans_m2_per_m * d + options_.odometry_trans_m2_per_rad * turn +
              options_.odometry_min_sigma_m * options_.odometry_min_sigma_m,
          options_.odometry_rot_rad2_per_m * d + options_.odometry_rot_rad2_per_rad * turn +
              options_.odometry_min_sigma_rad * options_.odometry_min_sigma_rad};
}

bool SlamBackEnd::AgreesWithOdometry(const Pose2D& odometry, const Pose2D& aligned) const {
  if (!(options_.sequential_gate_sigmas > 0)) return true;
  const double d = std::hypot(odometry.x_m, odometry.y_m);
  const auto [step_var_t, step_var_r] = OdometryVariances(odometry);
  const double var_t = step_var_t + options_.graph.scale_prior_sigma * options_.graph.scale_prior_sigma * d * d;
  const double drift_sigma =
      options_.graph.estimate_odometry_heading_drift ? options_.graph.heading_drift_prior_sigma_rad_per_m : 0.0;
  const double var_r = step_var_r + drift_sigma * drift_sigma * d * d;
  const double dx = aligned.x_m - odometry.x_m, dy = aligned.y_m - odometry.y_m;
  const double dtheta = NormalizeAngle(aligned.theta_rad - odometry.theta_rad);
  const double gate = options_.sequential_gate_sigmas * options_.sequential_gate_sigmas;
  return (dx * dx + dy * dy) / var_t <= gate && dtheta * dtheta / var_r <= gate;
}

PoseEdge SlamBackEnd::OdometryEdge(int from, int to) const {
  PoseEdge edge;
  edge.from = from;
  edge.to = to;
  edge.odometry = true;
  edge.measurement = nodes_[from].odometry.Between(nodes_[to].odometry);
  const auto [var_t, var_r] = OdometryVariances(edge.measurement);
  edge.information = Eigen::Vector3d(1.0 / var_t, 1.0 / var_t, 1.0 / var_r).asDiagonal();
  return edge;
}

}  // namespace doorplate_localization

#include "doorplate_localization/sim/odometry_simulator.h"

#include <cmath>

namespace doorplate_localization {

OdometrySimulator::OdometrySimulator(const OdometryNoiseOptions& options, Pose2D start_odom_pose)
    : options_(options), odom_pose_(start_odom_pose) {}

Pose2D OdometrySimulator::Update(const Pose2D& true_before, const Pose2D& true_after, std::mt19937_64& rng) {
  // Decompose the true step into rot1, trans, rot2; driving backwards is a negative trans, not a half turn.
  const double dx = true_after.x_m - true_before.x_m, dy = true_after.y_m - true_before.y_m;
  double trans = std::hypot(dx, dy);
  double rot1 = trans > 1e-9 ? NormalizeAngle(std::atan2(dy, dx) - true_before.theta_rad) : 0.0;
  if (std::fabs(rot1) > M_PI / 2) {
    rot1 = NormalizeAngle(rot1 - M_PI);
    trans = -trans;
  }
  const double rot2 = NormalizeAngle(true_after.theta_rad - true_before.theta_rad - rot1);
  const double abs_trans = std::fabs(trans);

  // Random walks: variance proportional to the motion, so the error does not depend on the step size.
  auto gauss = [&rng](double variance) {
    return variance > 0.0 ? std::normal_distribution<double>(0.0, std::sqrt(variance))(rng) : 0.0;
  };
  const double o = options_.alpha1_rad2_per_rad, p = options_.alpha2_rad2_per_m;
  const double q = options_.alpha3_m2_per_m, r = options_.alpha4_m2_per_rad;
  const double drift = 0.5 * options_.heading_drift_rad_per_m * abs_trans;
  const double rot1_hat = rot1 + drift + gauss(o * std::fabs(rot1) + p * abs_trans);
  const double trans_hat = trans * (1.0 + options_.scale_error) +
                           gauss(q * abs_trans + r * (std::fabs(rot1) + std::fabs(rot2)));
  const double rot2_hat = rot2 + drift + gauss(o * std::fabs(rot2) + p * abs_trans);

  const double heading = odom_pose_.theta_rad + rot1_hat;
  odom_pose_.x_m += trans_hat * std::cos(heading);
  odom_pose_.y_m += trans_hat * std::sin(heading);
  odom_pose_.theta_rad = NormalizeAngle(heading + rot2_hat);
  odometer_m_ += std::fabs(trans_hat);
  return odom_pose_;
}

}  // namespace doorplate_localization

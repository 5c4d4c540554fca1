#include "doorplate_localization/sim/odometry_simulator.h"

#include <cmath>
#include <stdexcept>

namespace doorplate_localization {
namespace {

const OdometryNoiseOptions& Checked(const OdometryNoiseOptions& options) {
  const OdometrySlipOptions& slip = options.slip;
  if (!(slip.scale_stddev >= 0.0)) throw std::invalid_argument("odometry slip.scale_stddev must be >= 0");
  if (!(slip.scale_correlation_length_m > 0.0)) {
    throw std::invalid_argument("odometry slip.scale_correlation_length_m must be > 0");
  }
  if (!(std::fabs(slip.turn_rotation_error_rad_per_rad) < 0.5)) {
    throw std::invalid_argument("odometry slip.turn_rotation_error_rad_per_rad must be in (-0.5, 0.5)");
  }
  return options;
}

}  // namespace

OdometrySimulator::OdometrySimulator(const OdometryNoiseOptions& options, Pose2D start_odom_pose)
    : options_(Checked(options)), odom_pose_(start_odom_pose) {}

void OdometrySimulator::AdvanceSlipScale(double distance_m, std::mt19937_64& rng) {
  const double sigma = options_.slip.scale_stddev;
  if (sigma <= 0.0) return;
  std::normal_distribution<double> unit(0.0, 1.0);
  if (!slip_started_) {
    slip_scale_error_ = sigma * unit(rng);  // stationary from the start
    slip_started_ = true;
  }
  if (distance_m <= 0.0) return;
  // Exact discretisation: the same process whatever the step length.
  const double decay = std::exp(-distance_m / options_.slip.scale_correlation_length_m);
  slip_scale_error_ = decay * slip_scale_error_ + sigma * std::sqrt(1.0 - decay * decay) * unit(rng);
}

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
  // Slip (off by default; then no draws and exactly the arithmetic of the model without it).
  double rot1_slip = rot1, rot2_slip = rot2, trans_slip = trans * (1.0 + options_.scale_error);
  if (options_.slip.Enabled()) {
    AdvanceSlipScale(abs_trans, rng);
    const double gain = 1.0 + options_.slip.turn_rotation_error_rad_per_rad;
    rot1_slip = rot1 * gain;
    rot2_slip = rot2 * gain;
    trans_slip = trans * (1.0 + options_.scale_error + slip_scale_error_);
    if (abs_trans > 0.0) {
      trans_slip += std::copysign(options_.slip.turn_scale_error_m_per_rad * std::fabs(rot1 + rot2), trans);
    }
  }
  const double rot1_hat = rot1_slip + drift + gauss(o * std::fabs(rot1) + p * abs_trans);
  const double trans_hat = trans_slip + gauss(q * abs_trans + r * (std::fabs(rot1) + std::fabs(rot2)));
  const double rot2_hat = rot2_slip + drift + gauss(o * std::fabs(rot2) + p * abs_trans);

  const double heading = odom_pose_.theta_rad + rot1_hat;
  odom_pose_.x_m += trans_hat * std::cos(heading);
  odom_pose_.y_m += trans_hat * std::sin(heading);
  odom_pose_.theta_rad = NormalizeAngle(heading + rot2_hat);
  odometer_m_ += std::fabs(trans_hat);
  return odom_pose_;
}

}  // namespace doorplate_localization

#include "doorplate_localization/slam/motion_model.h"

#include <cmath>
#include <stdexcept>

namespace doorplate_localization {
namespace {

struct Decomposed {
  double rot1, trans, rot2;
  bool direction_known;  // false for moves shorter than min_translation_m
};

Decomposed Decompose(const Pose2D& delta, double min_translation_m) {
  constexpr double kStill = 1e-4;  // a move this short is no move: no first rotation, no noise from it
  const double trans = std::hypot(delta.x_m, delta.y_m);
  const bool known = trans >= min_translation_m || trans < kStill;
  const double rot1 = known && trans >= kStill ? std::atan2(delta.y_m, delta.x_m) : 0.0;
  return {rot1, trans, NormalizeAngle(delta.theta_rad - rot1), known};
}

// Magnitudes of the two rotations for the noise. A short move's direction is lost in the noise, and
// so is how the turn split into rot1 and rot2: take the first rotation as a quarter turn.
void RotationMagnitudes(const Decomposed& d, double* rot1, double* rot2) {
  constexpr double kQuarterTurn = 1.5707963267948966;
  *rot1 = d.direction_known ? std::abs(d.rot1) : kQuarterTurn;
  *rot2 = d.direction_known ? std::abs(d.rot2) : kQuarterTurn + std::abs(d.rot2);
}

}  // namespace

OdometryMotionModel::OdometryMotionModel(const MotionModelOptions& options) : options_(options) {
  if (options.trans_stddev_m_per_m < 0 || options.trans_stddev_m_per_rad < 0 ||
      options.rot_stddev_rad_per_m < 0 || options.rot_stddev_rad_per_rad < 0 ||
      options.min_translation_m < 0) {
    throw std::invalid_argument("MotionModelOptions: noise coefficients must be >= 0");
  }
}

StepSpread OdometryMotionModel::Spread(const Pose2D& odometry_delta) const {
  const Decomposed d = Decompose(odometry_delta, options_.min_translation_m);
  double r1, r2;
  RotationMagnitudes(d, &r1, &r2);
  const MotionModelOptions& o = options_;
  const double s_rot1 = o.rot_stddev_rad_per_rad * r1 + o.rot_stddev_rad_per_m * d.trans;
  const double s_rot2 = o.rot_stddev_rad_per_rad * r2 + o.rot_stddev_rad_per_m * d.trans;
  const double s_trans = o.trans_stddev_m_per_m * d.trans + o.trans_stddev_m_per_rad * (r1 + r2);
  return {std::hypot(s_trans, d.trans * s_rot1), std::hypot(s_rot1, s_rot2)};
}

StepSpread OdometryMotionModel::Accumulate(const StepSpread& a, const StepSpread& b) {
  return {std::hypot(a.linear_m, b.linear_m), std::hypot(a.angular_rad, b.angular_rad)};
}

Pose2D OdometryMotionModel::Sample(const Pose2D& from, const Pose2D& odometry_delta,
                                   const StepSpread& spread, std::mt19937_64& rng) {
  std::normal_distribution<double> unit(0.0, 1.0);
  const Pose2D moved = from.Compose(odometry_delta);
  const double nx = unit(rng) * spread.linear_m;
  const double ny = unit(rng) * spread.linear_m;
  const double nt = unit(rng) * spread.angular_rad;
  return {moved.x_m + nx, moved.y_m + ny, NormalizeAngle(moved.theta_rad + nt)};
}

}  // namespace doorplate_localization

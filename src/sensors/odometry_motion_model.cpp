#include "doorplate_localization/sensors/odometry_motion_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

constexpr double kQuarterTurn = 1.5707963267948966;
// With kDirectionUnknown, a move this short is no move: a turn in place, no noise from a direction.
constexpr double kStill_m = 1e-4;

void RequireNonNegative(const char* name, double value) {
  if (!std::isfinite(value) || value < 0.0) {
    throw std::invalid_argument(std::string("OdometryMotionModel: ") + name + ": must be finite and >= 0, got " +
                                std::to_string(value));
  }
}

// Size of a rotation for the noise.
double RotationForNoise(double rot_rad, bool reverse_is_forward) {
  return reverse_is_forward ? std::min(std::fabs(rot_rad), std::fabs(NormalizeAngle(rot_rad - M_PI)))
                            : std::fabs(rot_rad);
}

}  // namespace

OdometryMotionModelOptions MapperOdometryDefaults() {
  OdometryMotionModelOptions o;
  o.noise_law = OdometryNoiseLaw::kLinear;
  o.rot_noise_from_rot = 0.1;
  o.rot_noise_from_trans = 0.05;
  o.trans_noise_from_trans = 0.1;
  o.trans_noise_from_rot = 0.05;
  o.min_translation_for_heading_m = 0.05;
  o.short_move_rule = ShortMoveRule::kDirectionUnknown;
  o.reverse_is_forward = false;
  return o;
}

OdometryMotionModel::OdometryMotionModel(const OdometryMotionModelOptions& options) : options_(options) {
  RequireNonNegative("rot_noise_from_rot", options.rot_noise_from_rot);
  RequireNonNegative("rot_noise_from_trans", options.rot_noise_from_trans);
  RequireNonNegative("trans_noise_from_trans", options.trans_noise_from_trans);
  RequireNonNegative("trans_noise_from_rot", options.trans_noise_from_rot);
  RequireNonNegative("min_translation_for_heading_m", options.min_translation_for_heading_m);
}

OdometryStep OdometryMotionModel::Decompose(const Pose2D& before, const Pose2D& after) const {
  OdometryStep d;
  const double dx = after.x_m - before.x_m, dy = after.y_m - before.y_m;
  d.trans_m = std::hypot(dx, dy);
  d.rot1_rad = d.trans_m < options_.min_translation_for_heading_m
                   ? 0.0
                   : NormalizeAngle(std::atan2(dy, dx) - before.theta_rad);
  d.rot2_rad = NormalizeAngle(after.theta_rad - before.theta_rad - d.rot1_rad);
  return d;
}

OdometryStep OdometryMotionModel::NoiseStddev(const OdometryStep& m) const {
  const OdometryMotionModelOptions& o = options_;
  double r1 = RotationForNoise(m.rot1_rad, o.reverse_is_forward);
  double r2 = RotationForNoise(m.rot2_rad, o.reverse_is_forward);
  const double t = m.trans_m;
  if (o.short_move_rule == ShortMoveRule::kDirectionUnknown && t < o.min_translation_for_heading_m &&
      t >= kStill_m) {
    r1 = kQuarterTurn;
    r2 = kQuarterTurn + r2;
  }
  OdometryStep s;
  if (o.noise_law == OdometryNoiseLaw::kLinear) {
    s.rot1_rad = o.rot_noise_from_rot * r1 + o.rot_noise_from_trans * t;
    s.rot2_rad = o.rot_noise_from_rot * r2 + o.rot_noise_from_trans * t;
    s.trans_m = o.trans_noise_from_trans * t + o.trans_noise_from_rot * (r1 + r2);
    return s;
  }
  s.rot1_rad = o.rot_noise_from_rot * r1 * r1 + o.rot_noise_from_trans * t * t;
  s.trans_m = o.trans_noise_from_trans * t * t + o.trans_noise_from_rot * (r1 * r1 + r2 * r2);
  s.rot2_rad = o.rot_noise_from_rot * r2 * r2 + o.rot_noise_from_trans * t * t;
  if (o.noise_law == OdometryNoiseLaw::kDiffCorrected) {
    s.rot1_rad = std::sqrt(s.rot1_rad);
    s.trans_m = std::sqrt(s.trans_m);
    s.rot2_rad = std::sqrt(s.rot2_rad);
  }
  return s;
}

Pose2D OdometryStepSampler::Sample(const Pose2D& from, std::mt19937_64& rng) {
  const double rot1 = motion_.rot1_rad - stddev_.rot1_rad * unit_(rng);
  const double trans = motion_.trans_m - stddev_.trans_m * unit_(rng);
  const double rot2 = motion_.rot2_rad - stddev_.rot2_rad * unit_(rng);
  const double heading = from.theta_rad + rot1;
  return {from.x_m + trans * std::cos(heading), from.y_m + trans * std::sin(heading),
          NormalizeAngle(heading + rot2)};
}

StepSpread OdometryMotionModel::Spread(const Pose2D& before, const Pose2D& after) const {
  const OdometryStep m = Decompose(before, after);
  const OdometryStep s = NoiseStddev(m);
  return {std::hypot(s.trans_m, m.trans_m * s.rot1_rad), std::hypot(s.rot1_rad, s.rot2_rad)};
}

StepSpread OdometryMotionModel::Accumulate(const StepSpread& a, const StepSpread& b) {
  return {std::hypot(a.linear_m, b.linear_m), std::hypot(a.angular_rad, b.angular_rad)};
}

Pose2D OdometryMotionModel::SampleIsotropic(const Pose2D& from, const Pose2D& delta, const StepSpread& spread,
                                            std::mt19937_64& rng) {
  std::normal_distribution<double> unit(0.0, 1.0);
  const Pose2D moved = from.Compose(delta);
  const double nx = unit(rng) * spread.linear_m;
  const double ny = unit(rng) * spread.linear_m;
  const double nt = unit(rng) * spread.angular_rad;
  return {moved.x_m + nx, moved.y_m + ny, NormalizeAngle(moved.theta_rad + nt)};
}

}  // namespace doorplate_localization

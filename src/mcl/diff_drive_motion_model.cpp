#include "doorplate_localization/mcl/diff_drive_motion_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace doorplate_localization {
namespace {

// A rotation's size for the noise, treating driving backwards like driving forwards: rot1 = pi for a
// robot reversing straight back is no real rotation (amcl does the same).
double RotationForNoise(double rot_rad) {
  return std::min(std::fabs(rot_rad), std::fabs(NormalizeAngle(rot_rad - M_PI)));
}

}  // namespace

OdomModelType ParseOdomModelType(const std::string& name) {
  if (name == "diff") return OdomModelType::kDiff;
  if (name == "diff-corrected") return OdomModelType::kDiffCorrected;
  throw std::invalid_argument("odom_model_type: expected \"diff\" or \"diff-corrected\", got \"" + name + "\"");
}

DiffDriveMotionModel::DiffDriveMotionModel(const DiffDriveMotionModelOptions& options) : options_(options) {
  const double alphas[] = {options.odom_alpha1, options.odom_alpha2, options.odom_alpha3, options.odom_alpha4};
  for (int i = 0; i < 4; ++i) {
    if (!std::isfinite(alphas[i]) || alphas[i] < 0.0) {
      throw std::invalid_argument("DiffDriveMotionModel: odom_alpha" + std::to_string(i + 1) +
                                  ": must be finite and >= 0, got " + std::to_string(alphas[i]));
    }
  }
  if (!std::isfinite(options.min_translation_for_heading_m) || options.min_translation_for_heading_m < 0.0) {
    throw std::invalid_argument("DiffDriveMotionModel: min_translation_for_heading_m: must be >= 0");
  }
}

DiffDriveMotionModel::Decomposition DiffDriveMotionModel::Decompose(const Pose2D& before, const Pose2D& after) const {
  Decomposition d;
  const double dx = after.x_m - before.x_m, dy = after.y_m - before.y_m;
  d.trans_m = std::hypot(dx, dy);
  d.rot1_rad = d.trans_m < options_.min_translation_for_heading_m
                   ? 0.0
                   : NormalizeAngle(std::atan2(dy, dx) - before.theta_rad);
  d.rot2_rad = NormalizeAngle(after.theta_rad - before.theta_rad - d.rot1_rad);
  return d;
}

DiffDriveMotionModel::Decomposition DiffDriveMotionModel::NoiseStddev(const Decomposition& m) const {
  const double r1 = RotationForNoise(m.rot1_rad), r2 = RotationForNoise(m.rot2_rad), t = m.trans_m;
  const double a1 = options_.odom_alpha1, a2 = options_.odom_alpha2;
  const double a3 = options_.odom_alpha3, a4 = options_.odom_alpha4;
  Decomposition s;
  s.rot1_rad = a1 * r1 * r1 + a2 * t * t;
  s.trans_m = a3 * t * t + a4 * (r1 * r1 + r2 * r2);
  s.rot2_rad = a1 * r2 * r2 + a2 * t * t;
  if (options_.odom_model_type == OdomModelType::kDiffCorrected) {
    s.rot1_rad = std::sqrt(s.rot1_rad);
    s.trans_m = std::sqrt(s.trans_m);
    s.rot2_rad = std::sqrt(s.rot2_rad);
  }
  return s;
}

void DiffDriveMotionModel::Predict(const Pose2D& odom_before, const Pose2D& odom_after,
                                   std::vector<Particle>* particles, std::mt19937_64& rng) const {
  const Decomposition m = Decompose(odom_before, odom_after);
  const Decomposition s = NoiseStddev(m);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (Particle& p : *particles) {
    const double rot1 = m.rot1_rad - s.rot1_rad * unit(rng);
    const double trans = m.trans_m - s.trans_m * unit(rng);
    const double rot2 = m.rot2_rad - s.rot2_rad * unit(rng);
    const double heading = p.pose.theta_rad + rot1;
    p.pose.x_m += trans * std::cos(heading);
    p.pose.y_m += trans * std::sin(heading);
    p.pose.theta_rad = NormalizeAngle(heading + rot2);
  }
}

}  // namespace doorplate_localization

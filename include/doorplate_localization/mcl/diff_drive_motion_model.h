// amcl's differential-drive odometry models: sample_motion_model_odometry (Thrun et al., Probabilistic
// Robotics, table 5.6) — the motion is split into rot1 (turn towards the travel direction), trans
// (straight) and rot2 (final turn), each perturbed with zero-mean Gaussian noise growing with the motion.
#pragma once

#include <string>

#include "doorplate_localization/mcl/motion_model.h"

namespace doorplate_localization {

enum class OdomModelType {
  // amcl's "diff": the noise term α·δ² is used directly as the standard deviation (the unit-mixing
  // bug of ros-planning/navigation #20, kept for configurations tuned against it; noise grows with
  // the square of the motion).
  kDiff,
  // amcl's "diff-corrected" (nav2's DifferentialMotionModel): standard deviation sqrt(α·δ²), as in
  // the book. Needs smaller alphas than "diff" for the same spread.
  kDiffCorrected,
};

// "diff" or "diff-corrected" (amcl's odom_model_type values). Throws std::invalid_argument naming
// odom_model_type for anything else ("omni" models are not provided).
OdomModelType ParseOdomModelType(const std::string& name);

struct DiffDriveMotionModelOptions {
  OdomModelType odom_model_type = OdomModelType::kDiffCorrected;
  // Noise variances per unit of motion; with kDiffCorrected: rotation noise variance (rad²) =
  // odom_alpha1·rot² + odom_alpha2·trans², translation noise variance (m²) = odom_alpha3·trans² +
  // odom_alpha4·(rot1² + rot2²), where rot is in rad and trans in m. amcl/nav2 defaults: 0.2 each.
  double odom_alpha1 = 0.2;  // rotation noise from the robot's rotation (rad²/rad²)
  double odom_alpha2 = 0.2;  // rotation noise from translation (rad²/m²)
  double odom_alpha3 = 0.2;  // translation noise from translation (m²/m²)
  double odom_alpha4 = 0.2;  // translation noise from rotation (m²/rad²)
  // Below this translation the travel direction is undefined (rotation in place): rot1 = 0.
  double min_translation_for_heading_m = 0.01;
};

class DiffDriveMotionModel : public MotionModel {
 public:
  // Throws std::invalid_argument naming a negative or non-finite alpha.
  explicit DiffDriveMotionModel(const DiffDriveMotionModelOptions& options);

  void Predict(const Pose2D& odom_before, const Pose2D& odom_after, std::vector<Particle>* particles,
               std::mt19937_64& rng) const override;

  // The decomposition of a motion into (rot1_rad, trans_m, rot2_rad), without noise.
  struct Decomposition {
    double rot1_rad = 0.0;
    double trans_m = 0.0;
    double rot2_rad = 0.0;
  };
  Decomposition Decompose(const Pose2D& odom_before, const Pose2D& odom_after) const;
  // Standard deviations of the noise on rot1, trans and rot2 for a motion (what Predict samples).
  Decomposition NoiseStddev(const Decomposition& motion) const;

  const DiffDriveMotionModelOptions& options() const { return options_; }

 private:
  const DiffDriveMotionModelOptions options_;
};

}  // namespace doorplate_localization

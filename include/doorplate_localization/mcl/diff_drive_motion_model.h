// The localizer's motion step for a differential drive: amcl's sample_motion_model_odometry. Every
// particle moves by the odometry's (rot1, trans, rot2) with its own noise drawn from the one odometry
// motion model (sensors/odometry_motion_model.h), by default with amcl's "diff-corrected" law.
#pragma once

#include "doorplate_localization/mcl/motion_model.h"
#include "doorplate_localization/sensors/odometry_motion_model.h"

namespace doorplate_localization {

class DiffDriveMotionModel : public MotionModel {
 public:
  // Throws std::invalid_argument naming a negative or non-finite coefficient.
  explicit DiffDriveMotionModel(const OdometryMotionModelOptions& options);

  void Predict(const Pose2D& odom_before, const Pose2D& odom_after, std::vector<Particle>* particles,
               std::mt19937_64& rng) const override;

 private:
  const OdometryMotionModel model_;
};

}  // namespace doorplate_localization

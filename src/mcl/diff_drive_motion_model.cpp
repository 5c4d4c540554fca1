#include "doorplate_localization/mcl/diff_drive_motion_model.h"

namespace doorplate_localization {

DiffDriveMotionModel::DiffDriveMotionModel(const OdometryMotionModelOptions& options) : model_(options) {}

void DiffDriveMotionModel::Predict(const Pose2D& odom_before, const Pose2D& odom_after,
                                   std::vector<Particle>* particles, std::mt19937_64& rng) const {
  const OdometryStep motion = model_.Decompose(odom_before, odom_after);
  OdometryStepSampler sampler(motion, model_.NoiseStddev(motion));
  for (Particle& p : *particles) p.pose = sampler.Sample(p.pose, rng);
}

}  // namespace doorplate_localization

// Runs a TextAmcl on the test worlds: builds the filter with its models, and drives a simulated robot
// (exact odometry, ray-cast scans with noise, plate readings on the left as plates come abeam).
#pragma once

#include <memory>
#include <random>
#include <vector>

#include "doorplate_localization/mcl/diff_drive_motion_model.h"
#include "doorplate_localization/mcl/likelihood_field_model.h"
#include "doorplate_localization/mcl/plate_likelihood_model.h"
#include "doorplate_localization/mcl/plate_pose_sampler.h"
#include "doorplate_localization/mcl/text_amcl.h"
#include "mcl_fixtures.h"

namespace doorplate_localization::test {

struct FilterSetup {
  TextAmclOptions amcl;
  LikelihoodFieldModelOptions laser;
  OdometryMotionModelOptions motion;
  PlateLikelihoodModelOptions plate;
  PlatePoseSamplerOptions sampler;
  bool with_text = true;

  FilterSetup() {
    motion.rot_noise_from_rot = motion.rot_noise_from_trans = motion.trans_noise_from_trans = motion.trans_noise_from_rot = 0.02;
  }
};

inline std::unique_ptr<TextAmcl> MakeFilter(std::shared_ptr<const LocalizationGrid> grid,
                                            std::shared_ptr<const TextMap> text_map, const FilterSetup& setup) {
  TextAmclModels models;
  models.grid = grid;
  models.motion = std::make_shared<DiffDriveMotionModel>(setup.motion);
  models.laser = std::make_shared<LikelihoodFieldModel>(grid, setup.laser);
  models.resampler = std::make_shared<LowVarianceResampler>();
  if (setup.with_text && text_map) {
    models.text = std::make_shared<PlateLikelihoodModel>(text_map, grid, setup.plate);
    models.plate_sampler = std::make_shared<PlatePoseSampler>(text_map, grid, setup.sampler);
  }
  return std::make_unique<TextAmcl>(setup.amcl, models);
}

struct Robot {
  Pose2D truth;  // base_link in the map
  Pose2D odom;   // base_link in odom (exact odometry)
};

struct DriveLog {
  std::vector<int> plates_read;                   // landmark indexes
  std::vector<PlateUpdateResult> plate_results;   // one per plate read
  int scans_used = 0;
};

// Moves the robot `distance_m` along its heading (negative: backwards) in 5 cm steps, feeding odometry,
// a scan after every filter update, and — if `read_plates` — a reading (confidence 0.9, with range) of
// every plate on its left as it comes abeam.
inline DriveLog Drive(TextAmcl* amcl, const LocalizationGrid& grid, const TextMap& map, Robot* robot,
                      double distance_m, bool read_plates, std::mt19937_64& rng, bool with_range = true) {
  DriveLog log;
  const double step = distance_m >= 0 ? 0.05 : -0.05;
  const int steps = static_cast<int>(std::lround(distance_m / step));
  for (int i = 0; i < steps; ++i) {
    const Pose2D before = robot->truth;
    robot->truth = robot->truth.Compose({step, 0.0, 0.0});
    robot->odom = robot->odom.Compose({step, 0.0, 0.0});
    if (amcl->UpdateOdometry(robot->odom) && amcl->UpdateLaser(SyntheticScan(grid, robot->truth, &rng))) {
      ++log.scans_used;
    }
    if (!read_plates) continue;
    const int plate = PlateComingAbeam(map, before, robot->truth);
    if (plate < 0) continue;
    log.plates_read.push_back(plate);
    log.plate_results.push_back(amcl->UpdatePlate(ReadingOf(map.landmarks[plate], robot->truth, 0.9, with_range)));
  }
  return log;
}

// Turns the robot in place by `angle_rad` (odometry follows exactly) and updates the filter with a scan.
inline void Turn(TextAmcl* amcl, const LocalizationGrid& grid, Robot* robot, double angle_rad, std::mt19937_64& rng) {
  robot->truth = robot->truth.Compose({0.0, 0.0, angle_rad});
  robot->odom = robot->odom.Compose({0.0, 0.0, angle_rad});
  if (amcl->UpdateOdometry(robot->odom)) amcl->UpdateLaser(SyntheticScan(grid, robot->truth, &rng));
}

// Applies the odometry not yet used (less than update_min_d/a since the last update) with one forced
// update, so the estimate can be compared with the truth (amcl's request_nomotion_update).
inline void Settle(TextAmcl* amcl, const LocalizationGrid& grid, const Robot& robot, std::mt19937_64& rng) {
  amcl->ForceUpdate();
  amcl->UpdateOdometry(robot.odom);
  amcl->UpdateLaser(SyntheticScan(grid, robot.truth, &rng));
}

inline double PositionError(const Pose2D& a, const Pose2D& b) { return std::hypot(a.x_m - b.x_m, a.y_m - b.y_m); }

// Share of the particle weight within `radius_m` and `angle_rad` of `pose`.
inline double WeightNear(const TextAmcl& amcl, const Pose2D& pose, double radius_m = 1.0, double angle_rad = 0.5) {
  double w = 0.0;
  for (const Particle& p : amcl.particles()) {
    const double turn = std::fabs(NormalizeAngle(p.pose.theta_rad - pose.theta_rad));
    if (PositionError(p.pose, pose) < radius_m && turn < angle_rad) w += p.weight;
  }
  return w;
}

}  // namespace doorplate_localization::test

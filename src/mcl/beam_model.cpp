#include "doorplate_localization/mcl/beam_model.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "doorplate_localization/mcl/grid_ray_caster.h"

namespace doorplate_localization {

BeamModel::BeamModel(std::shared_ptr<const LocalizationGrid> grid, const BeamModelOptions& options)
    : grid_(std::move(grid)), options_(options) {
  if (!grid_) throw std::invalid_argument("BeamModel: grid: must not be null");
  const auto require = [](bool ok, const std::string& field, const std::string& rule, double value) {
    if (!ok) throw std::invalid_argument("BeamModel: " + field + ": " + rule + ", got " + std::to_string(value));
  };
  const auto& o = options_;
  for (auto [name, z] : {std::pair<const char*, double>{"z_hit", o.z_hit}, {"z_short", o.z_short},
                         {"z_max", o.z_max}, {"z_rand", o.z_rand}}) {
    require(std::isfinite(z) && z >= 0.0, name, "must be finite and >= 0", z);
  }
  require(o.z_hit + o.z_short + o.z_max + o.z_rand > 0.0, "z_hit + z_short + z_max + z_rand", "must be > 0", 0.0);
  require(std::isfinite(o.sigma_hit_m) && o.sigma_hit_m > 0.0, "sigma_hit_m", "must be > 0", o.sigma_hit_m);
  require(std::isfinite(o.lambda_short_per_m) && o.lambda_short_per_m >= 0.0, "lambda_short_per_m", "must be >= 0",
          o.lambda_short_per_m);
  require(o.beams.laser_max_beams >= 1, "laser_max_beams", "must be >= 1", o.beams.laser_max_beams);
}

double BeamModel::BeamProbability(double measured_m, double expected_m, double max_range_m) const {
  const auto& o = options_;
  const double z = measured_m - expected_m;
  double pz = o.z_hit * std::exp(-z * z / (2.0 * o.sigma_hit_m * o.sigma_hit_m));
  if (z < 0.0) pz += o.z_short * o.lambda_short_per_m * std::exp(-o.lambda_short_per_m * measured_m);
  if (measured_m >= max_range_m) {
    pz += o.z_max;
  } else {
    pz += o.z_rand / max_range_m;
  }
  return pz;
}

void BeamModel::LogLikelihoods(const LaserScan& scan, const std::vector<Particle>& particles,
                               std::vector<double>* log_likelihoods) {
  const std::vector<SelectedBeam> beams = SelectBeams(scan, options_.beams);
  const double max_range = EffectiveMaxRange(scan, options_.beams);
  const bool cube = options_.combination == BeamCombination::kAmclCubeSum;
  log_likelihoods->resize(particles.size());
  for (size_t i = 0; i < particles.size(); ++i) {
    const Pose2D laser = particles[i].pose.Compose(scan.laser_pose);
    double sum = 0.0;
    for (const SelectedBeam& beam : beams) {
      const double expected =
          CastRay(*grid_, laser.Position(), laser.theta_rad + beam.angle_rad, max_range, options_.unknown_blocks_rays);
      const double pz = BeamProbability(beam.range_m, expected, max_range);
      sum += cube ? pz * pz * pz : std::log(pz);
    }
    (*log_likelihoods)[i] = cube ? std::log1p(sum) : sum;
  }
}

}  // namespace doorplate_localization

#include "doorplate_localization/mcl/plate_likelihood_model.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "doorplate_localization/mcl/grid_ray_caster.h"

namespace doorplate_localization {

PlateLikelihoodModel::PlateLikelihoodModel(std::shared_ptr<const TextMap> text_map,
                                           std::shared_ptr<const LocalizationGrid> grid,
                                           const PlateLikelihoodModelOptions& options)
    : text_map_(std::move(text_map)), grid_(std::move(grid)), options_(options), matcher_(options.text_match) {
  const auto require = [](bool ok, const std::string& field, const std::string& rule, double value) {
    if (!ok) {
      throw std::invalid_argument("PlateLikelihoodModel: " + field + ": " + rule + ", got " + std::to_string(value));
    }
  };
  if (!text_map_) throw std::invalid_argument("PlateLikelihoodModel: text_map: must not be null");
  const auto& o = options_;
  require(std::isfinite(o.bearing_stddev_rad) && o.bearing_stddev_rad > 0.0, "bearing_stddev_rad", "must be > 0",
          o.bearing_stddev_rad);
  require(std::isfinite(o.range_stddev_m) && o.range_stddev_m > 0.0, "range_stddev_m", "must be > 0",
          o.range_stddev_m);
  require(o.min_view_distance_m >= 0.0, "min_view_distance_m", "must be >= 0", o.min_view_distance_m);
  require(o.max_view_distance_m > o.min_view_distance_m, "max_view_distance_m", "must exceed min_view_distance_m",
          o.max_view_distance_m);
  require(o.max_view_angle_rad > 0.0 && o.max_view_angle_rad <= M_PI, "max_view_angle_rad", "must be in (0, pi]",
          o.max_view_angle_rad);
  require(o.floor_probability > 0.0 && o.floor_probability < 1.0, "floor_probability", "must be in (0, 1)",
          o.floor_probability);
  require(o.line_of_sight_tolerance_m >= 0.0, "line_of_sight_tolerance_m", "must be >= 0",
          o.line_of_sight_tolerance_m);
}

bool PlateLikelihoodModel::InView(int landmark_index, Vec2 position) const {
  const TextLandmark& plate = text_map_->landmarks.at(landmark_index);
  const Vec2 to_robot = position - plate.pose.Position();
  const double distance = Norm(to_robot);
  if (distance < options_.min_view_distance_m || distance > options_.max_view_distance_m) return false;
  const Vec2 facing{std::cos(plate.pose.theta_rad), std::sin(plate.pose.theta_rad)};
  if (Dot(facing, to_robot) < distance * std::cos(options_.max_view_angle_rad)) return false;
  if (grid_ && options_.check_line_of_sight) {
    return HasLineOfSight(*grid_, position, plate.pose.Position(), options_.line_of_sight_tolerance_m);
  }
  return true;
}

double PlateLikelihoodModel::LikelihoodGiven(const PlateReading& reading, const std::vector<LandmarkMatch>& matches,
                                             const Pose2D& pose) const {
  double sum = 0.0;
  const double bearing_denom = 2.0 * options_.bearing_stddev_rad * options_.bearing_stddev_rad;
  const double range_denom = 2.0 * options_.range_stddev_m * options_.range_stddev_m;
  for (const LandmarkMatch& match : matches) {
    if (!InView(match.landmark_index, pose.Position())) continue;
    const Vec2 to_plate = text_map_->landmarks[match.landmark_index].pose.Position() - pose.Position();
    const double expected_bearing = std::atan2(to_plate.y, to_plate.x) - pose.theta_rad;
    const double bearing_error = NormalizeAngle(reading.bearing_rad - expected_bearing);
    double g = std::exp(-bearing_error * bearing_error / bearing_denom);
    if (reading.range_m) {
      const double range_error = *reading.range_m - Norm(to_plate);
      g *= std::exp(-range_error * range_error / range_denom);
    }
    sum += match.probability * g;
  }
  return options_.floor_probability + sum;
}

double PlateLikelihoodModel::Likelihood(const PlateReading& reading, const Pose2D& pose) const {
  const std::string error = ValidatePlateReading(reading);
  if (!error.empty()) throw std::invalid_argument(error);
  return LikelihoodGiven(reading, matcher_.Compatible(*text_map_, reading.text, reading.confidence), pose);
}

void PlateLikelihoodModel::LogLikelihoods(const PlateReading& reading, const std::vector<Particle>& particles,
                                          std::vector<double>* log_likelihoods) const {
  const std::string error = ValidatePlateReading(reading);
  if (!error.empty()) throw std::invalid_argument(error);
  const std::vector<LandmarkMatch> matches = matcher_.Compatible(*text_map_, reading.text, reading.confidence);
  log_likelihoods->resize(particles.size());
  for (size_t i = 0; i < particles.size(); ++i) {
    (*log_likelihoods)[i] = std::log(LikelihoodGiven(reading, matches, particles[i].pose));
  }
}

double PlateLikelihoodModel::UnexplainedLogLikelihood(const PlateReading&) const {
  return std::log(options_.floor_probability);
}

}  // namespace doorplate_localization

#include "doorplate_localization/mcl/plate_pose_sampler.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "doorplate_localization/mcl/grid_ray_caster.h"

namespace doorplate_localization {

PlatePoseSampler::PlatePoseSampler(std::shared_ptr<const TextMap> text_map,
                                   std::shared_ptr<const LocalizationGrid> grid, const PlatePoseSamplerOptions& options)
    : text_map_(std::move(text_map)), grid_(std::move(grid)), options_(options), matcher_(options.text_match) {
  const auto require = [](bool ok, const std::string& field, const std::string& rule, double value) {
    if (!ok) throw std::invalid_argument("PlatePoseSampler: " + field + ": " + rule + ", got " + std::to_string(value));
  };
  if (!text_map_) throw std::invalid_argument("PlatePoseSampler: text_map: must not be null");
  const auto& o = options_;
  require(o.range_stddev_m >= 0.0, "range_stddev_m", "must be >= 0", o.range_stddev_m);
  require(o.heading_stddev_rad >= 0.0, "heading_stddev_rad", "must be >= 0", o.heading_stddev_rad);
  require(o.max_view_angle_rad > 0.0 && o.max_view_angle_rad < M_PI / 2, "max_view_angle_rad", "must be in (0, pi/2)",
          o.max_view_angle_rad);
  require(o.min_view_distance_m >= 0.0, "min_view_distance_m", "must be >= 0", o.min_view_distance_m);
  require(o.typical_view_distance_min_m > 0.0 && o.typical_view_distance_max_m >= o.typical_view_distance_min_m,
          "typical_view_distance_min_m/max_m", "need 0 < min <= max", o.typical_view_distance_min_m);
  require(o.lateral_stddev_m >= 0.0, "lateral_stddev_m", "must be >= 0", o.lateral_stddev_m);
  require(o.wall_clearance_m >= 0.0, "wall_clearance_m", "must be >= 0", o.wall_clearance_m);
  require(o.max_attempts_per_pose >= 1, "max_attempts_per_pose", "must be >= 1", o.max_attempts_per_pose);
  require(o.parallel_heading_probability >= 0.0 && o.parallel_heading_probability <= 1.0,
          "parallel_heading_probability", "must be in [0, 1]", o.parallel_heading_probability);
  require(o.parallel_heading_stddev_rad >= 0.0, "parallel_heading_stddev_rad", "must be >= 0",
          o.parallel_heading_stddev_rad);
}

double PlatePoseSampler::FreeDepth(const TextLandmark& plate) const {
  const Vec2 normal{std::cos(plate.pose.theta_rad), std::sin(plate.pose.theta_rad)};
  const double res = grid_->resolution_m();
  const double max_depth = options_.typical_view_distance_max_m + options_.wall_clearance_m + 10.0;
  // The plate sits on the wall surface: step out of the wall's cells before casting along the normal.
  for (double offset = 0.5 * res; offset <= 0.5; offset += res) {
    const double free = CastRay(*grid_, plate.pose.Position() + offset * normal, plate.pose.theta_rad, max_depth);
    if (free > 0.0) return offset + free;
  }
  return 0.0;
}

bool PlatePoseSampler::DepthBand(const TextLandmark& plate, double* lo, double* hi) const {
  *lo = options_.typical_view_distance_min_m;
  *hi = options_.typical_view_distance_max_m;
  if (!grid_) return true;
  const double room = FreeDepth(plate) - options_.wall_clearance_m;  // farthest the robot can stand
  if (room < options_.wall_clearance_m) return false;               // no free band in front of the plate
  *hi = std::min(*hi, room);
  if (*hi < *lo) *lo = options_.wall_clearance_m;  // narrower than the typical distance: anywhere in the band
  return true;
}

bool PlatePoseSampler::SampleAt(const TextLandmark& plate, const PlateReading& reading, std::mt19937_64& rng,
                                Pose2D* pose) const {
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vec2 normal{std::cos(plate.pose.theta_rad), std::sin(plate.pose.theta_rad)};
  const Vec2 along{-normal.y, normal.x};
  double lo = 0.0, hi = 0.0;
  if (!reading.range_m && !DepthBand(plate, &lo, &hi)) return false;
  Vec2 offset;  // plate -> robot
  double heading = 0.0;
  if (unit(rng) < options_.parallel_heading_probability) {
    // Corridor prior: heading along the wall (either way), the plate straight along heading + bearing.
    heading = std::atan2(along.y, along.x) + (unit(rng) < 0.5 ? 0.0 : M_PI) +
              options_.parallel_heading_stddev_rad * gauss(rng);
    const Vec2 to_plate{std::cos(heading + reading.bearing_rad), std::sin(heading + reading.bearing_rad)};
    const double facing = -Dot(to_plate, normal);  // cosine of the view angle off the plate's normal
    if (facing < std::cos(options_.max_view_angle_rad)) return false;
    const double r = reading.range_m ? *reading.range_m + options_.range_stddev_m * gauss(rng)
                                     : (lo + (hi - lo) * unit(rng)) / facing;
    offset = -r * to_plate;
  } else {
    if (reading.range_m) {
      const double r = *reading.range_m + options_.range_stddev_m * gauss(rng);
      const double phi = options_.max_view_angle_rad * (2.0 * unit(rng) - 1.0);
      offset = r * std::cos(phi) * normal + r * std::sin(phi) * along;
    } else {
      offset = (lo + (hi - lo) * unit(rng)) * normal + options_.lateral_stddev_m * gauss(rng) * along;
    }
    heading = std::atan2(-offset.y, -offset.x) - reading.bearing_rad + options_.heading_stddev_rad * gauss(rng);
  }
  const double distance = Norm(offset);
  if (distance < options_.min_view_distance_m) return false;
  if (Dot(offset, normal) < distance * std::cos(options_.max_view_angle_rad)) return false;
  const Vec2 position = plate.pose.Position() + offset;
  if (grid_ && (!grid_->IsFree(position) ||
                !HasLineOfSight(*grid_, position, plate.pose.Position(), options_.line_of_sight_tolerance_m))) {
    return false;
  }
  *pose = {position.x, position.y, NormalizeAngle(heading)};
  return true;
}

std::vector<Pose2D> PlatePoseSampler::Sample(const PlateReading& reading, int count, std::mt19937_64& rng) const {
  const std::string error = ValidatePlateReading(reading);
  if (!error.empty()) throw std::invalid_argument(error);
  const std::vector<LandmarkMatch> matches = matcher_.Compatible(*text_map_, reading.text, reading.confidence);
  std::vector<Pose2D> poses;
  if (matches.empty() || count <= 0) return poses;
  std::vector<double> weights;
  for (const LandmarkMatch& m : matches) weights.push_back(m.probability);
  std::discrete_distribution<size_t> pick(weights.begin(), weights.end());
  poses.reserve(count);
  for (int k = 0; k < count; ++k) {
    for (int attempt = 0; attempt < options_.max_attempts_per_pose; ++attempt) {
      Pose2D pose;
      if (SampleAt(text_map_->landmarks[matches[pick(rng)].landmark_index], reading, rng, &pose)) {
        poses.push_back(pose);
        break;
      }
    }
  }
  return poses;
}

}  // namespace doorplate_localization

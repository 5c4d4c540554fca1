#include "localize_start_poses.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

double RayToSurfaces(const World& world, Vec2 origin, Vec2 direction) {
  const double height = world.sensors.laser.mount_height_m;
  double best = std::numeric_limits<double>::infinity();
  for (const Surface& s : world.surfaces) {
    if (s.z_min_m > height || height > s.z_max_m) continue;
    if (const auto t = RaySegmentDistance(origin, direction, s.segment); t && *t < best) best = *t;
  }
  if (!std::isfinite(best)) {
    throw std::runtime_error("world " + world.name + ": no wall found from start_pose along (" +
                             std::to_string(direction.x) + ", " + std::to_string(direction.y) +
                             "): the main corridor must be closed");
  }
  return best;
}

void CheckOptions(const StartPoseSamplerOptions& options) {
  auto check = [](bool ok, const char* field) {
    if (!ok) throw std::invalid_argument(std::string("StartPoseSamplerOptions.") + field + ": out of range");
  };
  check(options.end_margin_m >= 0.0, "end_margin_m");
  check(options.wall_margin_m >= 0.0, "wall_margin_m");
  check(options.heading_noise_rad >= 0.0 && options.heading_noise_rad <= M_PI, "heading_noise_rad");
  check(options.clearance_m >= 0.0, "clearance_m");
  check(options.min_kidnap_distance_m >= 0.0, "min_kidnap_distance_m");
  check(options.max_attempts >= 1, "max_attempts");
}

}  // namespace

CorridorBand FindCorridorBand(const World& world) {
  const Vec2 o = world.start_pose.Position();
  CorridorBand band;
  band.x_max_m = o.x + RayToSurfaces(world, o, {1.0, 0.0});
  band.x_min_m = o.x - RayToSurfaces(world, o, {-1.0, 0.0});
  band.y_max_m = o.y + RayToSurfaces(world, o, {0.0, 1.0});
  band.y_min_m = o.y - RayToSurfaces(world, o, {0.0, -1.0});
  return band;
}

StartPoseSampler::StartPoseSampler(const CorridorBand& band, const OccupancyGrid& grid,
                                   const StartPoseSamplerOptions& options)
    : band_(band), grid_(grid), options_(options) {
  CheckOptions(options);
  if (band.x_max_m - band.x_min_m <= 2.0 * options.end_margin_m ||
      band.y_max_m - band.y_min_m <= 2.0 * options.wall_margin_m) {
    throw std::invalid_argument("StartPoseSampler: the corridor band is narrower than its margins");
  }
}

StartPoseSampler::StartPoseSampler(const std::vector<CorridorSpec>& corridors, const OccupancyGrid& grid,
                                   const StartPoseSamplerOptions& options)
    : band_(), grid_(grid), options_(options), corridors_(corridors) {
  CheckOptions(options);
  if (corridors.empty()) throw std::invalid_argument("StartPoseSampler: corridors: empty (no floor to draw from)");
  double total = 0.0;
  for (const CorridorSpec& c : corridors) {
    if (c.centreline.Length() <= 2.0 * options.end_margin_m || c.width_m <= 2.0 * options.wall_margin_m) {
      throw std::invalid_argument("StartPoseSampler: corridors['" + c.id + "']: shorter or narrower than its margins");
    }
    total += c.centreline.Length();
    cumulative_length_m_.push_back(total);
  }
}

bool StartPoseSampler::HasClearance(Vec2 p) const {
  const double r = options_.clearance_m;
  const int reach = static_cast<int>(std::ceil(r / grid_.resolution_m));
  int cx = 0, cy = 0;
  if (!grid_.WorldToCell(p, &cx, &cy)) return false;
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      if (std::hypot(dx, dy) * grid_.resolution_m > r) continue;
      if (!grid_.InBounds(cx + dx, cy + dy)) return false;
      const int value = grid_.At(cx + dx, cy + dy);
      if (value < 0 || value >= 50) return false;
    }
  }
  return true;
}

Pose2D StartPoseSampler::Sample(std::mt19937_64& rng) const {
  return on_floor() ? SampleOnFloor(rng) : SampleInBand(rng);
}

Pose2D StartPoseSampler::SampleInBand(std::mt19937_64& rng) const {
  std::uniform_real_distribution<double> x(band_.x_min_m + options_.end_margin_m, band_.x_max_m - options_.end_margin_m);
  std::uniform_real_distribution<double> y(band_.y_min_m + options_.wall_margin_m,
                                           band_.y_max_m - options_.wall_margin_m);
  std::uniform_real_distribution<double> noise(-options_.heading_noise_rad, options_.heading_noise_rad);
  std::bernoulli_distribution backwards(0.5);
  for (int attempt = 0; attempt < options_.max_attempts; ++attempt) {
    // The same four draws on every attempt, in a fixed order (reproducible for a seed).
    Pose2D pose{x(rng), y(rng), 0.0};
    const bool reverse = backwards(rng);
    pose.theta_rad = NormalizeAngle((reverse ? M_PI : 0.0) + noise(rng));
    if (HasClearance(pose.Position())) return pose;
  }
  throw std::runtime_error("StartPoseSampler: no free pose with clearance found in the corridor band");
}

Pose2D StartPoseSampler::SampleOnFloor(std::mt19937_64& rng) const {
  std::uniform_real_distribution<double> where(0.0, cumulative_length_m_.back());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> noise(-options_.heading_noise_rad, options_.heading_noise_rad);
  std::bernoulli_distribution backwards(0.5);
  for (int attempt = 0; attempt < options_.max_attempts; ++attempt) {
    // The same five draws on every attempt, in a fixed order (reproducible for a seed).
    const double w = where(rng);
    const size_t i = std::min<size_t>(
        std::upper_bound(cumulative_length_m_.begin(), cumulative_length_m_.end(), w) - cumulative_length_m_.begin(),
        corridors_.size() - 1);
    const CorridorSpec& c = corridors_[i];
    const double length = c.centreline.Length();
    const Vec2 along = (1.0 / length) * (c.centreline.b - c.centreline.a);
    const Vec2 left{-along.y, along.x};
    const double s = options_.end_margin_m + unit(rng) * (length - 2.0 * options_.end_margin_m);
    const double half_free = 0.5 * c.width_m - options_.wall_margin_m;
    const double u = (2.0 * unit(rng) - 1.0) * half_free;
    const Vec2 p = c.centreline.a + s * along + u * left;
    const bool reverse = backwards(rng);
    const double heading = std::atan2(along.y, along.x) + (reverse ? M_PI : 0.0) + noise(rng);
    if (HasClearance(p)) return {p.x, p.y, NormalizeAngle(heading)};
  }
  throw std::runtime_error("StartPoseSampler: no free pose with clearance found in the floor's corridors");
}

Pose2D StartPoseSampler::SampleAwayFrom(const Pose2D& current, std::mt19937_64& rng) const {
  for (int attempt = 0; attempt < options_.max_attempts; ++attempt) {
    const Pose2D pose = Sample(rng);
    if (std::hypot(pose.x_m - current.x_m, pose.y_m - current.y_m) >= options_.min_kidnap_distance_m) return pose;
  }
  throw std::runtime_error("StartPoseSampler: no pose found at least min_kidnap_distance_m from the robot");
}

StartPoseSampler MakeStartPoseSampler(const World& world, const OccupancyGrid& grid,
                                      const StartPoseSamplerOptions& options) {
  if (!world.corridors.empty()) return StartPoseSampler(world.corridors, grid, options);
  return StartPoseSampler(FindCorridorBand(world), grid, options);
}

}  // namespace doorplate_localization

#include "doorplate_localization/laser_fit/reference_map.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

#include "doorplate_localization/mcl/grid_ray_caster.h"

namespace doorplate_localization {
namespace {

TiledGridOptions GridOptions(const ReferenceMapOptions& o) {
  if (!(o.resolution_m > 0.0 && o.resolution_m <= 0.5)) {
    throw std::invalid_argument("ReferenceMapOptions.resolution_m: must be in (0, 0.5], got " +
                                std::to_string(o.resolution_m));
  }
  if (!(o.max_range_m > 0.0)) throw std::invalid_argument("ReferenceMapOptions.max_range_m: must be > 0");
  if (!(o.surface_radius_m >= o.resolution_m)) {
    throw std::invalid_argument("ReferenceMapOptions.surface_radius_m: must be >= resolution_m");
  }
  if (o.min_surface_points < 3) throw std::invalid_argument("ReferenceMapOptions.min_surface_points: must be >= 3");
  if (!(o.max_surface_rms_m > 0.0)) throw std::invalid_argument("ReferenceMapOptions.max_surface_rms_m: must be > 0");
  if (!(o.max_refine_shift_m > 0.0)) throw std::invalid_argument("ReferenceMapOptions.max_refine_shift_m: must be > 0");
  TiledGridOptions g;
  g.resolution_m = o.resolution_m;
  g.distance_field_radius_m = o.resolution_m;  // the distance field is not used here: keep it cheap
  return g;
}

}  // namespace

ReferenceMap::ReferenceMap(const ReferenceMapOptions& options) : options_(options), tiled_(GridOptions(options)) {}

void ReferenceMap::AddScan(const Pose2D& laser_in_map, const LaserScan& scan) {
  if (cells_) throw std::logic_error("ReferenceMap::AddScan after Finish");
  const Vec2 from = laser_in_map.Position();
  for (size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double r = scan.ranges_m[i];
    if (!std::isfinite(r) || r < scan.min_range_m || r > options_.max_range_m) continue;
    const double a = laser_in_map.theta_rad + scan.BeamAngle(static_cast<int>(i));
    const Vec2 to = from + r * Vec2{std::cos(a), std::sin(a)};
    tiled_.IntegrateBeam(from, to, true);
    end_points_[Key(tiled_.CellOf(to))].push_back(to);
  }
}

void ReferenceMap::Finish() {
  if (cells_) return;
  const double occupied = tiled_.options().occupied_log_odds;
  for (auto it = end_points_.begin(); it != end_points_.end();) {
    const CellIndex c{static_cast<int>(it->first >> 32), static_cast<int>(static_cast<std::uint32_t>(it->first))};
    it = tiled_.LogOdds(c) > occupied ? std::next(it) : end_points_.erase(it);
  }
  grid_ = tiled_.ToOccupancyGrid(occupied);
  cells_ = std::make_unique<LocalizationGrid>(grid_);
}

bool ReferenceMap::FitSurface(Vec2 p, Vec2* centroid, Vec2* normal) const {
  const CellIndex c = tiled_.CellOf(p);
  const int k = static_cast<int>(std::ceil(options_.surface_radius_m / options_.resolution_m));
  const double r2 = options_.surface_radius_m * options_.surface_radius_m;
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  for (int dy = -k; dy <= k; ++dy) {
    for (int dx = -k; dx <= k; ++dx) {
      const auto it = end_points_.find(Key({c.x + dx, c.y + dy}));
      if (it == end_points_.end()) continue;
      for (const Vec2& q : it->second) {
        const Vec2 d = q - p;  // relative to p: keeps the sums well conditioned
        if (Dot(d, d) > r2) continue;
        n += 1, sx += d.x, sy += d.y, sxx += d.x * d.x, sxy += d.x * d.y, syy += d.y * d.y;
      }
    }
  }
  if (n < options_.min_surface_points) return false;
  const double mx = sx / n, my = sy / n;
  const double cxx = sxx / n - mx * mx, cxy = sxy / n - mx * my, cyy = syy / n - my * my;
  const double half_diff = 0.5 * (cxx - cyy);
  const double smallest = 0.5 * (cxx + cyy) - std::sqrt(half_diff * half_diff + cxy * cxy);
  if (std::sqrt(std::max(0.0, smallest)) > options_.max_surface_rms_m) return false;
  const double along = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);
  *centroid = p + Vec2{mx, my};
  *normal = {-std::sin(along), std::cos(along)};
  return true;
}

ExpectedBeam ReferenceMap::Expect(Vec2 origin, double angle_rad, double max_range_m) const {
  if (!cells_) throw std::logic_error("ReferenceMap::Expect before Finish");
  ExpectedBeam out;
  int x = 0, y = 0;
  if (!cells_->PointToCell(origin, &x, &y) || cells_->State(x, y) != CellState::kFree) return out;
  const double r = CastRay(*cells_, origin, angle_rad, max_range_m, true);
  if (r >= max_range_m) {
    out.kind = ExpectedKind::kNothing;
    out.range_m = max_range_m;
    return out;
  }
  const Vec2 dir{std::cos(angle_rad), std::sin(angle_rad)};
  // The cell that stopped the ray starts at r; a step into it tells whether it is an obstacle.
  if (!cells_->PointToCell(origin + (r + 1e-4 * options_.resolution_m) * dir, &x, &y) ||
      cells_->State(x, y) != CellState::kOccupied) {
    return out;
  }
  out.kind = ExpectedKind::kHit;
  out.range_m = r;
  Vec2 centroid, normal;
  if (!FitSurface(origin + r * dir, &centroid, &normal)) return out;
  const double cos_incidence = Dot(dir, normal);
  if (std::fabs(cos_incidence) < 1e-3) return out;  // the beam runs along the fitted line
  const double t = Dot(centroid - origin, normal) / cos_incidence;
  if (!(std::fabs(t - r) <= options_.max_refine_shift_m)) return out;
  out.range_m = t;
  out.incidence_rad = std::acos(std::min(1.0, std::fabs(cos_incidence)));
  out.surface_fit = true;
  return out;
}

}  // namespace doorplate_localization

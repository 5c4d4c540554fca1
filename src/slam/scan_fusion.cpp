#include "doorplate_localization/slam/scan_fusion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "doorplate_localization/slam/minor_axis.h"

namespace doorplate_localization {

const ScanFusionOptions& ValidatedScanFusionOptions(const ScanFusionOptions& o) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("ScanFusionOptions." + what); };
  if (!(o.scans_before >= 0)) fail("scans_before: must be >= 0");
  if (!(o.scans_after >= 0)) fail("scans_after: must be >= 0");
  if (!(o.max_distance_m >= 0)) fail("max_distance_m: must be >= 0");
  if (!(o.max_rotation_rad >= 0)) fail("max_rotation_rad: must be >= 0");
  if (!(o.radius_m > 0)) fail("radius_m: must be > 0");
  if (!(o.radius_per_m >= 0)) fail("radius_per_m: must be >= 0");
  if (!(o.min_neighbours >= 3)) fail("min_neighbours: must be >= 3 (a line needs them)");
  if (!(o.max_residual_m >= 0)) fail("max_residual_m: must be >= 0");
  if (!(o.max_residual_per_m >= 0)) fail("max_residual_per_m: must be >= 0");
  return o;
}

ScanFusion::ScanFusion(const ScanFusionOptions& options) : options_(ValidatedScanFusionOptions(options)) {}

long ScanFusion::Add(std::vector<Vec2> points, const Pose2D& odometry_pose) {
  scans_.push_back({std::move(points), odometry_pose});
  const int keep = options_.scans_before + options_.scans_after + 1;
  while (static_cast<int>(scans_.size()) > keep) scans_.pop_front();
  return next_id_++;
}

const ScanFusion::Scan& ScanFusion::At(long id) const {
  const long first = next_id_ - static_cast<long>(scans_.size());
  if (!Remembered(id)) {
    throw std::out_of_range("ScanFusion: scan " + std::to_string(id) + " is not remembered (scans " +
                            std::to_string(first) + " to " + std::to_string(next_id_ - 1) + " are)");
  }
  return scans_[id - first];
}

bool ScanFusion::Usable(const Scan& center, const Scan& other) const {
  const Pose2D rel = center.odometry.Between(other.odometry);
  return std::hypot(rel.x_m, rel.y_m) <= options_.max_distance_m &&
         std::abs(NormalizeAngle(rel.theta_rad)) <= options_.max_rotation_rad;
}

int ScanFusion::UsableScansBefore(long id) const {
  const Scan& center = At(id);
  int usable = 0;
  for (long k = std::max(id - options_.scans_before, next_id_ - static_cast<long>(scans_.size())); k < id; ++k) {
    usable += Usable(center, At(k)) ? 1 : 0;
  }
  return usable;
}

int ScanFusion::UsableScansAfter(long id) const {
  const Scan& center = At(id);
  int usable = 0;
  for (long k = id + 1; k < next_id_ && k <= id + options_.scans_after; ++k) usable += Usable(center, At(k)) ? 1 : 0;
  return usable;
}

bool ScanFusion::Complete(long id) const {
  if (!Remembered(id)) return true;
  return next_id_ - 1 - id >= options_.scans_after || (id < next_id_ - 1 && !Usable(At(id), scans_.back()));
}

std::vector<Vec2> ScanFusion::Fuse(long id) const {
  const Scan& center = At(id);
  const std::vector<Vec2>& own = center.points;
  const long first = std::max(id - options_.scans_before, next_id_ - static_cast<long>(scans_.size()));
  const long last = std::min(id + options_.scans_after, next_id_ - 1);
  // Every usable echo in scan id's frame (its own first), in a hash grid of cells as wide as the smallest radius.
  std::vector<Vec2> all = own;
  for (long k = first; k <= last; ++k) {
    if (k == id || !Usable(center, At(k))) continue;
    const Pose2D rel = center.odometry.Between(At(k).odometry);
    for (const Vec2& p : At(k).points) all.push_back(rel.TransformPoint(p));
  }
  if (all.size() == own.size()) return own;
  const double cell = options_.radius_m;
  const auto cell_of = [cell](double v) { return static_cast<int>(std::floor(v / cell)); };
  const auto key = [](int cx, int cy) { return static_cast<long long>(cx) * (1LL << 32) + static_cast<unsigned>(cy); };
  std::unordered_map<long long, std::vector<int>> cells;
  for (int i = 0; i < static_cast<int>(all.size()); ++i) cells[key(cell_of(all[i].x), cell_of(all[i].y))].push_back(i);

  std::vector<Vec2> fused = own;
  for (Vec2& q : fused) {
    const double range = Norm(q);
    const double radius = std::max(options_.radius_m, options_.radius_per_m * range);
    const int reach = static_cast<int>(std::ceil(radius / cell));
    const int cx = cell_of(q.x), cy = cell_of(q.y);
    // Mean and scatter of the neighbourhood.
    int n = 0;
    double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
    for (int dx = -reach; dx <= reach; ++dx) {
      for (int dy = -reach; dy <= reach; ++dy) {
        const auto it = cells.find(key(cx + dx, cy + dy));
        if (it == cells.end()) continue;
        for (int i : it->second) {
          const Vec2 d = all[i] - q;
          if (Dot(d, d) > radius * radius) continue;
          ++n, sx += d.x, sy += d.y, sxx += d.x * d.x, sxy += d.x * d.y, syy += d.y * d.y;
        }
      }
    }
    if (n < options_.min_neighbours) continue;
    const double mx = sx / n, my = sy / n;
    const double cxx = sxx / n - mx * mx, cxy = sxy / n - mx * my, cyy = syy / n - my * my;
    const MinorAxis across = MinorAxisOf(cxx, cxy, cyy);  // variance across the line, and its normal
    const double limit = options_.max_residual_m + options_.max_residual_per_m * range;
    if (!(across.eigenvalue <= limit * limit)) continue;
    const Vec2 normal = across.axis;
    // q is at the origin of the offsets d: move it by its offset from the line through the mean.
    const double off = -Dot(Vec2{mx, my}, normal);  // signed distance of q from the line
    q = q - off * normal;
  }
  return fused;
}

}  // namespace doorplate_localization

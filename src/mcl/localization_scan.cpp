#include "doorplate_localization/mcl/localization_scan.h"

#include <cmath>
#include <stdexcept>

#include "doorplate_localization/common/limits.h"

namespace doorplate_localization {

std::string ValidateLocalizationScan(const LaserScan& scan) {
  const auto finite = [](double v) { return std::isfinite(v); };
  if (scan.ranges_m.empty()) return "LaserScan.ranges_m: empty";
  if (scan.ranges_m.size() > limits::kMaxScanBeams) {
    return "LaserScan.ranges_m: " + std::to_string(scan.ranges_m.size()) + " beams, more than the limit of " +
           std::to_string(limits::kMaxScanBeams) + " (limits::kMaxScanBeams)";
  }
  if (!finite(scan.angle_min_rad)) return "LaserScan.angle_min_rad: must be finite";
  if (!finite(scan.angle_increment_rad) || scan.angle_increment_rad == 0.0) {
    return "LaserScan.angle_increment_rad: must be finite and non-zero, got " +
           std::to_string(scan.angle_increment_rad);
  }
  if (!finite(scan.min_range_m) || scan.min_range_m < 0.0) {
    return "LaserScan.min_range_m: must be finite and >= 0, got " + std::to_string(scan.min_range_m);
  }
  if (!finite(scan.max_range_m) || scan.max_range_m <= scan.min_range_m) {
    return "LaserScan.max_range_m: must be finite and > min_range_m, got " + std::to_string(scan.max_range_m);
  }
  const Pose2D& m = scan.laser_pose;
  if (!finite(m.x_m) || !finite(m.y_m) || !finite(m.theta_rad)) return "LaserScan.laser_pose: must be finite";
  return "";
}

BeamKind ClassifyRange(float range_m, double min_range_m, double max_range_m) {
  if (std::isnan(range_m)) return BeamKind::kInvalid;
  if (range_m >= max_range_m) return BeamKind::kMaxRange;  // includes +inf
  if (range_m < min_range_m) return BeamKind::kInvalid;    // includes -inf (REP-117: too close)
  return BeamKind::kHit;
}

double EffectiveMinRange(const LaserScan& scan, const BeamSelectionOptions& options) {
  return options.laser_min_range_m > 0.0 ? std::max(options.laser_min_range_m, scan.min_range_m)
                                         : scan.min_range_m;
}

double EffectiveMaxRange(const LaserScan& scan, const BeamSelectionOptions& options) {
  return options.laser_max_range_m > 0.0 ? std::min(options.laser_max_range_m, scan.max_range_m)
                                         : scan.max_range_m;
}

std::vector<SelectedBeam> SelectBeams(const LaserScan& scan, const BeamSelectionOptions& options) {
  const std::string error = ValidateLocalizationScan(scan);
  if (!error.empty()) throw std::invalid_argument(error);
  if (options.laser_max_beams < 1) {
    throw std::invalid_argument("laser_max_beams: must be >= 1, got " + std::to_string(options.laser_max_beams));
  }
  const double min_range = EffectiveMinRange(scan, options);
  const double max_range = EffectiveMaxRange(scan, options);
  if (!(max_range > min_range)) {
    throw std::invalid_argument("laser_max_range_m: effective max range " + std::to_string(max_range) +
                                " must exceed the min range " + std::to_string(min_range));
  }
  const int n = static_cast<int>(scan.ranges_m.size());
  const int m = std::min(n, options.laser_max_beams);
  std::vector<SelectedBeam> beams;
  beams.reserve(m);
  for (int i = 0; i < m; ++i) {
    const int index = m == 1 ? 0 : static_cast<int>(std::lround(static_cast<double>(i) * (n - 1) / (m - 1)));
    const float r = scan.ranges_m[index];
    const BeamKind kind = ClassifyRange(r, min_range, max_range);
    if (kind == BeamKind::kInvalid) continue;
    beams.push_back({scan.angle_min_rad + index * scan.angle_increment_rad,
                     kind == BeamKind::kMaxRange ? max_range : static_cast<double>(r), kind});
  }
  return beams;
}

}  // namespace doorplate_localization

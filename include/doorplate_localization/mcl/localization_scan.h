// A 2D laser scan as the localizer consumes it, and the choice of the beams the laser models use.
// (Named apart from slam/range_scan.h's RangeScan, which has no max range: both live in one namespace.)
// Frames: ranges and angles are in the laser frame (x forward, angles counter-clockwise, REP-103);
// `laser_pose` places the laser frame in base_link. Units: metres, radians.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/mcl/plate_reading.h"
#include "doorplate_localization/sensors/plate_range.h"

namespace doorplate_localization {

struct LocalizationScan {
  double angle_min_rad = 0.0;        // angle of ranges_m[0]
  double angle_increment_rad = 0.0;  // between consecutive beams (may be negative)
  double min_range_m = 0.0;          // the device's valid interval (sensor_msgs/LaserScan range_min/max)
  double max_range_m = 0.0;
  std::vector<float> ranges_m;       // REP-117: +inf = no echo within max range, -inf = too close, NaN = error
  Pose2D laser_pose;                 // laser frame in base_link (the mounting pose)
};

// The scan's beams as the shared sensor rules read them (sensors/plate_range.h).
inline BeamGeometry BeamGeometryOf(const LocalizationScan& scan) {
  BeamGeometry g;
  g.angle_min_rad = scan.angle_min_rad;
  g.angle_increment_rad = scan.angle_increment_rad;
  g.min_range_m = scan.min_range_m;
  g.max_range_m = scan.max_range_m;
  g.laser_pose = scan.laser_pose;
  return g;
}

// Returns "" if the scan's geometry is usable, else what is wrong ("LocalizationScan.ranges_m: empty", more
// than limits::kMaxScanBeams ranges, ...).
// Individual non-finite or out-of-range ranges do not make a scan unusable; models skip them.
std::string ValidateLocalizationScan(const LocalizationScan& scan);

// How a laser model treats one range reading.
enum class BeamKind {
  kHit,       // finite, within [min, max): an echo
  kMaxRange,  // +inf or >= max range: no echo (REP-117); the beam model's z_max part, the field model skips it
  kInvalid,   // NaN, -inf, or below min range: skipped by every model
};

// Classifies `range_m` against the range interval [min_range_m, max_range_m].
BeamKind ClassifyRange(float range_m, double min_range_m, double max_range_m);

// One beam chosen for a laser model.
struct SelectedBeam {
  double angle_rad = 0.0;  // in the laser frame
  double range_m = 0.0;    // the reading; max_range_m for kMaxRange beams
  BeamKind kind = BeamKind::kHit;
};

// Range limits a model applies on top of the scan's own (amcl's laser_min_range / laser_max_range:
// a value <= 0 means "use the scan's").
struct BeamSelectionOptions {
  int laser_max_beams = 60;         // beams used per scan, evenly spread over the scan (all if fewer)
  double laser_min_range_m = -1.0;
  double laser_max_range_m = -1.0;
};

// The effective range interval of `scan` under `options`.
double EffectiveMinRange(const LocalizationScan& scan, const BeamSelectionOptions& options);
double EffectiveMaxRange(const LocalizationScan& scan, const BeamSelectionOptions& options);

// Picks min(laser_max_beams, N) beam indexes evenly spread over the N readings (first and last
// included: index round(i (N-1) / (M-1))), classifies them and drops kInvalid ones. Throws
// std::invalid_argument naming the field when the scan or the options are unusable.
std::vector<SelectedBeam> SelectBeams(const LocalizationScan& scan, const BeamSelectionOptions& options);

// A plate reading of `text` with `confidence`, seen at `bearing_rad` in base_link (wrapped to (-pi, pi];
// a non-finite bearing is kept as given, for ValidatePlateReading to name), with `range_m` (metres,
// base_link -> plate; nullopt = unknown) and camera side unknown. Callers validate it.
PlateReading PlateReadingAt(const std::string& text, double confidence, double bearing_rad,
                            std::optional<double> range_m);

}  // namespace doorplate_localization

// What the localizer asks of a laser scan (sensors/laser_scan.h), and the choice of the beams its laser
// models use. Frames: ranges and angles are in the laser frame (x forward, angles counter-clockwise,
// REP-103); `laser_pose` places the laser frame in base_link. Units: metres, radians.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/sensors/plate_reading.h"
#include "doorplate_localization/sensors/laser_scan.h"

namespace doorplate_localization {

// Returns "" if the scan's geometry is usable by the localizer (a finite max_range_m above min_range_m
// among others), else what is wrong ("LaserScan.ranges_m: empty", more
// than limits::kMaxScanBeams ranges, ...).
// Individual non-finite or out-of-range ranges do not make a scan unusable; models skip them.
std::string ValidateLocalizationScan(const LaserScan& scan);

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
double EffectiveMinRange(const LaserScan& scan, const BeamSelectionOptions& options);
double EffectiveMaxRange(const LaserScan& scan, const BeamSelectionOptions& options);

// Picks min(laser_max_beams, N) beam indexes evenly spread over the N readings (first and last
// included: index round(i (N-1) / (M-1))), classifies them and drops kInvalid ones. Throws
// std::invalid_argument naming the field when the scan or the options are unusable.
std::vector<SelectedBeam> SelectBeams(const LaserScan& scan, const BeamSelectionOptions& options);

}  // namespace doorplate_localization

// Spurious returns of a real 2D laser: beams that come back from nothing the robot must avoid (dust, a
// reflection, a mixed pixel between two surfaces; docs/results/laser-model.md measures ~2 % of the beams of
// real indoor logs as spurious short readings, scattered one or two beams at a time). A wall, a door frame or
// a leg returns on several neighbouring beams at nearly the same range; a spurious return stands alone. The
// driving behaviours ignore isolated returns, so that one such beam in front of the robot does not end a
// corridor sweep, stop the robot or swerve it. Beam index order is angle order.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace doorplate_localization {

struct IsolatedReturnOptions {
  int min_support = 2;               // a return needs this many supporting beams; 0: keep every return
  int window_beams = 3;              // supporting beams are within this many beams on either side
  double range_tolerance_m = 0.15;   // ... and return within max(this, range_tolerance_fraction × its range)
  double range_tolerance_fraction = 0.1;  //     of its range
};

// Throws std::invalid_argument naming `prefix` + the field of an invalid option.
inline void CheckIsolatedReturnOptions(const IsolatedReturnOptions& o, const std::string& prefix) {
  if (o.min_support < 0) throw std::invalid_argument(prefix + "min_support: must be >= 0");
  if (o.window_beams < 1) throw std::invalid_argument(prefix + "window_beams: must be >= 1");
  if (!(o.range_tolerance_m > 0.0) || !std::isfinite(o.range_tolerance_m)) {
    throw std::invalid_argument(prefix + "range_tolerance_m: must be finite and > 0");
  }
  if (!(o.range_tolerance_fraction >= 0.0) || !std::isfinite(o.range_tolerance_fraction)) {
    throw std::invalid_argument(prefix + "range_tolerance_fraction: must be finite and >= 0");
  }
}

// True when ranges_m[i] is a finite return with fewer than `min_support` finite returns within the range
// tolerance of it among the `window_beams` beams on either side (beams beyond the scan's ends do not count).
// A wall near the robot always has such neighbours; one seen far away at a very grazing angle may not (its
// beams differ by more than the tolerance), which the behaviours, looking a few metres ahead, do not use.
inline bool IsIsolatedReturn(const std::vector<float>& ranges_m, std::size_t i, const IsolatedReturnOptions& o) {
  if (o.min_support <= 0 || i >= ranges_m.size()) return false;
  const double r = ranges_m[i];
  if (!std::isfinite(r) || r <= 0.0) return false;
  const std::size_t first = i >= static_cast<std::size_t>(o.window_beams) ? i - o.window_beams : 0;
  const std::size_t last = std::min(ranges_m.size() - 1, i + static_cast<std::size_t>(o.window_beams));
  const double tolerance_m = std::max(o.range_tolerance_m, o.range_tolerance_fraction * r);
  int support = 0;
  for (std::size_t j = first; j <= last; ++j) {
    if (j == i || !std::isfinite(ranges_m[j]) || ranges_m[j] <= 0.0) continue;
    if (std::fabs(ranges_m[j] - r) <= tolerance_m && ++support >= o.min_support) return false;
  }
  return true;
}

}  // namespace doorplate_localization

// The pose histogram shared by KLD-sampling and clustering: bins of bin_size_xy_m × bin_size_xy_m ×
// bin_size_theta_rad (amcl: 0.5 m × 0.5 m × 10°), heading bins wrapping around at ±pi.
#pragma once

#include <cstdint>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct PoseBinSize {
  double xy_m = 0.5;
  double theta_rad = 10.0 * M_PI / 180.0;
};

// Integer bin coordinates of a pose. theta is in [0, ThetaBinCount()) (heading wrapped to [-pi, pi)).
struct PoseBin {
  int x = 0;
  int y = 0;
  int theta = 0;
};

// Number of heading bins around the circle: ceil(2 pi / theta_rad).
int ThetaBinCount(const PoseBinSize& size);
PoseBin BinOf(const Pose2D& pose, const PoseBinSize& size);
// A unique 64-bit key per bin (x and y within ±2^25 bins).
std::uint64_t BinKey(const PoseBin& bin);

}  // namespace doorplate_localization

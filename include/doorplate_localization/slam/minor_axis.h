// The smaller eigenvalue of a symmetric 2×2 matrix [[xx, xy], [xy, yy]] (a scatter or an information
// matrix) and its unit eigenvector, in closed form: the weakest direction of a scan's information
// (rbpf_slam.cpp) and the normal of a line fitted to a point neighbourhood (scan_fusion.cpp).
#pragma once

#include <cmath>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct MinorAxis {
  double eigenvalue = 0.0;  // the smaller one
  Vec2 axis;                // its unit eigenvector (sign arbitrary)
};

inline MinorAxis MinorAxisOf(double xx, double xy, double yy) {
  const double mean = 0.5 * (xx + yy), half_diff = 0.5 * (xx - yy);
  const double angle = 0.5 * std::atan2(2.0 * xy, xx - yy) + 1.5707963267948966;  // the major axis's + 90°
  return {mean - std::sqrt(half_diff * half_diff + xy * xy), {std::cos(angle), std::sin(angle)}};
}

}  // namespace doorplate_localization

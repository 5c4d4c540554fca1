#include "doorplate_localization/mcl/pose_histogram.h"

#include <cmath>

namespace doorplate_localization {

int ThetaBinCount(const PoseBinSize& size) {
  return std::max(1, static_cast<int>(std::ceil(2.0 * M_PI / size.theta_rad - 1e-9)));
}

PoseBin BinOf(const Pose2D& pose, const PoseBinSize& size) {
  const int n = ThetaBinCount(size);
  // Heading in [0, 2 pi) from -pi, so the wrap at ±pi falls on a bin edge.
  const double a = NormalizeAngle(pose.theta_rad) + M_PI;
  int theta = static_cast<int>(std::floor(a / size.theta_rad));
  theta = ((theta % n) + n) % n;
  return {static_cast<int>(std::floor(pose.x_m / size.xy_m)), static_cast<int>(std::floor(pose.y_m / size.xy_m)),
          theta};
}

std::uint64_t BinKey(const PoseBin& bin) {
  constexpr std::int64_t kOffset = std::int64_t{1} << 25;
  const auto field = [&](int v) { return static_cast<std::uint64_t>((v + kOffset) & ((std::int64_t{1} << 26) - 1)); };
  return (field(bin.x) << 38) | (field(bin.y) << 12) | static_cast<std::uint64_t>(bin.theta & 0xfff);
}

}  // namespace doorplate_localization

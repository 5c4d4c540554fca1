#include "plate_alignment.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "doorplate_localization/common/room_id.h"

namespace doorplate_localization {
namespace {

// Index pairs (mapped, true) of plates whose room is named exactly once in each map.
std::vector<std::pair<int, int>> UniqueTextPairs(const TextMap& mapped, const TextMap& truth) {
  const auto count = [](const TextMap& map, const std::string& text) {
    return std::count_if(map.landmarks.begin(), map.landmarks.end(),
                         [&](const TextLandmark& l) { return SameRoom(l.text, text); });
  };
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t i = 0; i < mapped.landmarks.size(); ++i) {
    const std::string& text = mapped.landmarks[i].text;
    if (count(mapped, text) != 1 || count(truth, text) != 1) continue;
    for (std::size_t j = 0; j < truth.landmarks.size(); ++j) {
      if (SameRoom(truth.landmarks[j].text, text)) pairs.emplace_back(static_cast<int>(i), static_cast<int>(j));
    }
  }
  return pairs;
}

}  // namespace

PlateAlignment AlignPlates(const TextMap& mapped, const TextMap& truth) {
  PlateAlignment result;
  result.residuals_m.assign(mapped.landmarks.size(), -1.0);
  const std::vector<std::pair<int, int>> pairs = UniqueTextPairs(mapped, truth);
  result.pairs = static_cast<int>(pairs.size());
  if (pairs.empty()) return result;
  Vec2 mean_map, mean_true;
  const double w = 1.0 / static_cast<double>(pairs.size());
  for (const auto& [i, j] : pairs) {
    mean_map = mean_map + w * mapped.landmarks[i].pose.Position();
    mean_true = mean_true + w * truth.landmarks[j].pose.Position();
  }
  double sum_cross = 0.0, sum_dot = 0.0, spread = 0.0;
  for (const auto& [i, j] : pairs) {
    const Vec2 m = mapped.landmarks[i].pose.Position() - mean_map;
    const Vec2 t = truth.landmarks[j].pose.Position() - mean_true;
    sum_cross += Cross(m, t);
    sum_dot += Dot(m, t);
    spread += Dot(m, m);
  }
  result.ok = pairs.size() >= 2 && spread > 1e-12;
  const double theta = result.ok ? std::atan2(sum_cross, sum_dot) : 0.0;
  const Pose2D rotation{0.0, 0.0, theta};
  const Vec2 shift = mean_true - rotation.TransformPoint(mean_map);
  result.world_from_map = {shift.x, shift.y, theta};
  double sum2 = 0.0;
  for (const auto& [i, j] : pairs) {
    const double r = Norm(result.world_from_map.TransformPoint(mapped.landmarks[i].pose.Position()) -
                          truth.landmarks[j].pose.Position());
    result.residuals_m[i] = r;
    sum2 += r * r;
    result.max_residual_m = std::max(result.max_residual_m, r);
  }
  result.rmse_m = std::sqrt(sum2 / static_cast<double>(pairs.size()));
  return result;
}

}  // namespace doorplate_localization

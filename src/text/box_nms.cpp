#include "doorplate_localization/text/box_nms.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace doorplate_localization {

double BoxIoU(const cv::Rect& a, const cv::Rect& b) {
  if (a.area() <= 0 || b.area() <= 0) return 0.0;
  const double inter = static_cast<double>((a & b).area());
  return inter / (static_cast<double>(a.area()) + b.area() - inter);
}

double BoxCoverage(const cv::Rect& inner, const cv::Rect& outer) {
  if (inner.area() <= 0) return 0.0;
  return static_cast<double>((inner & outer).area()) / inner.area();
}

std::vector<ScoredBox> NonMaximumSuppression(std::vector<ScoredBox> boxes, double max_iou) {
  if (!(max_iou >= 0.0 && max_iou <= 1.0)) {
    throw std::invalid_argument("NonMaximumSuppression: max_iou must be in [0, 1], got " +
                                std::to_string(max_iou));
  }
  std::stable_sort(boxes.begin(), boxes.end(), [](const ScoredBox& a, const ScoredBox& b) {
    if (a.score != b.score) return a.score > b.score;
    return a.box_px.area() > b.box_px.area();
  });
  std::vector<bool> suppressed(boxes.size(), false);
  std::vector<ScoredBox> kept;
  for (size_t i = 0; i < boxes.size(); ++i) {
    if (suppressed[i]) continue;
    ScoredBox merged = boxes[i];
    for (size_t j = i + 1; j < boxes.size(); ++j) {
      if (suppressed[j] || BoxIoU(boxes[i].box_px, boxes[j].box_px) <= max_iou) continue;
      suppressed[j] = true;
      merged.box_px |= boxes[j].box_px;
      merged.score = std::max(merged.score, boxes[j].score);
    }
    kept.push_back(merged);
  }
  std::sort(kept.begin(), kept.end(), [](const ScoredBox& a, const ScoredBox& b) {
    return a.box_px.x != b.box_px.x ? a.box_px.x < b.box_px.x : a.box_px.y < b.box_px.y;
  });
  return kept;
}

}  // namespace doorplate_localization

// Box overlap and non-maximum suppression (paper section 4, Fig. 12: MSER vs. MSER + NMS).
// Boxes are in image pixels; a cv::Rect covers [x, x + width) × [y, y + height).
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace doorplate_localization {

struct ScoredBox {
  cv::Rect box_px;
  double score = 0.0;  // higher is better; ties keep the larger box
};

// Intersection over union in [0, 1]; 0 when either box is empty.
double BoxIoU(const cv::Rect& a, const cv::Rect& b);

// Fraction of `inner`'s area that lies inside `outer`, in [0, 1]; 0 for an empty `inner`.
double BoxCoverage(const cv::Rect& inner, const cv::Rect& outer);

// Greedy NMS: visits boxes by decreasing score (then area); each box not yet suppressed seeds a kept
// box and suppresses the remaining boxes whose IoU with the seed exceeds `max_iou`. Suppressed boxes
// are merged into the kept one (it becomes their union; IoU is always taken with the original seed, so
// merging does not chain), so overlapping fragments of one text line yield one full box.
// Returns the kept boxes sorted by x then y. `max_iou` must be in [0, 1] (std::invalid_argument).
std::vector<ScoredBox> NonMaximumSuppression(std::vector<ScoredBox> boxes, double max_iou);

}  // namespace doorplate_localization

// Text region detection interface: finds text-line boxes (room numbers) in a camera image.
// Frame: image pixels, origin top-left, x right, y down; boxes are in full-image coordinates.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace doorplate_localization {

// One detected text line.
struct TextRegion {
  cv::Rect box_px;      // full-image pixels, clipped to the image
  int num_chars = 0;    // character candidates grouped into the line (also the NMS score)
};

// Swappable text detector (MSER in the paper, section 3.2; a learned detector could replace it).
class TextRegionDetector {
 public:
  virtual ~TextRegionDetector() = default;
  // `grey` is a CV_8UC1 image of the full camera frame. Returns text-line boxes sorted left to right.
  // Throws std::invalid_argument for an empty or non-CV_8UC1 image, or a configuration that does not
  // fit this image (the message names the option field).
  virtual std::vector<TextRegion> Detect(const cv::Mat& grey) const = 0;
};

}  // namespace doorplate_localization

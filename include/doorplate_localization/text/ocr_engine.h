// Optical character recognition interface: reads the single text line in an image crop.
#pragma once

#include <string>

#include <opencv2/core.hpp>

namespace doorplate_localization {

struct OcrReading {
  std::string text;         // recognized characters, whitespace removed; empty when nothing was read
  double confidence = 0.0;  // in [0, 1]; 0 when `text` is empty
};

// Swappable recogniser (Tesseract in the paper, section 3.2). Implementations need not be thread-safe:
// use one instance per thread.
class OcrEngine {
 public:
  virtual ~OcrEngine() = default;
  // `crop` is a CV_8UC1 or CV_8UC3 (BGR) image holding one text line, text of either polarity.
  // Throws std::invalid_argument for an empty crop or another type.
  virtual OcrReading Read(const cv::Mat& crop) = 0;
};

}  // namespace doorplate_localization

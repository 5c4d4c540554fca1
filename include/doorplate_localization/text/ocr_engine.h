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

  // Readings below this confidence are not validated (TextExtractor): each recogniser's confidence has
  // its own scale, so the threshold belongs to the recogniser.
  virtual double min_confidence() const { return 0.0; }
  // True when Read gains from a colour (BGR) crop; false: TextExtractor hands it the grey image.
  virtual bool reads_colour() const { return false; }
};

}  // namespace doorplate_localization

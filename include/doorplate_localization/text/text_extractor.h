// The doorplate text extractor of the paper's section 3.2: text-line detection in the fixed image band
// (MSER + NMS), Tesseract OCR on the binarized boxes, validation against the room-number pattern and
// known rooms, and multi-frame voting that reports each plate once, when it passes the image centre.
// Frame: image pixels of the camera frame (x right, y down); bearings as in plate_tracker.h.
// Threading: not thread-safe (it owns a TesseractOcr); one instance per thread, OMP_THREAD_LIMIT=1.
#pragma once

#include <memory>
#include <vector>

#include <opencv2/core.hpp>

#include "doorplate_localization/text/mser_band_detector.h"
#include "doorplate_localization/text/ocr_engine.h"
#include "doorplate_localization/text/plate_reading_validator.h"
#include "doorplate_localization/text/plate_tracker.h"
#include "doorplate_localization/text/tesseract_ocr.h"

namespace doorplate_localization {

struct TextExtractorOptions {
  MserBandDetectorOptions detector;
  TesseractOcrOptions ocr;
  PlateReadingValidatorOptions validator;
  PlateTrackerOptions tracker;  // set fx_px / cx_px from the camera's intrinsics
  int max_regions_per_frame = 8;  // OCR is the costly step: at most this many boxes (largest first)
};

class TextExtractor {
 public:
  // Builds MserBandDetector + TesseractOcr. Throws std::invalid_argument (bad option, field named) or
  // std::runtime_error (missing Tesseract model, path named).
  explicit TextExtractor(const TextExtractorOptions& options);
  // With other detector / OCR implementations (options.detector / options.ocr are then unused).
  TextExtractor(const TextExtractorOptions& options, std::unique_ptr<TextRegionDetector> detector,
                std::unique_ptr<OcrEngine> ocr);

  // Processes one camera image (CV_8UC3 BGR or CV_8UC1 grey) taken at `stamp_s` seconds. Returns the
  // plates reported in this frame (usually none; one per plate as it crosses the image centre).
  // Throws std::invalid_argument for an empty image or another type, or when the detector's band does
  // not fit the image (field named); the extractor stays usable.
  std::vector<PlateReport> Process(const cv::Mat& image, double stamp_s);

  // Every text box of the last processed frame with its OCR and validated text (for display).
  const std::vector<PlateObservation>& last_observations() const { return last_observations_; }

  void Reset() { tracker_.Reset(); }

 private:
  const TextExtractorOptions options_;
  std::unique_ptr<TextRegionDetector> detector_;
  std::unique_ptr<OcrEngine> ocr_;
  PlateReadingValidator validator_;
  PlateTracker tracker_;
  std::vector<PlateObservation> last_observations_;
};

}  // namespace doorplate_localization

// A learned text-line detector behind TextRegionDetector: the PP-OCRv4 detection network
// (Differentiable Binarization, Liao et al. 2020; PaddleOCR, Apache-2.0) run by OpenCV's dnn module.
// Post-processing (DB's inference path): probability map > binary_threshold → connected regions → their
// minimum-area rectangle, kept if the mean probability inside is >= box_threshold → grown by DB's unclip
// offset D = A · unclip_ratio / L (A, L: the rectangle's area and perimeter) → axis-aligned box.
// (OpenCV 4.6's TextDetectionModel_DB finds no box on this network's [1, 1, H, W] output: measured.)
// It finds text of any size, font and polarity in cluttered photographs, where the MSER filters tuned
// for plates in a corridor miss; it costs ~0.1–1 s per frame on one core (docs/results/real-photos.md),
// so it is meant for still images and slow cameras, with the band to cut the cost. Weights: the same
// install step as PpOcrRecognizer (scripts/fetch_ocr_models.sh).
// Frame: image pixels, origin top-left; returned boxes are axis-aligned, in full-image coordinates.
// Threading: not thread-safe (the network keeps state); one instance per thread.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>

#include "doorplate_localization/text/mser_band_detector.h"
#include "doorplate_localization/text/text_region_detector.h"

namespace doorplate_localization {

struct DbTextDetectorOptions {
  std::string model_dir;  // as PpOcrRecognizerOptions::model_dir (ppocrv4_det.onnx)
  BandOptions band;       // rows searched; band.enabled = false: the whole image
  // The searched rows are scaled so that their shorter side becomes this many pixels (small text needs
  // ~10 px glyphs at the network's input), but the longer side at most max_input_side_px; then padded
  // to multiples of 32 (the network's stride).
  int target_short_side_px = 640;
  int max_input_side_px = 1280;
  double binary_threshold = 0.3;   // probability map → text mask
  double box_threshold = 0.5;      // mean probability inside a box to keep it
  double unclip_ratio = 1.6;       // box growth around the shrunk text kernel (DB's D = A·r / L)
  int max_candidates = 200;
  int min_box_side_px = 8;         // both sides, image pixels; smaller boxes (braille dots, specks) cannot be read
  int num_threads = 1;
};

class DbTextDetector : public TextRegionDetector {
 public:
  // Throws std::runtime_error naming a missing model file, std::invalid_argument naming a bad option.
  explicit DbTextDetector(const DbTextDetectorOptions& options);

  // Text-line boxes, left to right; num_chars is an estimate from the box's aspect (width / 0.6 height).
  std::vector<TextRegion> Detect(const cv::Mat& grey) const override;

 private:
  const DbTextDetectorOptions options_;
  // One network per input size: OpenCV 4.6 keeps the upsampling sizes of the first input it ran, so a
  // network fed another size returns a misaligned map (measured). Camera frames have one size; still
  // images of many sizes load the graph again (~0.1 s) and keep the last kMaxNetworks sizes.
  cv::dnn::Net& NetFor(const cv::Size& input_size) const;
  static constexpr size_t kMaxNetworks = 4;
  std::vector<char> onnx_bytes_;
  mutable std::vector<std::pair<cv::Size, cv::dnn::Net>> nets_;
};

}  // namespace doorplate_localization

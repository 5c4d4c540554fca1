#include "doorplate_localization/text/text_extractor.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <opencv2/imgproc.hpp>

namespace doorplate_localization {

TextExtractor::TextExtractor(const TextExtractorOptions& options)
    : TextExtractor(options, std::make_unique<MserBandDetector>(options.detector),
                    std::make_unique<TesseractOcr>(options.ocr)) {}

TextExtractor::TextExtractor(const TextExtractorOptions& options,
                             std::unique_ptr<TextRegionDetector> detector, std::unique_ptr<OcrEngine> ocr)
    : options_(options),
      detector_(std::move(detector)),
      ocr_(std::move(ocr)),
      validator_(options.validator),
      tracker_(options.tracker) {
  if (!detector_ || !ocr_) throw std::invalid_argument("TextExtractor: detector and ocr must not be null");
  if (options.max_regions_per_frame < 0) {
    throw std::invalid_argument("TextExtractorOptions.max_regions_per_frame must be >= 0");
  }
}

std::vector<PlateReport> TextExtractor::Process(const cv::Mat& image, double stamp_s) {
  if (image.empty() || (image.type() != CV_8UC3 && image.type() != CV_8UC1)) {
    throw std::invalid_argument("TextExtractor::Process: expected a non-empty CV_8UC3 (bgr8) or CV_8UC1 "
                                "(mono8) image, got " + std::to_string(image.cols) + "x" +
                                std::to_string(image.rows) + " of OpenCV type " +
                                std::to_string(image.type()));
  }
  cv::Mat grey;
  if (image.channels() == 3) {
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  } else {
    grey = image;
  }
  std::vector<TextRegion> regions = detector_->Detect(grey);
  if (static_cast<int>(regions.size()) > options_.max_regions_per_frame) {
    std::stable_sort(regions.begin(), regions.end(), [](const TextRegion& a, const TextRegion& b) {
      return a.box_px.area() > b.box_px.area();
    });
    regions.resize(options_.max_regions_per_frame);
  }
  last_observations_.clear();
  const cv::Rect image_rect(0, 0, grey.cols, grey.rows);
  for (const TextRegion& region : regions) {
    const cv::Rect box = region.box_px & image_rect;  // another detector might not clip
    if (box.empty()) continue;
    const OcrReading reading = ocr_->Read(grey(box));
    PlateObservation observation;
    observation.box_px = box;
    observation.raw_text = reading.text;
    if (const auto text = validator_.Validate(reading.text)) {
      observation.text = *text;
      observation.confidence = reading.confidence;
    }
    last_observations_.push_back(observation);
  }
  return tracker_.Update(last_observations_, stamp_s);
}

}  // namespace doorplate_localization

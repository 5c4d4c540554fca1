#include "doorplate_localization/text/text_extractor.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <opencv2/imgproc.hpp>

namespace doorplate_localization {
namespace {

std::unique_ptr<TextRegionDetector> MakeDetector(const TextExtractorOptions& options) {
  if (options.detector_type == TextDetectorType::kMser) {
    return std::make_unique<MserBandDetector>(options.detector);
  }
  DbTextDetectorOptions db = options.db_detector;
  db.band = options.detector.band;
  return std::make_unique<DbTextDetector>(db);
}

std::unique_ptr<OcrEngine> MakeRecognizer(const TextExtractorOptions& options) {
  if (options.recognizer_type == TextRecognizerType::kTesseract) {
    return std::make_unique<TesseractOcr>(options.ocr);
  }
  return std::make_unique<PpOcrRecognizer>(options.ppocr);
}

}  // namespace

TextDetectorType ParseTextDetectorType(const std::string& name, const std::string& field) {
  if (name == "mser") return TextDetectorType::kMser;
  if (name == "db") return TextDetectorType::kDb;
  throw std::invalid_argument(field + " \"" + name + "\" is not a text detector (mser, db)");
}

TextRecognizerType ParseTextRecognizerType(const std::string& name, const std::string& field) {
  if (name == "tesseract") return TextRecognizerType::kTesseract;
  if (name == "ppocr") return TextRecognizerType::kPpOcr;
  throw std::invalid_argument(field + " \"" + name + "\" is not a text recognizer (tesseract, ppocr)");
}

void UseReadingScheduleFor(TextRecognizerType recognizer, PlateTrackerOptions* tracker) {
  const bool slow = recognizer == TextRecognizerType::kPpOcr;
  tracker->read_every_n_frames = slow ? 3 : 1;
  tracker->max_readings_per_track = slow ? 8 : 0;
  tracker->enough_votes = slow ? 3 : 0;
}

std::string ToString(TextDetectorType type) { return type == TextDetectorType::kMser ? "mser" : "db"; }
std::string ToString(TextRecognizerType type) {
  return type == TextRecognizerType::kTesseract ? "tesseract" : "ppocr";
}

TextExtractor::TextExtractor(const TextExtractorOptions& options)
    : TextExtractor(options, MakeDetector(options), MakeRecognizer(options)) {}

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
  const cv::Mat grey = Grey(image);
  const std::vector<TextRegion> regions = DetectRegions(grey);
  std::vector<cv::Rect> boxes;
  for (const TextRegion& region : regions) boxes.push_back(region.box_px);
  last_observations_ = ReadRegions(image, grey, regions, tracker_.PlanReadings(boxes, stamp_s));
  return tracker_.Update(last_observations_, stamp_s);
}

std::vector<PlateObservation> TextExtractor::ReadFrame(const cv::Mat& image) {
  const cv::Mat grey = Grey(image);
  const std::vector<TextRegion> regions = DetectRegions(grey);
  return ReadRegions(image, grey, regions, std::vector<bool>(regions.size(), true));
}

cv::Mat TextExtractor::Grey(const cv::Mat& image) {
  if (image.empty() || (image.type() != CV_8UC3 && image.type() != CV_8UC1)) {
    throw std::invalid_argument("TextExtractor: expected a non-empty CV_8UC3 (bgr8) or CV_8UC1 "
                                "(mono8) image, got " + std::to_string(image.cols) + "x" +
                                std::to_string(image.rows) + " of OpenCV type " +
                                std::to_string(image.type()));
  }
  if (image.channels() == 1) return image;
  cv::Mat grey;
  cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  return grey;
}

std::vector<TextRegion> TextExtractor::DetectRegions(const cv::Mat& grey) const {
  std::vector<TextRegion> regions = detector_->Detect(grey);
  if (static_cast<int>(regions.size()) > options_.max_regions_per_frame) {
    std::stable_sort(regions.begin(), regions.end(), [](const TextRegion& a, const TextRegion& b) {
      return a.box_px.area() > b.box_px.area();
    });
    regions.resize(options_.max_regions_per_frame);
    std::stable_sort(regions.begin(), regions.end(), [](const TextRegion& a, const TextRegion& b) {
      return a.box_px.x < b.box_px.x;
    });
  }
  const cv::Rect image_rect(0, 0, grey.cols, grey.rows);
  for (TextRegion& region : regions) region.box_px &= image_rect;  // another detector might not clip
  regions.erase(std::remove_if(regions.begin(), regions.end(), [](const TextRegion& r) { return r.box_px.empty(); }),
                regions.end());
  return regions;
}

std::vector<PlateObservation> TextExtractor::ReadRegions(const cv::Mat& image, const cv::Mat& grey,
                                                         const std::vector<TextRegion>& regions,
                                                         const std::vector<bool>& read) {
  const cv::Mat& source = ocr_->reads_colour() ? image : grey;
  std::vector<PlateObservation> observations;
  for (size_t i = 0; i < regions.size(); ++i) {
    PlateObservation observation;
    observation.box_px = regions[i].box_px;
    observation.read_attempted = read[i];
    if (read[i]) {
      const OcrReading reading = ocr_->Read(source(observation.box_px));
      observation.raw_text = reading.text;
      observation.raw_confidence = reading.confidence;
      if (reading.confidence >= ocr_->min_confidence()) {
        if (const auto text = validator_.Validate(reading.text)) {
          observation.text = *text;
          observation.confidence = reading.confidence;
        }
      }
    }
    observations.push_back(observation);
  }
  return observations;
}

}  // namespace doorplate_localization

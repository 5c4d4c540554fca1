// The doorplate text extractor of the paper's section 3.2: text-line detection in the fixed image band
// (MSER + NMS), Tesseract OCR on the binarized boxes, validation against the room-number pattern and
// known rooms, and multi-frame voting that reports each plate once, when it passes the image centre.
// Detector and recogniser are chosen by option: MSER (default) or the learned DB detector, Tesseract
// (default) or the learned PP-OCR recogniser (db_text_detector.h, ppocr_recognizer.h); both learned
// models are optional installs, and asking for one that is not installed throws naming its file.
// Frame: image pixels of the camera frame (x right, y down); bearings as in plate_tracker.h.
// Threading: not thread-safe (it owns a TesseractOcr); one instance per thread, OMP_THREAD_LIMIT=1.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "doorplate_localization/text/db_text_detector.h"
#include "doorplate_localization/text/mser_band_detector.h"
#include "doorplate_localization/text/ocr_engine.h"
#include "doorplate_localization/text/plate_reading_validator.h"
#include "doorplate_localization/text/plate_tracker.h"
#include "doorplate_localization/text/ppocr_recognizer.h"
#include "doorplate_localization/text/tesseract_ocr.h"

namespace doorplate_localization {

enum class TextDetectorType { kMser, kDb };
enum class TextRecognizerType { kTesseract, kPpOcr };

// "mser" / "db" and "tesseract" / "ppocr"; throws std::invalid_argument naming `field` and the choices.
TextDetectorType ParseTextDetectorType(const std::string& name, const std::string& field);
TextRecognizerType ParseTextRecognizerType(const std::string& name, const std::string& field);
std::string ToString(TextDetectorType type);
std::string ToString(TextRecognizerType type);

// The tracker's reading schedule suited to a recogniser (PlateTrackerOptions::read_every_n_frames,
// max_readings_per_track, enough_votes): Tesseract (~3 ms a crop) reads every frame until the plate is
// reported; PP-OCR (~20–60 ms a crop on one core) reads a track every 3rd frame, stops after 3 agreeing
// readings or 8 attempts. Sets those three fields of `tracker` and nothing else.
void UseReadingScheduleFor(TextRecognizerType recognizer, PlateTrackerOptions* tracker);

struct TextExtractorOptions {
  TextDetectorType detector_type = TextDetectorType::kMser;
  TextRecognizerType recognizer_type = TextRecognizerType::kTesseract;
  MserBandDetectorOptions detector;  // its `band` is the band of either detector
  DbTextDetectorOptions db_detector;  // its `band` is ignored: detector.band is used
  TesseractOcrOptions ocr;
  PpOcrRecognizerOptions ppocr;
  PlateReadingValidatorOptions validator;
  PlateTrackerOptions tracker;  // set fx_px / cx_px from the camera's intrinsics
  int max_regions_per_frame = 8;  // OCR is the costly step: at most this many boxes (largest first)
};

class TextExtractor {
 public:
  // Builds the detector and recogniser the options choose. Throws std::invalid_argument (bad option,
  // field named) or std::runtime_error (missing Tesseract / PP-OCR model, path named).
  explicit TextExtractor(const TextExtractorOptions& options);
  // With other detector / OCR implementations (the options' detector and recogniser fields are unused).
  TextExtractor(const TextExtractorOptions& options, std::unique_ptr<TextRegionDetector> detector,
                std::unique_ptr<OcrEngine> ocr);

  // Processes one camera image (CV_8UC3 BGR or CV_8UC1 grey) taken at `stamp_s` seconds: detection,
  // recognition of the boxes the tracker's reading schedule asks for (PlateTracker::PlanReadings),
  // validation, voting. Returns the plates reported in this frame (usually none; one per plate as it
  // crosses the image centre).
  // Throws std::invalid_argument for an empty image or another type, or when the detector's band does
  // not fit the image (field named); the extractor stays usable.
  std::vector<PlateReport> Process(const cv::Mat& image, double stamp_s);

  // One still image, without the tracker: every text box (at most max_regions_per_frame, largest
  // first, returned left to right) with its OCR reading and validated text (empty when the validator
  // refused it). The same per-frame steps Process() runs; the tracker's state is untouched.
  // Throws as Process().
  std::vector<PlateObservation> ReadFrame(const cv::Mat& image);

  // Every text box of the last processed frame with its OCR and validated text (for display).
  const std::vector<PlateObservation>& last_observations() const { return last_observations_; }

  void Reset() { tracker_.Reset(); }

 private:
  static cv::Mat Grey(const cv::Mat& image);  // throws std::invalid_argument for another type
  // The detector's boxes, at most max_regions_per_frame (largest), clipped, left to right.
  std::vector<TextRegion> DetectRegions(const cv::Mat& grey) const;
  // OCR + validation of the regions whose `read` flag is set; the others are observations without text.
  std::vector<PlateObservation> ReadRegions(const cv::Mat& image, const cv::Mat& grey,
                                            const std::vector<TextRegion>& regions, const std::vector<bool>& read);

  const TextExtractorOptions options_;
  std::unique_ptr<TextRegionDetector> detector_;
  std::unique_ptr<OcrEngine> ocr_;
  PlateReadingValidator validator_;
  PlateTracker tracker_;
  std::vector<PlateObservation> last_observations_;
};

}  // namespace doorplate_localization

#include "doorplate_localization/text/db_text_detector.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>

#include "doorplate_localization/text/ppocr_recognizer.h"

namespace doorplate_localization {
namespace {

void Require(bool ok, const std::string& field, const std::string& rule) {
  if (!ok) throw std::invalid_argument("DbTextDetectorOptions." + field + " " + rule);
}

int RoundUpTo32(int v) { return (v + 31) / 32 * 32; }

// DB's post-processing on the probability map (input pixels): see the header.
std::vector<cv::RotatedRect> DbBoxes(const cv::Mat& probability, const DbTextDetectorOptions& o) {
  cv::Mat mask = probability > o.binary_threshold;
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask, contours, cv::RETR_LIST, cv::CHAIN_APPROX_SIMPLE);
  if (static_cast<int>(contours.size()) > o.max_candidates) contours.resize(o.max_candidates);
  std::vector<cv::RotatedRect> out;
  for (const std::vector<cv::Point>& contour : contours) {
    if (contour.size() < 3) continue;
    const cv::RotatedRect rect = cv::minAreaRect(contour);
    if (std::min(rect.size.width, rect.size.height) < 2.0f) continue;
    // Box score: mean probability inside the contour's region.
    const cv::Rect bound = cv::boundingRect(contour) & cv::Rect(0, 0, probability.cols, probability.rows);
    cv::Mat region(bound.size(), CV_8UC1, cv::Scalar(0));
    std::vector<std::vector<cv::Point>> shifted{contour};
    for (cv::Point& p : shifted[0]) p -= bound.tl();
    cv::fillPoly(region, shifted, cv::Scalar(255));
    if (cv::mean(probability(bound), region)[0] < o.box_threshold) continue;
    const double area = static_cast<double>(rect.size.width) * rect.size.height;
    const double perimeter = 2.0 * (rect.size.width + rect.size.height);
    const float grow = static_cast<float>(2.0 * area * o.unclip_ratio / perimeter);
    out.emplace_back(rect.center, cv::Size2f(rect.size.width + grow, rect.size.height + grow), rect.angle);
  }
  return out;
}

// Validates the options (fields named) and reads the network file.
std::vector<char> ReadNetBytes(const DbTextDetectorOptions& options) {
  Require(options.target_short_side_px >= 32, "target_short_side_px", "must be >= 32");
  Require(options.max_input_side_px >= options.target_short_side_px, "max_input_side_px",
          "must be >= target_short_side_px");
  Require(options.binary_threshold > 0.0 && options.binary_threshold < 1.0, "binary_threshold", "must be in (0, 1)");
  Require(options.box_threshold > 0.0 && options.box_threshold < 1.0, "box_threshold", "must be in (0, 1)");
  Require(options.unclip_ratio > 0.0, "unclip_ratio", "must be > 0");
  Require(options.max_candidates >= 1, "max_candidates", "must be >= 1");
  Require(options.min_box_side_px >= 1, "min_box_side_px", "must be >= 1");
  Require(options.num_threads >= 1, "num_threads", "must be >= 1");
  ResolveBandRows(options.band, 1000);  // validates the band fields (names them)
  const std::string path = ResolveOcrModelDir(options.model_dir) + "/ppocrv4_det.onnx";
  if (!std::ifstream(path).good()) {
    throw std::runtime_error("DbTextDetector: model " + path +
                             " not found (install it with scripts/fetch_ocr_models.sh, or set "
                             "DbTextDetectorOptions.model_dir / DOORPLATE_OCR_MODEL_DIR)");
  }
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  cv::dnn::Net net = cv::dnn::readNetFromONNX(bytes.data(), bytes.size());
  if (net.empty()) throw std::runtime_error("DbTextDetector: OpenCV could not load " + path);
  return bytes;
}

}  // namespace

DbTextDetector::DbTextDetector(const DbTextDetectorOptions& options)
    : options_(options), onnx_bytes_(ReadNetBytes(options)) {}

cv::dnn::Net& DbTextDetector::NetFor(const cv::Size& input_size) const {
  for (auto& [size, net] : nets_) {
    if (size == input_size) return net;
  }
  if (nets_.size() >= kMaxNetworks) nets_.erase(nets_.begin());
  nets_.emplace_back(input_size, cv::dnn::readNetFromONNX(onnx_bytes_.data(), onnx_bytes_.size()));
  nets_.back().second.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
  return nets_.back().second;
}

std::vector<TextRegion> DbTextDetector::Detect(const cv::Mat& grey) const {
  if (grey.empty() || grey.type() != CV_8UC1) {
    throw std::invalid_argument("DbTextDetector::Detect: expected a non-empty CV_8UC1 image, got " +
                                std::to_string(grey.cols) + "x" + std::to_string(grey.rows) + " of type " +
                                std::to_string(grey.type()));
  }
  const cv::Range rows = ResolveBandRows(options_.band, grey.rows);
  const cv::Mat band = grey.rowRange(rows);
  const int short_side = std::min(band.rows, band.cols), long_side = std::max(band.rows, band.cols);
  const double scale = std::min(static_cast<double>(options_.target_short_side_px) / short_side,
                                static_cast<double>(options_.max_input_side_px) / long_side);
  const int w = std::max(1, static_cast<int>(std::lround(band.cols * scale)));
  const int h = std::max(1, static_cast<int>(std::lround(band.rows * scale)));
  // The network input: the scaled band in BGR, padded (bottom, right) to multiples of 32.
  cv::Mat input(RoundUpTo32(h), RoundUpTo32(w), CV_8UC3, cv::Scalar::all(0));
  cv::Mat scaled;
  cv::resize(band, scaled, cv::Size(w, h), 0, 0, scale < 1.0 ? cv::INTER_AREA : cv::INTER_LINEAR);
  cv::cvtColor(scaled, input(cv::Rect(0, 0, w, h)), cv::COLOR_GRAY2BGR);
  // PP-OCRv4 det normalisation: (x / 255 − 0.5) / 0.5.
  const cv::Mat blob = cv::dnn::blobFromImage(input, 2.0 / 255.0, cv::Size(), cv::Scalar::all(127.5));
  const int threads = cv::getNumThreads();
  cv::setNumThreads(options_.num_threads);
  cv::dnn::Net& net = NetFor(input.size());
  net.setInput(blob);
  const cv::Mat probability = net.forward();  // [1, 1, H, W] text probability
  cv::setNumThreads(threads);
  const std::vector<cv::RotatedRect> boxes =
      DbBoxes(cv::Mat(probability.size[2], probability.size[3], CV_32F,
                      const_cast<float*>(probability.ptr<float>())), options_);
  const cv::Rect image_rect(0, 0, grey.cols, grey.rows);
  std::vector<TextRegion> out;
  for (const cv::RotatedRect& rotated : boxes) {
    const cv::Rect r = rotated.boundingRect();
    const cv::Rect box(static_cast<int>(std::floor(r.x / scale)), rows.start + static_cast<int>(std::floor(r.y / scale)),
                       static_cast<int>(std::ceil(r.width / scale)), static_cast<int>(std::ceil(r.height / scale)));
    const cv::Rect clipped = box & image_rect;
    if (std::min(clipped.width, clipped.height) < options_.min_box_side_px) continue;
    const int chars = std::max(1, static_cast<int>(std::lround(clipped.width / (0.6 * clipped.height))));
    out.push_back({clipped, chars});
  }
  std::sort(out.begin(), out.end(), [](const TextRegion& a, const TextRegion& b) {
    return a.box_px.x != b.box_px.x ? a.box_px.x < b.box_px.x : a.box_px.y < b.box_px.y;
  });
  return out;
}

}  // namespace doorplate_localization

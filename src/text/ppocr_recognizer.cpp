#include "doorplate_localization/text/ppocr_recognizer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

namespace doorplate_localization {
namespace {

constexpr const char* kDefaultModelDir = "/usr/local/share/doorplate_localization/ocr_models";
constexpr const char* kInstallHint = " (install it with scripts/fetch_ocr_models.sh, or set "
                                     "PpOcrRecognizerOptions.model_dir / DOORPLATE_OCR_MODEL_DIR)";

void Require(bool ok, const std::string& field, const std::string& rule) {
  if (!ok) throw std::invalid_argument("PpOcrRecognizerOptions." + field + " " + rule);
}

// What a dictionary entry becomes in a room identifier: ASCII letters upper-cased, the raised dot and
// full-width / typographic separators folded to their ASCII form; other entries unchanged.
std::string FoldEntry(const std::string& entry) {
  if (entry.size() == 1) {
    const char c = entry[0];
    return std::string(1, (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c);
  }
  if (entry == "\xC2\xB7" || entry == "\xEF\xBC\x8E" || entry == "\xE3\x80\x82") return ".";  // · ． 。
  if (entry == "\xE2\x80\x93" || entry == "\xE2\x80\x94" || entry == "\xEF\xBC\x8D") return "-";  // – — －
  if (entry == "\xEF\xBC\x8F") return "/";                                                       // ／
  return entry;
}

std::vector<std::string> ReadDictionary(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("PpOcrRecognizer: dictionary " + path + " not found" + kInstallHint);
  std::vector<std::string> entries;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    entries.push_back(line);
  }
  if (entries.empty()) throw std::runtime_error("PpOcrRecognizer: dictionary " + path + " is empty");
  return entries;
}

}  // namespace

std::string ResolveOcrModelDir(const std::string& model_dir) {
  if (!model_dir.empty()) return model_dir;
  const char* env = std::getenv("DOORPLATE_OCR_MODEL_DIR");
  if (env != nullptr && env[0] != '\0') return env;
  return kDefaultModelDir;
}

PpOcrRecognizer::PpOcrRecognizer(const PpOcrRecognizerOptions& options) : options_(options) {
  Require(options.input_height_px >= 8, "input_height_px", "must be >= 8");
  Require(!options.input_widths_px.empty(), "input_widths_px", "must not be empty");
  Require(std::is_sorted(options.input_widths_px.begin(), options.input_widths_px.end()) &&
              options.input_widths_px.front() >= options.input_height_px,
          "input_widths_px", "must be ascending and each >= input_height_px");
  Require(options.num_threads >= 1, "num_threads", "must be >= 1");
  Require(options.min_confidence >= 0.0 && options.min_confidence <= 1.0, "min_confidence", "must be in [0, 1]");
  const std::string dir = ResolveOcrModelDir(options.model_dir);
  const std::vector<std::string> dictionary = ReadDictionary(dir + "/ppocrv4_rec_dict.txt");
  // Class 0 is the CTC blank, 1..N the dictionary, N+1 a space (PP-OCR's use_space_char).
  classes_.assign(dictionary.size() + 2, "");
  for (size_t i = 0; i < dictionary.size(); ++i) {
    const std::string folded = FoldEntry(dictionary[i]);
    const bool allowed = options.allowed_characters.empty() ||
                         (folded.size() == 1 && options.allowed_characters.find(folded[0]) != std::string::npos);
    if (allowed) classes_[i + 1] = folded;
  }
  for (const int width : options.input_widths_px) {
    const std::string path =
        dir + "/ppocrv4_rec_" + std::to_string(options.input_height_px) + "x" + std::to_string(width) + ".onnx";
    if (!std::ifstream(path).good()) {
      throw std::runtime_error("PpOcrRecognizer: model " + path + " not found" + kInstallHint);
    }
    Model model{width, cv::dnn::readNetFromONNX(path)};
    if (model.net.empty()) throw std::runtime_error("PpOcrRecognizer: OpenCV could not load " + path);
    model.net.setPreferableBackend(cv::dnn::DNN_BACKEND_OPENCV);
    models_.push_back(std::move(model));
  }
}

OcrReading PpOcrRecognizer::Read(const cv::Mat& crop) {
  if (crop.empty() || (crop.type() != CV_8UC1 && crop.type() != CV_8UC3)) {
    throw std::invalid_argument("PpOcrRecognizer::Read: expected a non-empty CV_8UC1 or CV_8UC3 crop");
  }
  cv::Mat bgr;
  if (crop.channels() == 1) {
    cv::cvtColor(crop, bgr, cv::COLOR_GRAY2BGR);
  } else {
    bgr = crop;
  }
  const int h = options_.input_height_px;
  const int natural_w = std::max(1, static_cast<int>(std::ceil(h * static_cast<double>(bgr.cols) / bgr.rows)));
  auto model = std::find_if(models_.begin(), models_.end(), [&](const Model& m) { return m.width_px >= natural_w; });
  if (model == models_.end()) model = std::prev(models_.end());
  const int w = std::min(natural_w, model->width_px);
  cv::Mat resized;
  cv::resize(bgr, resized, cv::Size(w, h), 0, 0, cv::INTER_LINEAR);
  // PP-OCR's normalisation, (x / 255 − 0.5) / 0.5, with zeros (mid-grey) padding the right.
  cv::Mat input(h, model->width_px, CV_32FC3, cv::Scalar::all(0.0));
  resized.convertTo(input(cv::Rect(0, 0, w, h)), CV_32FC3, 2.0 / 255.0, -1.0);
  const cv::Mat blob = cv::dnn::blobFromImage(input);  // NCHW, no scaling or swapping
  const int threads = cv::getNumThreads();
  cv::setNumThreads(options_.num_threads);
  model->net.setInput(blob);
  const cv::Mat out = model->net.forward();  // [1, T, C] probabilities
  cv::setNumThreads(threads);
  if (out.dims != 3 || out.size[2] != static_cast<int>(classes_.size())) {
    throw std::runtime_error("PpOcrRecognizer: the model's output does not match the dictionary (" +
                             std::to_string(classes_.size()) + " classes)");
  }
  return Decode(cv::Mat(out.size[1], out.size[2], CV_32F, const_cast<float*>(out.ptr<float>())));
}

OcrReading PpOcrRecognizer::Decode(const cv::Mat& probabilities) const {
  OcrReading reading;
  double probability_sum = 0.0;
  int emitted = 0;
  int previous = -1;
  for (int t = 0; t < probabilities.rows; ++t) {
    const float* p = probabilities.ptr<float>(t);
    int best = 0;  // blank
    for (int c = 1; c < probabilities.cols; ++c) {
      if (!classes_[c].empty() && p[c] > p[best]) best = c;
    }
    if (best != 0 && best != previous) {
      reading.text += classes_[best];
      probability_sum += p[best];
      ++emitted;
    }
    previous = best;
  }
  if (emitted > 0) reading.confidence = std::clamp(probability_sum / emitted, 0.0, 1.0);
  return reading;
}

}  // namespace doorplate_localization

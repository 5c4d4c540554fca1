#include "doorplate_localization/text/tesseract_ocr.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <tesseract/baseapi.h>

namespace doorplate_localization {
namespace {

constexpr const char* kDebianTessdataDir = "/usr/share/tesseract-ocr/5/tessdata";

std::string RemoveWhitespace(const char* text) {
  std::string out;
  for (const char* p = text; p != nullptr && *p != '\0'; ++p) {
    if (!std::isspace(static_cast<unsigned char>(*p))) out.push_back(*p);
  }
  return out;
}

}  // namespace

std::string ResolveTessdataDir(const TesseractOcrOptions& options) {
  if (!options.tessdata_dir.empty()) return options.tessdata_dir;
  const char* env = std::getenv("TESSDATA_PREFIX");
  if (env != nullptr && env[0] != '\0') return env;
  return kDebianTessdataDir;
}

TesseractOcr::TesseractOcr(const TesseractOcrOptions& options)
    : options_(options), api_(std::make_unique<tesseract::TessBaseAPI>()) {
  ValidateOcrPreprocessOptions(options.preprocess);
  if (!(options.min_confidence >= 0.0 && options.min_confidence <= 1.0)) {
    throw std::invalid_argument("TesseractOcrOptions.min_confidence must be in [0, 1]");
  }
  const std::string dir = ResolveTessdataDir(options);
  const std::string model = dir + "/" + options.language + ".traineddata";
  if (!std::ifstream(model).good()) {
    throw std::runtime_error("TesseractOcr: model file " + model +
                             " not found (install tesseract-ocr-" + options.language +
                             ", or set TesseractOcrOptions.tessdata_dir / TESSDATA_PREFIX)");
  }
  // Dictionaries only help with words; room numbers are not words. Both are init-only variables.
  const std::vector<std::string> names = {"load_system_dawg", "load_freq_dawg"};
  const std::vector<std::string> values = {"0", "0"};
  if (api_->Init(dir.c_str(), options.language.c_str(), tesseract::OEM_LSTM_ONLY, nullptr, 0, &names,
                 &values, false) != 0) {
    throw std::runtime_error("TesseractOcr: Tesseract failed to load " + model);
  }
  api_->SetPageSegMode(options.line_mode == OcrLineMode::kSingleWord ? tesseract::PSM_SINGLE_WORD
                                                                     : tesseract::PSM_SINGLE_LINE);
  api_->SetVariable("debug_file", "/dev/null");  // Tesseract's own diagnostics would flood stdout
  if (!options.whitelist.empty()) api_->SetVariable("tessedit_char_whitelist", options.whitelist.c_str());
}

TesseractOcr::~TesseractOcr() {
  if (api_) api_->End();
}

OcrReading TesseractOcr::Read(const cv::Mat& crop) {
  const cv::Mat binary = PrepareCropForOcr(crop, options_.preprocess);
  if (binary.empty()) return {};
  return ReadBinary(binary);
}

OcrReading TesseractOcr::ReadBinary(const cv::Mat& binary) {
  if (binary.empty() || binary.type() != CV_8UC1) {
    throw std::invalid_argument("TesseractOcr::ReadBinary: expected a non-empty CV_8UC1 image");
  }
  const cv::Mat image = binary.isContinuous() ? binary : binary.clone();
  api_->SetImage(image.data, image.cols, image.rows, 1, static_cast<int>(image.step));
  api_->SetSourceResolution(300);  // glyphs are rescaled to a fixed height; silences the dpi guess
  OcrReading reading;
  if (api_->Recognize(nullptr) == 0) {
    const std::unique_ptr<char[]> text(api_->GetUTF8Text());
    reading.text = RemoveWhitespace(text.get());
    if (!reading.text.empty()) reading.confidence = std::clamp(api_->MeanTextConf() / 100.0, 0.0, 1.0);
  }
  api_->Clear();
  return reading;
}

}  // namespace doorplate_localization

// Tesseract 5 (LSTM) reader of one doorplate text line (paper section 3.2).
// Threading: a TesseractOcr is NOT thread-safe; create one instance per thread. Tesseract uses OpenMP
// internally: the process should run with OMP_THREAD_LIMIT=1 (scripts/env.sh sets it) or it will spin
// extra threads per call and get slower on a loaded robot computer — setting it is the caller's job.
#pragma once

#include <memory>
#include <string>

#include "doorplate_localization/text/ocr_engine.h"
#include "doorplate_localization/text/ocr_preprocess.h"

namespace tesseract {
class TessBaseAPI;
}

namespace doorplate_localization {

enum class OcrLineMode { kSingleLine, kSingleWord };  // Tesseract PSM_SINGLE_LINE / PSM_SINGLE_WORD

struct TesseractOcrOptions {
  // Folder holding `<language>.traineddata`. Empty: $TESSDATA_PREFIX if set, else Debian's
  // /usr/share/tesseract-ocr/5/tessdata (package tesseract-ocr-eng).
  std::string tessdata_dir;
  std::string language = "eng";
  OcrLineMode line_mode = OcrLineMode::kSingleLine;
  // Characters Tesseract may output: digits and the letters seen on room plates (wing/suffix letters).
  // Empty: no restriction.
  std::string whitelist = "0123456789ABCDEFGLNSW";
  OcrPreprocessOptions preprocess;
  // Readings whose confidence is below this are not validated (TextExtractor). 0: every reading goes
  // to the validator (Tesseract's mean confidence is poorly calibrated on single lines; the validator
  // and the multi-frame vote do the filtering).
  double min_confidence = 0.0;
};

// The tessdata folder the options resolve to (see TesseractOcrOptions::tessdata_dir).
std::string ResolveTessdataDir(const TesseractOcrOptions& options);

class TesseractOcr : public OcrEngine {
 public:
  // Loads the LSTM model. Throws std::runtime_error naming the missing file when
  // `<tessdata>/<language>.traineddata` does not exist or Tesseract fails to load it, and
  // std::invalid_argument for out-of-range preprocessing options.
  explicit TesseractOcr(const TesseractOcrOptions& options);
  ~TesseractOcr() override;
  TesseractOcr(const TesseractOcr&) = delete;
  TesseractOcr& operator=(const TesseractOcr&) = delete;

  // Binarizes the crop (PrepareCropForOcr) and reads it. confidence = Tesseract's mean text
  // confidence / 100. An unreadable crop gives {"", 0}.
  OcrReading Read(const cv::Mat& crop) override;
  double min_confidence() const override { return options_.min_confidence; }

  // Reads an already binarized image (dark text on white), skipping the preprocessing.
  OcrReading ReadBinary(const cv::Mat& binary);

 private:
  const TesseractOcrOptions options_;
  std::unique_ptr<tesseract::TessBaseAPI> api_;
};

}  // namespace doorplate_localization

// A learned text-line recogniser behind OcrEngine: the PP-OCRv4 recognition network (SVTR-LCNet, CTC
// head; PaddleOCR, Apache-2.0) run by OpenCV's dnn module on one core. Its weights come from the
// rapidocr-onnxruntime wheel on PyPI, rewritten once at install time into graphs Debian 12's OpenCV 4.6
// runs (scripts/fetch_ocr_models.sh); the package builds and runs without them (Tesseract stays the
// default recogniser, chosen by TextExtractorOptions::recognizer).
// Input: a crop holding one text line, any polarity (the network was trained on both), BGR or grey.
// Decoding: greedy CTC restricted to `allowed_characters` (room identifiers: digits, capital letters,
// separators) — a plate's "O" and "0" are told apart by the network, not by a dictionary.
// Threading: not thread-safe (cv::dnn::Net keeps state); one instance per thread.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/dnn.hpp>

#include "doorplate_localization/text/ocr_engine.h"

namespace doorplate_localization {

struct PpOcrRecognizerOptions {
  // Folder holding ppocrv4_rec_48x<W>.onnx (one per width in input_widths_px) and ppocrv4_rec_dict.txt.
  // Empty: $DOORPLATE_OCR_MODEL_DIR if set, else /usr/local/share/doorplate_localization/ocr_models.
  std::string model_dir;
  int input_height_px = 48;  // the network's input height (fixed by the model)
  // Fixed input widths the models were exported with, ascending; a crop goes to the narrowest that holds
  // it at input_height_px without squeezing, else the widest (squeezed horizontally). Cost grows with W.
  std::vector<int> input_widths_px = {160, 320};
  // Characters the decoder may output (lower-case letters of the model are folded to upper case first).
  // Empty: every character of the model's dictionary.
  std::string allowed_characters = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ-./";
  int num_threads = 1;  // cv::setNumThreads for the forward pass; the robot computer has few cores
  // Readings whose confidence (see Read) is below this are not validated (TextExtractor): PP-OCR's
  // own default score threshold; a pictogram or a braille block read as a digit scores ~0.3–0.4.
  double min_confidence = 0.5;
};

// The model folder the options resolve to (see PpOcrRecognizerOptions::model_dir).
std::string ResolveOcrModelDir(const std::string& model_dir);

class PpOcrRecognizer : public OcrEngine {
 public:
  // Loads every width's model and the dictionary. Throws std::runtime_error naming the missing or
  // unreadable file (and the command that installs it), std::invalid_argument naming a bad option.
  explicit PpOcrRecognizer(const PpOcrRecognizerOptions& options);

  // Reads one line. text: the allowed characters decoded (CTC: repeats merged, blanks dropped; the
  // middle dot "·" printed on some plates comes out as "."); confidence: the mean over the emitted
  // characters of the probability the network gives to each (PP-OCR's own score), in [0, 1];
  // {"", 0} when nothing allowed was read. Throws std::invalid_argument for an empty crop or a type
  // other than CV_8UC1 / CV_8UC3.
  OcrReading Read(const cv::Mat& crop) override;
  double min_confidence() const override { return options_.min_confidence; }
  bool reads_colour() const override { return true; }

  const PpOcrRecognizerOptions& options() const { return options_; }

 private:
  struct Model {
    int width_px = 0;
    cv::dnn::Net net;
  };
  // CTC greedy decoding of the network's [T, C] class probabilities.
  OcrReading Decode(const cv::Mat& probabilities) const;

  const PpOcrRecognizerOptions options_;
  std::vector<Model> models_;          // ascending width
  std::vector<std::string> classes_;   // class index → output UTF-8 text; "" for blank and not allowed
};

}  // namespace doorplate_localization

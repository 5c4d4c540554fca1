// Turns a detected text-line crop into the clean binary image Tesseract reads best (paper section 3.2:
// "the corresponding region of binarization is used for text recognition").
#pragma once

#include <opencv2/core.hpp>

namespace doorplate_localization {

struct OcrPreprocessOptions {
  int target_text_height_px = 30;  // glyph height after rescaling (Tesseract's LSTM likes 30–50 px)
  int border_px = 10;              // white margin added on every side, output pixels
  int min_text_height_px = 5;      // glyphs shorter than this in the crop are not read (empty output)
  // Ink eroded by this many output pixels after the rescale: Otsu on a blurred 10–15 px glyph makes its
  // strokes bold, and Tesseract then reads a flat-topped "3" as "5" or "35" (213 → 215 in 45 % of the
  // frames of the simulated ward; docs/results/table1-ocr.md). 0 keeps the thresholded strokes.
  int ink_thinning_px = 1;
};

// Throws std::invalid_argument naming the field when an option is out of range.
void ValidateOcrPreprocessOptions(const OcrPreprocessOptions& options);

// Steps: grey → Otsu threshold on the crop's inner part (15 % of the rows and 5 % of the columns
// trimmed on each side: a detector box's margin may show wall or the plate edge) → polarity: the class
// (dark or bright) with more glyph-like components (not touching the border, at least 30 % of the crop
// height) is the text, ties broken by the crop border's majority being background; light text is
// inverted → text height = tallest glyph → rescale so it becomes `target_text_height_px` → threshold
// again, ink thinned by `ink_thinning_px`, border-touching components and specks removed → white border.
// `crop`: CV_8UC1 or CV_8UC3 (BGR). Returns a CV_8UC1 image of 0 (text) and 255 (background), or an
// empty Mat when the crop holds no glyph-like component at least `min_text_height_px` tall.
// Throws std::invalid_argument for an empty crop or another type.
cv::Mat PrepareCropForOcr(const cv::Mat& crop, const OcrPreprocessOptions& options);

}  // namespace doorplate_localization

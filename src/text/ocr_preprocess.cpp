#include "doorplate_localization/text/ocr_preprocess.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <opencv2/imgproc.hpp>

namespace doorplate_localization {
namespace {

// Ink mask (255 where darker than `threshold`).
cv::Mat InkMask(const cv::Mat& grey, double threshold) {
  cv::Mat ink;
  cv::threshold(grey, ink, threshold, 255, cv::THRESH_BINARY_INV);
  return ink;
}

// The crop's inner part, where a detector's box holds text and plate only (no wall or plate edge).
cv::Mat Inner(const cv::Mat& grey) {
  const int dy = grey.rows * 15 / 100, dx = grey.cols * 5 / 100;
  return grey(cv::Rect(dx, dy, grey.cols - 2 * dx, grey.rows - 2 * dy));
}

bool TouchesBorder(const cv::Mat& stats, int label, const cv::Size& size) {
  const int x = stats.at<int>(label, cv::CC_STAT_LEFT), y = stats.at<int>(label, cv::CC_STAT_TOP);
  const int w = stats.at<int>(label, cv::CC_STAT_WIDTH), h = stats.at<int>(label, cv::CC_STAT_HEIGHT);
  return x == 0 || y == 0 || x + w == size.width || y + h == size.height;
}

// Ink components that could be glyphs: not touching the border, at least `min_height_px` tall.
struct Glyphs {
  int count = 0;
  int tallest_px = 0;
};

Glyphs FindGlyphs(const cv::Mat& ink, int min_height_px) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(ink, labels, stats, centroids, 8, CV_32S);
  Glyphs glyphs;
  for (int i = 1; i < n; ++i) {
    const int height = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    if (TouchesBorder(stats, i, ink.size()) || height < min_height_px) continue;
    ++glyphs.count;
    glyphs.tallest_px = std::max(glyphs.tallest_px, height);
  }
  return glyphs;
}

// Fraction of the mask's border pixels that are set.
double BorderFraction(const cv::Mat& mask) {
  const double set = cv::countNonZero(mask.row(0)) + cv::countNonZero(mask.row(mask.rows - 1)) +
                     cv::countNonZero(mask.col(0)) + cv::countNonZero(mask.col(mask.cols - 1));
  return set / (2.0 * (mask.rows + mask.cols));
}

// Keeps ink components that neither touch the border nor are specks smaller than `min_size` px both ways.
cv::Mat CleanInk(const cv::Mat& ink, int min_size_px) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(ink, labels, stats, centroids, 8, CV_32S);
  std::vector<std::uint8_t> keep(n, 0);
  for (int i = 1; i < n; ++i) {
    const bool speck = stats.at<int>(i, cv::CC_STAT_WIDTH) < min_size_px &&
                       stats.at<int>(i, cv::CC_STAT_HEIGHT) < min_size_px;
    keep[i] = !speck && !TouchesBorder(stats, i, ink.size());
  }
  cv::Mat clean(ink.size(), CV_8UC1);
  for (int r = 0; r < ink.rows; ++r) {
    const int* label_row = labels.ptr<int>(r);
    std::uint8_t* out = clean.ptr<std::uint8_t>(r);
    for (int c = 0; c < ink.cols; ++c) out[c] = keep[label_row[c]] ? 255 : 0;
  }
  return clean;
}

}  // namespace

void ValidateOcrPreprocessOptions(const OcrPreprocessOptions& o) {
  if (o.target_text_height_px < 8) {
    throw std::invalid_argument("OcrPreprocessOptions.target_text_height_px must be >= 8");
  }
  if (o.border_px < 0) throw std::invalid_argument("OcrPreprocessOptions.border_px must be >= 0");
  if (o.ink_thinning_px < 0) throw std::invalid_argument("OcrPreprocessOptions.ink_thinning_px must be >= 0");
  if (o.min_text_height_px < 1) {
    throw std::invalid_argument("OcrPreprocessOptions.min_text_height_px must be >= 1");
  }
}

cv::Mat PrepareCropForOcr(const cv::Mat& crop, const OcrPreprocessOptions& options) {
  if (crop.empty() || (crop.type() != CV_8UC1 && crop.type() != CV_8UC3)) {
    throw std::invalid_argument("PrepareCropForOcr: expected a non-empty CV_8UC1 or CV_8UC3 crop");
  }
  cv::Mat grey;
  if (crop.channels() == 3) {
    cv::cvtColor(crop, grey, cv::COLOR_BGR2GRAY);
  } else {
    grey = crop.clone();
  }
  // Otsu on the inner part, then the polarity that yields more glyph-like components (light text on
  // a dark plate has its glyphs in the bright class); ties go to the polarity whose background is the
  // majority of the crop's border.
  cv::Mat inner_ink;
  double threshold = cv::threshold(Inner(grey), inner_ink, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
  const int min_glyph_px = std::max(options.min_text_height_px, grey.rows * 3 / 10);
  const cv::Mat dark_ink = InkMask(grey, threshold);
  const Glyphs dark = FindGlyphs(dark_ink, min_glyph_px);
  const Glyphs light = FindGlyphs(255 - dark_ink, min_glyph_px);
  const bool light_text =
      light.count > dark.count || (light.count == dark.count && BorderFraction(dark_ink) > 0.5);
  if (light_text) {
    grey = 255 - grey;
    threshold = 255.0 - threshold;
  }
  const int text_h = light_text ? light.tallest_px : dark.tallest_px;
  if (text_h < options.min_text_height_px) return cv::Mat();

  const double scale = static_cast<double>(options.target_text_height_px) / text_h;
  cv::Mat scaled;
  cv::resize(grey, scaled, cv::Size(), scale, scale, scale > 1.0 ? cv::INTER_CUBIC : cv::INTER_AREA);
  cv::Mat ink = InkMask(scaled, threshold);
  if (options.ink_thinning_px > 0) {
    const int size = 2 * options.ink_thinning_px + 1;
    cv::erode(ink, ink, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(size, size)));
  }
  const cv::Mat clean = CleanInk(ink, options.target_text_height_px / 4);
  cv::Mat out = 255 - clean;
  cv::copyMakeBorder(out, out, options.border_px, options.border_px, options.border_px, options.border_px,
                     cv::BORDER_CONSTANT, cv::Scalar(255));
  return out;
}

}  // namespace doorplate_localization

#include "doorplate_localization/text/mser_band_detector.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "doorplate_localization/text/box_nms.h"

namespace doorplate_localization {
namespace {

void Require(bool ok, const std::string& field, const std::string& rule) {
  if (!ok) throw std::invalid_argument("MserBandDetectorOptions." + field + " " + rule);
}

void ValidateBand(const BandOptions& b) {
  const bool has_top = b.top_px >= 0, has_bottom = b.bottom_px >= 0;
  Require(has_top == has_bottom, "band.top_px/band.bottom_px",
          "must both be set (>= 0) or both unset (-1)");
  if (has_top) {
    Require(b.bottom_px > b.top_px, "band.bottom_px", "must be greater than band.top_px");
  } else {
    Require(b.top_fraction >= 0.0 && b.top_fraction < 1.0, "band.top_fraction", "must be in [0, 1)");
    Require(b.bottom_fraction > b.top_fraction && b.bottom_fraction <= 1.0, "band.bottom_fraction",
            "must be in (band.top_fraction, 1]");
  }
}

// Sum of grey values inside `r` from an integral image (CV_64F, one row/column larger than the band).
double BoxSum(const cv::Mat& integral, const cv::Rect& r) {
  return integral.at<double>(r.y + r.height, r.x + r.width) - integral.at<double>(r.y, r.x + r.width) -
         integral.at<double>(r.y + r.height, r.x) + integral.at<double>(r.y, r.x);
}

// Applies the character filters to one MSER region; false when it is not a plausible glyph.
bool ToCandidate(const cv::Mat& band, const cv::Mat& integral, const std::vector<cv::Point>& region,
                 const cv::Rect& box, const CharacterFilterOptions& f, CharacterCandidate* out) {
  if (box.height < f.min_char_height_px || box.height > f.max_char_height_px) return false;
  const double aspect = static_cast<double>(box.width) / box.height;
  if (aspect < f.min_char_aspect || aspect > f.max_char_aspect) return false;
  const double n = static_cast<double>(region.size());
  const double fill = n / box.area();
  if (fill < f.min_fill_ratio || fill > f.max_fill_ratio) return false;
  double ink_sum = 0.0;
  for (const cv::Point& p : region) ink_sum += band.at<std::uint8_t>(p);
  const double ink = ink_sum / n;
  const double rest_pixels = box.area() - n;
  if (rest_pixels < 1.0) return false;
  const double background = (BoxSum(integral, box) - ink_sum) / rest_pixels;
  if (std::abs(ink - background) < f.min_contrast_grey) return false;
  *out = CharacterCandidate{box, ink, ink < background};
  return true;
}

}  // namespace

cv::Range ResolveBandRows(const BandOptions& band, int image_height_px) {
  if (!band.enabled) return cv::Range(0, image_height_px);
  ValidateBand(band);
  if (band.top_px >= 0) {
    Require(band.bottom_px <= image_height_px, "band.bottom_px",
            "= " + std::to_string(band.bottom_px) + " exceeds the image height " +
                std::to_string(image_height_px));
    return cv::Range(band.top_px, band.bottom_px);
  }
  const int top = static_cast<int>(std::lround(band.top_fraction * image_height_px));
  const int bottom = static_cast<int>(std::lround(band.bottom_fraction * image_height_px));
  Require(bottom > top, "band.bottom_fraction",
          "gives an empty band on an image " + std::to_string(image_height_px) + " px high");
  return cv::Range(top, bottom);
}

MserBandDetector::MserBandDetector(const MserBandDetectorOptions& options) : options_(options) {
  ValidateBand(options.band);
  const MserOptions& m = options.mser;
  Require(m.delta >= 1, "mser.delta", "must be >= 1");
  Require(m.min_area_px >= 1 && m.max_area_px > m.min_area_px, "mser.max_area_px",
          "must be greater than mser.min_area_px >= 1");
  Require(m.max_variation > 0.0, "mser.max_variation", "must be > 0");
  const CharacterFilterOptions& c = options.character;
  Require(c.min_char_height_px >= 1 && c.max_char_height_px >= c.min_char_height_px,
          "character.max_char_height_px", "must be >= character.min_char_height_px >= 1");
  Require(c.min_char_aspect >= 0.0 && c.max_char_aspect >= c.min_char_aspect,
          "character.max_char_aspect", "must be >= character.min_char_aspect >= 0");
  Require(c.min_fill_ratio >= 0.0 && c.max_fill_ratio >= c.min_fill_ratio, "character.max_fill_ratio",
          "must be >= character.min_fill_ratio >= 0");
  Require(c.min_contrast_grey >= 0.0, "character.min_contrast_grey", "must be >= 0");
  ValidateLineGroupingOptions(options.grouping);
  Require(options.box_padding_to_height >= 0.0, "box_padding_to_height", "must be >= 0");
  Require(options.reference_width_px >= 0, "reference_width_px", "must be >= 0 (0: no scaling)");
  Require(options.nms_max_iou >= 0.0 && options.nms_max_iou <= 1.0, "nms_max_iou", "must be in [0, 1]");
}

std::vector<TextRegion> MserBandDetector::Detect(const cv::Mat& grey) const {
  if (grey.empty() || grey.type() != CV_8UC1) {
    throw std::invalid_argument("MserBandDetector::Detect: expected a non-empty CV_8UC1 image, got " +
                                std::to_string(grey.cols) + "x" + std::to_string(grey.rows) +
                                " of type " + std::to_string(grey.type()));
  }
  const cv::Range rows = ResolveBandRows(options_.band, grey.rows);
  const cv::Mat band = grey.rowRange(rows);
  // Pixel sizes scaled to this image's width (see reference_width_px).
  const double scale =
      options_.reference_width_px > 0 ? std::max(1.0, static_cast<double>(grey.cols) / options_.reference_width_px) : 1.0;
  const MserOptions& m = options_.mser;
  const int min_area = std::max(1, static_cast<int>(std::lround(m.min_area_px * scale * scale)));
  const int max_area = std::max(min_area + 1, static_cast<int>(std::lround(m.max_area_px * scale * scale)));
  cv::Ptr<cv::MSER> mser = cv::MSER::create(m.delta, min_area, max_area, m.max_variation);
  CharacterFilterOptions character = options_.character;
  character.min_char_height_px = std::max(1, static_cast<int>(std::lround(character.min_char_height_px * scale)));
  character.max_char_height_px = std::max(character.min_char_height_px,
                                          static_cast<int>(std::lround(character.max_char_height_px * scale)));
  std::vector<std::vector<cv::Point>> regions;
  std::vector<cv::Rect> boxes;
  mser->detectRegions(band, regions, boxes);

  cv::Mat integral;
  cv::integral(band, integral, CV_64F);
  std::vector<CharacterCandidate> candidates;
  for (size_t i = 0; i < regions.size(); ++i) {
    CharacterCandidate c;
    if (ToCandidate(band, integral, regions[i], boxes[i], character, &c)) candidates.push_back(c);
  }

  std::vector<ScoredBox> lines;
  const cv::Rect image_rect(0, 0, grey.cols, grey.rows);
  for (const TextRegion& line : GroupCharactersIntoLines(std::move(candidates), options_.grouping)) {
    const cv::Rect& b = line.box_px;
    if (b.y <= 0 || b.y + b.height >= band.rows) continue;  // cut by the band edge: unreadable
    const int pad = static_cast<int>(std::lround(options_.box_padding_to_height * b.height));
    const cv::Rect padded(b.x - pad, b.y + rows.start - pad, b.width + 2 * pad, b.height + 2 * pad);
    lines.push_back({padded & image_rect, static_cast<double>(line.num_chars)});
  }
  if (options_.nms_enabled) lines = NonMaximumSuppression(std::move(lines), options_.nms_max_iou);

  std::vector<TextRegion> out;
  for (const ScoredBox& s : lines) out.push_back({s.box_px, static_cast<int>(s.score)});
  std::sort(out.begin(), out.end(),
            [](const TextRegion& a, const TextRegion& b) { return a.box_px.x < b.box_px.x; });
  return out;
}

}  // namespace doorplate_localization

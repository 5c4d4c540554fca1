// MSER text-line detector restricted to a fixed horizontal band of the image (paper section 3.2: the
// camera looks sideways from a fixed height, so doorplates always appear at the same image rows).
// Pipeline: crop band → cv::MSER (dark and bright regions) → character filters (size, aspect, fill,
// contrast) → grouping into lines → lines touching the band's top/bottom edge dropped → padding → NMS.
// Frame: image pixels, origin top-left; all returned boxes are in full-image coordinates.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "doorplate_localization/text/character_grouping.h"
#include "doorplate_localization/text/text_region_detector.h"

namespace doorplate_localization {

// The image rows searched for plates. Defaults fit the simulator's default camera (640×480, 60° HFOV,
// 1.2 m high, pitched 10° up) and plate text centred 1.6 m high (±3.5 cm) 1.0–3.5 m away: its rows
// span 0.22–0.58 of the image height; door handles and wall signs ~1.0–1.1 m high fall below 0.75.
struct BandOptions {
  bool enabled = true;            // false: search the full image (paper Fig. 12 "MSER" baselines)
  double top_fraction = 0.20;     // of image height, in [0, 1)
  double bottom_fraction = 0.62;  // of image height, in (top_fraction, 1]
  // When both are >= 0 they replace the fractions: band rows [top_px, bottom_px).
  int top_px = -1;
  int bottom_px = -1;
};

// cv::MSER parameters (see cv::MSER::create); areas in band pixels.
struct MserOptions {
  // delta 2 and the small areas and heights below find 6–8 px glyphs of grey-on-grey plates (18 × 9 cm
  // plates 2–3 m away; docs/results/real-photos.md "Small, dim plates"); measured on the ward and the
  // real corridor: the same boxes and readings as the coarser 5 / 15 px / 8 px / 30 grey, at the same cost.
  int delta = 2;
  int min_area_px = 8;    // a thin "1" 6 px high covers ~8 px
  int max_area_px = 6000;
  double max_variation = 0.25;
};

// Per-region character filters, applied to every MSER region.
struct CharacterFilterOptions {
  int min_char_height_px = 6;
  int max_char_height_px = 80;
  double min_char_aspect = 0.1;      // box width / height
  double max_char_aspect = 1.2;
  double min_fill_ratio = 0.15;      // region pixels / box area
  double max_fill_ratio = 0.95;
  double min_contrast_grey = 10.0;   // |mean grey of region − mean grey of rest of its box|
};

struct MserBandDetectorOptions {
  BandOptions band;
  MserOptions mser;
  CharacterFilterOptions character;
  LineGroupingOptions grouping;
  double box_padding_to_height = 0.15;  // each side, as a fraction of the line height (for OCR)
  // The pixel sizes above (mser areas, character heights) are for an image this wide; on a wider image
  // (W > reference_width_px) they are scaled by W / reference_width_px (areas by its square), so a
  // 1280 × 720 camera with the same field of view needs no other settings. Narrower images (crops) keep
  // them as given. 0: no scaling.
  int reference_width_px = 640;
  bool nms_enabled = true;              // false reproduces the paper's plain "MSER" count
  double nms_max_iou = 0.3;
};

// Rows [top, bottom) of the band for an image `image_height_px` tall. Throws std::invalid_argument
// naming the field ("band.bottom_px", ...) when the band is empty or leaves the image.
cv::Range ResolveBandRows(const BandOptions& band, int image_height_px);

class MserBandDetector : public TextRegionDetector {
 public:
  // Throws std::invalid_argument naming the field of an out-of-range option.
  explicit MserBandDetector(const MserBandDetectorOptions& options);

  std::vector<TextRegion> Detect(const cv::Mat& grey) const override;

  const MserBandDetectorOptions& options() const { return options_; }

 private:
  const MserBandDetectorOptions options_;
};

}  // namespace doorplate_localization

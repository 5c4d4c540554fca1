// Groups single-character candidates (e.g. MSER regions) into horizontal text lines, as the paper's
// section 3.2 does before NMS: room numbers are short horizontal lines of same-height, same-ink glyphs.
// Coordinates are image pixels (any common origin); the output uses the input's coordinates.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "doorplate_localization/text/text_region_detector.h"

namespace doorplate_localization {

// One character candidate: its box and its ink (mean grey of the region's pixels).
struct CharacterCandidate {
  cv::Rect box_px;
  double ink_grey = 0.0;       // 0..255
  bool dark_on_light = true;   // ink darker than the box's remaining (background) pixels
};

struct LineGroupingOptions {
  // A candidate whose box lies at least this fraction inside a larger candidate's box is dropped
  // (inner holes of 0/4/6/8/9 and the same glyph found at several MSER levels).
  double max_nested_coverage = 0.8;
  // Two candidates are neighbours when all of these hold:
  double max_height_ratio = 1.5;             // taller / shorter box height
  double max_center_offset_to_height = 0.4;  // |Δ centre y| / shorter height
  // Horizontal gap between boxes / taller height. 2.4 bridges a printed separator ("16-186", "3.21",
  // "B/1404"): the hyphen or dot is too small to be a glyph candidate, so the line has a gap of about a
  // glyph there, up to ~2.2 heights on thin or italic faces with wide spacing (measured on the small,
  // dim plates world; at 1.0 "E14-295" became the lines "E14" and "295").
  double max_gap_to_height = 2.4;
  // |Δ ink_grey|; polarity must also match. Loose because blur makes thin strokes (a "1") read much
  // lighter than thick ones at 12–16 px text height.
  double max_ink_difference_grey = 80.0;
  // A line (connected component of neighbours) is kept when:
  int min_chars_per_line = 2;
  double min_line_aspect = 0.8;    // line width / height
  double max_line_aspect = 12.0;
};

// Throws std::invalid_argument naming the field when an option is out of range.
void ValidateLineGroupingOptions(const LineGroupingOptions& options);

// Returns one TextRegion per kept line: the union of its candidates' boxes (no padding) and the number
// of candidates in it, sorted left to right.
std::vector<TextRegion> GroupCharactersIntoLines(std::vector<CharacterCandidate> candidates,
                                                 const LineGroupingOptions& options);

}  // namespace doorplate_localization

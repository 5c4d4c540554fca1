#include "doorplate_localization/text/character_grouping.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>

#include "doorplate_localization/text/box_nms.h"

namespace doorplate_localization {
namespace {

void Require(bool ok, const char* field, const std::string& rule) {
  if (!ok) throw std::invalid_argument(std::string("LineGroupingOptions.") + field + " " + rule);
}

// Drops candidates lying mostly inside a larger one (largest first, so the outer glyph survives).
std::vector<CharacterCandidate> DropNested(std::vector<CharacterCandidate> candidates,
                                           double max_coverage) {
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const CharacterCandidate& a, const CharacterCandidate& b) {
                     return a.box_px.area() > b.box_px.area();
                   });
  std::vector<CharacterCandidate> kept;
  for (const CharacterCandidate& c : candidates) {
    const bool nested = std::any_of(kept.begin(), kept.end(), [&](const CharacterCandidate& k) {
      return BoxCoverage(c.box_px, k.box_px) >= max_coverage;
    });
    if (!nested) kept.push_back(c);
  }
  return kept;
}

bool AreNeighbours(const CharacterCandidate& a, const CharacterCandidate& b,
                   const LineGroupingOptions& o) {
  if (a.dark_on_light != b.dark_on_light) return false;
  if (std::abs(a.ink_grey - b.ink_grey) > o.max_ink_difference_grey) return false;
  const double ha = a.box_px.height, hb = b.box_px.height;
  const double tall = std::max(ha, hb), short_h = std::min(ha, hb);
  if (tall > o.max_height_ratio * short_h) return false;
  const double cya = a.box_px.y + 0.5 * ha, cyb = b.box_px.y + 0.5 * hb;
  if (std::abs(cya - cyb) > o.max_center_offset_to_height * short_h) return false;
  const int gap = std::max(a.box_px.x, b.box_px.x) -
                  std::min(a.box_px.x + a.box_px.width, b.box_px.x + b.box_px.width);
  return gap <= o.max_gap_to_height * tall;
}

int FindRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

void ValidateLineGroupingOptions(const LineGroupingOptions& o) {
  Require(o.max_nested_coverage > 0.0 && o.max_nested_coverage <= 1.0, "max_nested_coverage",
          "must be in (0, 1]");
  Require(o.max_height_ratio >= 1.0, "max_height_ratio", "must be >= 1");
  Require(o.max_center_offset_to_height >= 0.0, "max_center_offset_to_height", "must be >= 0");
  Require(o.max_gap_to_height >= 0.0, "max_gap_to_height", "must be >= 0");
  Require(o.max_ink_difference_grey >= 0.0, "max_ink_difference_grey", "must be >= 0");
  Require(o.min_chars_per_line >= 1, "min_chars_per_line", "must be >= 1");
  Require(o.min_line_aspect >= 0.0 && o.min_line_aspect <= o.max_line_aspect, "min_line_aspect",
          "must be in [0, max_line_aspect]");
}

std::vector<TextRegion> GroupCharactersIntoLines(std::vector<CharacterCandidate> candidates,
                                                 const LineGroupingOptions& options) {
  ValidateLineGroupingOptions(options);
  const std::vector<CharacterCandidate> chars =
      DropNested(std::move(candidates), options.max_nested_coverage);
  const int n = static_cast<int>(chars.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (AreNeighbours(chars[i], chars[j], options)) parent[FindRoot(parent, i)] = FindRoot(parent, j);
    }
  }
  std::map<int, TextRegion> lines;  // keyed by root: deterministic order
  for (int i = 0; i < n; ++i) {
    TextRegion& line = lines[FindRoot(parent, i)];
    line.box_px = line.num_chars == 0 ? chars[i].box_px : (line.box_px | chars[i].box_px);
    ++line.num_chars;
  }
  std::vector<TextRegion> out;
  for (const auto& [root, line] : lines) {
    const double aspect = static_cast<double>(line.box_px.width) / line.box_px.height;
    if (line.num_chars >= options.min_chars_per_line && aspect >= options.min_line_aspect &&
        aspect <= options.max_line_aspect) {
      out.push_back(line);
    }
  }
  std::sort(out.begin(), out.end(), [](const TextRegion& a, const TextRegion& b) {
    return a.box_px.x != b.box_px.x ? a.box_px.x < b.box_px.x : a.box_px.y < b.box_px.y;
  });
  return out;
}

}  // namespace doorplate_localization

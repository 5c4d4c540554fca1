#include "doorplate_localization/text/band_geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace doorplate_localization {
namespace {

constexpr double kPi = 3.14159265358979323846;

void Require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("BandFromGeometry: " + what);
}

}  // namespace

bool RowOfWallPoint(const BandGeometryOptions& o, double height_m, double distance_m, double* row_px) {
  const double p = o.pitch_up_deg * kPi / 180.0, up = height_m - o.mount_height_m;
  const double z = std::cos(p) * distance_m + std::sin(p) * up;  // depth in the pitched optical frame
  const double y = std::sin(p) * distance_m - std::cos(p) * up;   // down in the pitched optical frame
  if (!(z > 1e-9)) return false;
  *row_px = o.cy_px + o.fy_px * y / z;
  return true;
}

void ValidateBandGeometryOptions(const BandGeometryOptions& o) {
  Require(std::isfinite(o.mount_height_m) && o.mount_height_m > 0.0, "mount_height_m must be finite and > 0");
  Require(std::isfinite(o.pitch_up_deg) && std::fabs(o.pitch_up_deg) < 80.0, "pitch_up_deg must be within ±80");
  Require(std::isfinite(o.text_bottom_min_m) && std::isfinite(o.text_top_max_m) &&
              o.text_top_max_m > o.text_bottom_min_m,
          "text_top_max_m must be finite and > text_bottom_min_m");
  Require(std::isfinite(o.min_distance_m) && o.min_distance_m > 0.0, "min_distance_m must be finite and > 0");
  Require(std::isfinite(o.max_distance_m) && o.max_distance_m >= o.min_distance_m,
          "max_distance_m must be finite and >= min_distance_m");
  Require(std::isfinite(o.margin_px) && o.margin_px >= 0.0, "margin_px must be finite and >= 0");
}

BandOptions BandFromGeometry(const BandGeometryOptions& o) {
  Require(o.image_height_px > 0, "image_height_px must be > 0, got " + std::to_string(o.image_height_px));
  Require(std::isfinite(o.fy_px) && o.fy_px > 0.0, "fy_px must be finite and > 0, got " + std::to_string(o.fy_px));
  Require(std::isfinite(o.cy_px), "cy_px must be finite");
  ValidateBandGeometryOptions(o);
  double top = 0.0, bottom = 0.0;
  bool first = true;
  for (const double height : {o.text_top_max_m, o.text_bottom_min_m}) {
    for (const double distance : {o.min_distance_m, o.max_distance_m}) {
      double row = 0.0;
      Require(RowOfWallPoint(o, height, distance, &row),
              "text at " + std::to_string(height) + " m, " + std::to_string(distance) + " m away is behind the camera");
      top = first ? row : std::min(top, row);
      bottom = first ? row : std::max(bottom, row);
      first = false;
    }
  }
  const int top_px = std::max(0, static_cast<int>(std::floor(top - o.margin_px)));
  const int bottom_px = std::min(o.image_height_px, static_cast<int>(std::ceil(bottom + o.margin_px)) + 1);
  Require(top_px < bottom_px, "the plate text (rows " + std::to_string(top) + " to " + std::to_string(bottom) +
                                  ") is outside the image of " + std::to_string(o.image_height_px) + " rows");
  BandOptions band;
  band.enabled = true;
  band.top_px = top_px;
  band.bottom_px = bottom_px;
  return band;
}

}  // namespace doorplate_localization

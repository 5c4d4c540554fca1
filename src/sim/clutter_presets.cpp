// Clutter presets: each a few boxes at the sizes of common hospital-corridor items. Sizes follow typical
// products (type 22 panel radiator 600 mm high; 6 kg extinguisher, Ø 160 mm, 550 mm tall; EN 1970 /
// ISO hospital bed 2.18 × 1.04 m; three-shelf linen trolley 0.9 × 0.55 × 1.0 m; 45 cm seat bench) and
// are documented in docs/world-format.md. What a 2D laser at 0.25 m sees follows from the z ranges alone.
#include "doorplate_localization/sim/clutter_presets.h"

#include <stdexcept>

namespace doorplate_localization {
namespace {

const ColorRgb kMetal{85, 85, 90};
const ColorRgb kSteel{190, 192, 196};
const ColorRgb kWhite{238, 238, 232};
const ColorRgb kWood{165, 122, 80};
const ColorRgb kRed{200, 30, 30};

ClutterBox Box(double cx, double cy, double sx, double sy, double z0, double z1, const ColorRgb& color) {
  ClutterBox box;
  box.center = {cx, cy};
  box.size_x_m = sx;
  box.size_y_m = sy;
  box.z_min_m = z0;
  box.z_max_m = z1;
  box.color = color;
  return box;
}

// Four posts of side `post_m` inset `inset_m` from the corners of an l × d footprint.
void AddCornerPosts(double l, double d, double post_m, double inset_m, double z0, double z1, const ColorRgb& color,
                    std::vector<ClutterBox>* boxes) {
  const double x = l / 2 - inset_m - post_m / 2, y = d / 2 - inset_m - post_m / 2;
  for (const double sx : {-1.0, 1.0}) {
    for (const double sy : {-1.0, 1.0}) boxes->push_back(Box(sx * x, sy * y, post_m, post_m, z0, z1, color));
  }
}

std::vector<ClutterBox> Boxes(const std::string& type, double l, double d, double h, const ColorRgb* main) {
  const auto c = [&](const ColorRgb& fallback) { return main ? *main : fallback; };
  std::vector<ClutterBox> b;
  if (type == "radiator") {  // panel 0.15–0.75 m, two supply pipes to the floor
    b.push_back(Box(0, 0, l, d, 0.15, 0.75, c(kWhite)));
    for (const double sx : {-1.0, 1.0}) b.push_back(Box(sx * (l / 2 - 0.05), 0, 0.02, 0.02, 0.0, 0.15, kWhite));
  } else if (type == "fire_extinguisher") {  // wall-hung, bottom 0.9 m
    b.push_back(Box(0, 0, l, d, 0.90, 1.45, c(kRed)));
  } else if (type == "fire_extinguisher_stand") {  // on a floor stand
    b.push_back(Box(0, 0, 0.30, 0.30, 0.0, 0.03, kMetal));
    b.push_back(Box(0, 0, 0.16, 0.16, 0.05, 0.62, c(kRed)));
  } else if (type == "bench") {  // legs to 0.42 m, seat 0.42–0.47 m, backrest 0.50–0.85 m
    AddCornerPosts(l, d, 0.05, 0.05, 0.0, 0.42, kMetal, &b);
    b.push_back(Box(0, 0, l, d, 0.42, 0.47, c(kWood)));
    b.push_back(Box(0, -d / 2 + 0.02, l, 0.04, 0.50, 0.85, c(kWood)));
  } else if (type == "trolley") {  // castors, four corner posts, three shelves
    AddCornerPosts(l, d, 0.06, 0.0, 0.0, 0.12, kMetal, &b);
    AddCornerPosts(l, d, 0.03, 0.015, 0.12, 1.0, kSteel, &b);
    for (const double z : {0.28, 0.62, 0.96}) b.push_back(Box(0, 0, l, d, z, z + 0.03, c(kSteel)));
  } else if (type == "bed") {  // castors, base frame 0.20–0.34 m, lift columns, platform, mattress, boards
    AddCornerPosts(1.90, 0.75, 0.12, 0.0, 0.0, 0.20, kMetal, &b);
    b.push_back(Box(0, 0, 1.90, 0.75, 0.20, 0.34, kMetal));
    for (const double sx : {-1.0, 1.0}) b.push_back(Box(sx * 0.6, 0, 0.15, 0.15, 0.34, 0.45, kMetal));
    b.push_back(Box(0, 0, 2.00, 0.92, 0.45, 0.55, kSteel));
    b.push_back(Box(0, 0, 1.96, 0.88, 0.55, 0.70, c({215, 225, 235})));
    b.push_back(Box(-l / 2 + 0.025, 0, 0.05, d, 0.45, 1.00, kWood));
    b.push_back(Box(l / 2 - 0.025, 0, 0.05, d, 0.45, 0.85, kWood));
  } else if (type == "plant") {  // pot and foliage
    b.push_back(Box(0, 0, 0.40, 0.40, 0.0, 0.40, {170, 90, 60}));
    b.push_back(Box(0, 0, l, d, 0.40, 1.50, c({60, 120, 50})));
  } else if (type == "handrail") {  // rail 0.87–0.92 m
    b.push_back(Box(0, 0, l, d, 0.87, 0.92, c(kWood)));
  } else if (type == "skirting") {
    b.push_back(Box(0, 0, l, d, 0.0, h, c({120, 110, 100})));
  } else {
    throw std::invalid_argument("no clutter preset '" + type + "'");
  }
  return b;
}

}  // namespace

const std::vector<ClutterPreset>& ClutterPresets() {
  //                                      type, length, depth, gap, min len, max len, run, height adj., height
  static const std::vector<ClutterPreset> kPresets = {
      {"radiator", 1.0, 0.10, 0.04, 0.4, 3.0, false, false, 0.0},
      {"fire_extinguisher", 0.16, 0.16, 0.03, 0.16, 0.16, false, false, 0.0},
      {"fire_extinguisher_stand", 0.30, 0.30, 0.02, 0.30, 0.30, false, false, 0.0},
      {"bench", 1.5, 0.45, 0.02, 0.8, 3.0, false, false, 0.0},
      {"trolley", 0.9, 0.55, 0.05, 0.9, 0.9, false, false, 0.0},
      {"bed", 2.18, 1.04, 0.05, 2.18, 2.18, false, false, 0.0},
      {"plant", 0.70, 0.70, 0.05, 0.70, 0.70, false, false, 0.0},
      {"handrail", 0.0, 0.05, 0.04, 0.05, 1000.0, true, false, 0.0},
      {"skirting", 0.0, 0.015, 0.0, 0.05, 1000.0, true, true, 0.10},
  };
  return kPresets;
}

const ClutterPreset* FindClutterPreset(const std::string& type) {
  for (const ClutterPreset& p : ClutterPresets()) {
    if (p.type == type) return &p;
  }
  return nullptr;
}

std::vector<ClutterBox> ClutterPresetBoxes(const ClutterPreset& preset, double length_m, double height_m,
                                           const std::optional<ColorRgb>& color) {
  const double l = length_m > 0.0 ? length_m : preset.length_m;
  if (!(l >= preset.min_length_m - 1e-12 && l <= preset.max_length_m + 1e-12)) {
    throw std::invalid_argument("clutter '" + preset.type + "': length_m must be in [" +
                                std::to_string(preset.min_length_m) + ", " + std::to_string(preset.max_length_m) +
                                "], got " + std::to_string(l));
  }
  const double h = height_m > 0.0 ? height_m : preset.default_height_m;
  if (preset.height_adjustable && !(h > 0.0 && h <= 0.5)) {
    throw std::invalid_argument("clutter '" + preset.type + "': height_m must be in (0, 0.5], got " +
                                std::to_string(h));
  }
  return Boxes(preset.type, l, preset.depth_m, h, color ? &*color : nullptr);
}

}  // namespace doorplate_localization

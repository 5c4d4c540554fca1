#include "doorplate_localization/sim/clutter_presets.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace doorplate_localization {
namespace {

bool AnySpans(const std::vector<ClutterBox>& boxes, double z) {
  for (const ClutterBox& b : boxes) {
    if (b.z_min_m <= z && z <= b.z_max_m) return true;
  }
  return false;
}

const ClutterPreset& Preset(const std::string& type) {
  const ClutterPreset* p = FindClutterPreset(type);
  if (p == nullptr) throw std::runtime_error("no preset " + type);
  return *p;
}

TEST(ClutterPresets, TheLaserHeightMeetsWhatItShouldAndNothingElse) {
  for (const char* seen : {"radiator", "fire_extinguisher_stand", "bench", "trolley", "bed", "plant"}) {
    EXPECT_TRUE(AnySpans(ClutterPresetBoxes(Preset(seen), 0, 0, std::nullopt), 0.25)) << seen;
  }
  for (const char* unseen : {"fire_extinguisher", "handrail", "skirting"}) {
    EXPECT_FALSE(AnySpans(ClutterPresetBoxes(Preset(unseen), 1.0 * Preset(unseen).run, 0, std::nullopt), 0.25))
        << unseen;
  }
  // A skirting board tall enough reaches the laser.
  EXPECT_TRUE(AnySpans(ClutterPresetBoxes(Preset("skirting"), 2.0, 0.3, std::nullopt), 0.25));
}

TEST(ClutterPresets, BoxesStayInsideTheFootprint) {
  for (const ClutterPreset& p : ClutterPresets()) {
    const double l = p.run ? 2.0 : p.length_m;
    for (const ClutterBox& b : ClutterPresetBoxes(p, l, 0, std::nullopt)) {
      EXPECT_LE(std::abs(b.center.x) + b.size_x_m / 2, l / 2 + 1e-9) << p.type;
      EXPECT_LE(std::abs(b.center.y) + b.size_y_m / 2, p.depth_m / 2 + 1e-9) << p.type;
      EXPECT_LT(b.z_min_m, b.z_max_m) << p.type;
    }
  }
}

TEST(ClutterPresets, LengthOutsideTheRangeAndColourOverride) {
  EXPECT_THROW(ClutterPresetBoxes(Preset("radiator"), 5.0, 0, std::nullopt), std::invalid_argument);
  EXPECT_THROW(ClutterPresetBoxes(Preset("skirting"), 1.0, 0.8, std::nullopt), std::invalid_argument);
  const auto boxes = ClutterPresetBoxes(Preset("radiator"), 1.4, 0, ColorRgb{1, 2, 3});
  EXPECT_EQ(boxes[0].color, (ColorRgb{1, 2, 3}));
  EXPECT_DOUBLE_EQ(boxes[0].size_x_m, 1.4);
}

}  // namespace
}  // namespace doorplate_localization

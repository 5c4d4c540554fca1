// Box models of the static clutter a world file may place (`clutter[]`, docs/world-format.md): radiators,
// fire extinguishers, benches, trolleys, beds, plants, handrails and skirting boards, at real sizes.
// Item frame: origin at the centre of the footprint on the floor, x along the item's length (along the
// wall for wall-mounted items), y across it with the back (the side towards a wall) at y = -depth/2,
// z up from the floor. Metres.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

struct ClutterPreset {
  std::string type;
  double length_m = 0.0;          // default footprint along x
  double depth_m = 0.0;           // footprint along y
  double wall_gap_m = 0.0;        // default gap between a wall and the item's back when wall-mounted
  double min_length_m = 0.0;      // length_m may be set within [min, max]; equal: fixed size
  double max_length_m = 0.0;
  bool run = false;               // placed as a run along a wall (from_m..to_m), broken at doors and glass
  bool height_adjustable = false; // height_m may be set (skirting)
  double default_height_m = 0.0;  // for height_adjustable presets
};

// Every preset, in documentation order.
const std::vector<ClutterPreset>& ClutterPresets();
// The preset named `type`, or nullptr.
const ClutterPreset* FindClutterPreset(const std::string& type);

// The boxes of `preset` at `length_m` (0: the preset's default) and `height_m` (height-adjustable presets
// only; 0: default), in the item frame; `color` (if given) replaces the colour of the main body.
// Throws std::invalid_argument for a length or height outside the preset's range.
std::vector<ClutterBox> ClutterPresetBoxes(const ClutterPreset& preset, double length_m, double height_m,
                                           const std::optional<ColorRgb>& color);

}  // namespace doorplate_localization

// A doorplate landmark for the behaviour tests' tiny text maps.
#pragma once

#include <string>

#include "doorplate_localization/maps/text_map.h"

namespace doorplate_localization::test {

inline TextLandmark Plate(const std::string& text, double x_m, double y_m, double yaw_rad, const std::string& wall) {
  TextLandmark plate;
  plate.text = text;
  plate.pose = {x_m, y_m, yaw_rad};
  plate.wall = wall;
  return plate;
}

}  // namespace doorplate_localization::test

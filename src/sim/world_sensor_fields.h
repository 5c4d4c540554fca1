// Reads the `sensors:` block of a world file into SensorOptions (private to the world loader).
#pragma once

#include "doorplate_localization/common/yaml_reader.h"
#include "doorplate_localization/sim/sensor_options.h"

namespace doorplate_localization {

// Overrides the fields present in `sensors` ({laser: {...}, odometry: {...}, camera: {...}}); validates ranges.
void ParseSensorOptions(const YamlField& sensors, SensorOptions* options);

}  // namespace doorplate_localization

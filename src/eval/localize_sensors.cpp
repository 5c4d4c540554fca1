#include "localize_sensors.h"

#include <cmath>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

PlateReading ToPlateReading(const PlateReport& report, double camera_yaw_rad) {
  PlateReading reading = PlateReadingFromCamera(report.text, report.confidence, CameraAxis{camera_yaw_rad, 1.0},
                                                report.bearing_rad);
  reading.camera_side = camera_yaw_rad > 0.0 ? CameraSide::kLeft : camera_yaw_rad < 0.0 ? CameraSide::kRight
                                                                                        : CameraSide::kUnknown;
  return reading;
}

std::vector<PlateReading> ReadCameraFrame(Simulator& sim, TextExtractor& extractor, double camera_yaw_rad) {
  std::vector<PlateReading> readings;
  for (const PlateReport& report : extractor.Process(sim.CameraImage(), sim.time_s())) {
    readings.push_back(ToPlateReading(report, camera_yaw_rad));
  }
  return readings;
}

}  // namespace doorplate_localization

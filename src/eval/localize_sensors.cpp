#include "localize_sensors.h"

#include <cmath>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

LocalizationScan ToLocalizationScan(const SimulatedScan& scan, const LaserOptions& laser) {
  LocalizationScan out;
  out.angle_min_rad = scan.angle_min_rad;
  out.angle_increment_rad = scan.angle_increment_rad;
  out.min_range_m = scan.min_range_m;
  out.max_range_m = scan.max_range_m;
  out.ranges_m = scan.ranges_m;
  out.laser_pose = {laser.mount_x_m, laser.mount_y_m, laser.mount_yaw_rad};
  return out;
}

PlateReading ToPlateReading(const PlateReport& report, double camera_yaw_rad) {
  PlateReading reading =
      PlateReadingAt(report.text, report.confidence, camera_yaw_rad + report.bearing_rad, std::nullopt);
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

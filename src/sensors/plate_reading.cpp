#include "doorplate_localization/sensors/plate_reading.h"

#include <cmath>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/common/room_id.h"

namespace doorplate_localization {

std::string ValidatePlateReading(const PlateReading& reading) {
  if (reading.text.size() > limits::kMaxPlateTextBytes) {  // before any work on it
    return "PlateReading.text: " + std::to_string(reading.text.size()) + " bytes, more than the limit of " +
           std::to_string(limits::kMaxPlateTextBytes) + " (limits::kMaxPlateTextBytes)";
  }
  if (CanonicalPlateText(reading.text).empty()) return "PlateReading.text: empty";
  if (!(reading.confidence >= 0.0 && reading.confidence <= 1.0)) {
    return "PlateReading.confidence: must be in [0, 1], got " + std::to_string(reading.confidence);
  }
  if (!std::isfinite(reading.bearing_rad)) return "PlateReading.bearing_rad: must be finite";
  if (reading.range_m && !(std::isfinite(*reading.range_m) && *reading.range_m > 0.0)) {
    return "PlateReading.range_m: must be finite and > 0 when set, got " + std::to_string(*reading.range_m);
  }
  const double bearing = std::remainder(reading.bearing_rad, 2.0 * M_PI);
  if (reading.camera_side == CameraSide::kLeft && !(bearing > 0.0)) {
    return "PlateReading.bearing_rad: a left camera sees plates at bearings in (0, pi), got " +
           std::to_string(reading.bearing_rad);
  }
  if (reading.camera_side == CameraSide::kRight && !(bearing < 0.0)) {
    return "PlateReading.bearing_rad: a right camera sees plates at bearings in (-pi, 0), got " +
           std::to_string(reading.bearing_rad);
  }
  return "";
}

double BearingInBase(const CameraAxis& axis, double image_bearing_rad) {
  const double bearing_rad = axis.yaw_rad + axis.bearing_sign * image_bearing_rad;
  return std::isfinite(bearing_rad) ? NormalizeAngle(bearing_rad) : bearing_rad;
}

PlateReading PlateReadingFromCamera(const std::string& text, double confidence, const CameraAxis& axis,
                                    double image_bearing_rad) {
  PlateReading reading;
  reading.text = text;
  reading.confidence = confidence;
  reading.bearing_rad = BearingInBase(axis, image_bearing_rad);
  return reading;
}

std::string CanonicalPlateText(const std::string& text) { return CanonicalRoomId(text); }

}  // namespace doorplate_localization

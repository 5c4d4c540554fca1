// A doorplate reading as the localizer consumes it: what was read, how sure the reader is, and where
// the plate was seen from the robot.
#pragma once

#include <optional>
#include <string>

namespace doorplate_localization {

enum class CameraSide { kUnknown, kLeft, kRight };

struct PlateReading {
  std::string text;                // the room number read (validated text, e.g. "214")
  double confidence = 0.0;         // probability that `text` is exactly right, in [0, 1]
  // Angle of the plate centre seen from base_link (robot frame, counter-clockwise from x forward,
  // REP-103): the camera's bearing composed with its mounting yaw.
  double bearing_rad = 0.0;
  std::optional<double> range_m;   // distance base_link -> plate centre on the floor plane (e.g. from
                                   // the laser beam along the bearing); unset when unknown
  CameraSide camera_side = CameraSide::kUnknown;  // which side camera saw it (consistency check only)
};

// Returns "" if the reading is usable, else what is wrong, naming the field ("PlateReading.confidence:
// must be in [0, 1], got 1.5"). A text longer than limits::kMaxPlateTextBytes is refused (the message
// gives its length, never the text). A left camera must report a bearing in (0, pi), a right one in (-pi, 0).
std::string ValidatePlateReading(const PlateReading& reading);

// Canonical form of a plate text for matching: CanonicalRoomId (common/room_id.h): ASCII letters
// upper-cased, separators ('-' '.' '·' '/' whitespace and their OCR variants) removed ("b-12 " -> "B12").
std::string CanonicalPlateText(const std::string& text);

}  // namespace doorplate_localization

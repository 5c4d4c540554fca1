// A doorplate reading, the one plate observation type of the core (the paper's text observation
// z = (text, bearing, range)): what was read, how sure the reader is, and where the plate was seen from the
// robot. The mapping session (slam/mapping_session.h) and the localization session (mcl/text_amcl_session.h)
// consume it; when range_m is unset they measure it from their scans (sensors/plate_range.h).
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

// A camera's optical axis in base_link (ros/pose_conversions.h ToCameraAxis reads it from tf; the
// simulator's experiments from the world's camera options).
struct CameraAxis {
  double yaw_rad = 0.0;       // yaw of the optical axis about base_link's z, (-pi, pi]
  double bearing_sign = 1.0;  // turns an image bearing (positive towards the image's left) into a
                              // counter-clockwise angle about base_link's z: +1 upright, -1 upside down
};

// The one bearing composition: a plate seen at `image_bearing_rad` (positive towards the image's left) by a
// camera with `axis` lies at NormalizeAngle(yaw_rad + bearing_sign * image_bearing_rad) in base_link
// ((-pi, pi]). A non-finite image bearing gives a non-finite result (for ValidatePlateReading to name).
double BearingInBase(const CameraAxis& axis, double image_bearing_rad);

// The reading of `text` with `confidence` seen at `image_bearing_rad` by a camera with `axis`
// (BearingInBase), no range (the sessions measure it), camera side unknown. Callers validate it.
PlateReading PlateReadingFromCamera(const std::string& text, double confidence, const CameraAxis& axis,
                                    double image_bearing_rad);

// Returns "" if the reading is usable, else what is wrong, naming the field ("PlateReading.confidence:
// must be in [0, 1], got 1.5"). A text longer than limits::kMaxPlateTextBytes is refused (the message
// gives its length, never the text). A left camera must report a bearing in (0, pi), a right one in (-pi, 0).
std::string ValidatePlateReading(const PlateReading& reading);

// Canonical form of a plate text for matching: CanonicalRoomId (common/room_id.h): ASCII letters
// upper-cased, separators ('-' '.' '·' '/' whitespace and their OCR variants) removed ("b-12 " -> "B12").
std::string CanonicalPlateText(const std::string& text);

}  // namespace doorplate_localization

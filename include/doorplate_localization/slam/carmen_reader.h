// Reader of CARMEN laser logs (FLASER lines): the real-log input of the offline SLAM command.
// A FLASER line is `FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_timestamp host
// logger_timestamp`; other message types (ODOM, PARAM, comments, ...) are skipped. The log carries no
// beam geometry; CARMEN front lasers cover 180° from -90°, so n beams are spread over π radians with a
// step of π/n (n even: 180 → 1°, 360 → 0.5°) or π/(n-1) (n odd: 361 → 0.5°).
#pragma once

#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "doorplate_localization/sensors/laser_scan.h"

namespace doorplate_localization {

struct CarmenReaderOptions {
  // Readings at or above this are "no return" and become +inf (REP-117). <= 0: detect it from the log:
  // the largest reading of the log is the device's no-return value if it is at least
  // `min_no_return_range_m` (CARMEN logs hold e.g. 50.0, 81.83 or 81.91 for beams without an echo).
  double no_return_range_m = 0.0;
  double min_no_return_range_m = 20.0;
  double min_range_m = 0.01;        // shorter readings are invalid (0 is CARMEN's "no reading")
  double first_beam_angle_rad = -1.5707963267948966;
  double field_of_view_rad = 3.141592653589793;
};

// One FLASER line.
struct CarmenScan {
  int line_number = 0;        // 1-based line in the file, for messages
  int scan_index = 0;         // 0-based index among the FLASER lines (the protocol's scan_index)
  LaserScan scan;             // laser at base_link (CARMEN FLASER ranges are in the laser frame)
  Pose2D laser_pose;          // first pose triple (x y theta): the laser pose as logged
  Pose2D odometry_pose;       // second pose triple: the robot's odometry
  double timestamp_s = 0.0;   // ipc_timestamp
};

struct CarmenLog {
  std::vector<CarmenScan> scans;
  double no_return_range_m = 0.0;  // the value used (detected or given); 0 if none was found
};

// A malformed FLASER line; what() names the source, the line and the field.
class CarmenLogError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads every FLASER line of `stream` (`source` names it in errors). A `.gz` file must be unpacked
// first. Throws CarmenLogError on a malformed FLASER line.
CarmenLog ReadCarmenLog(std::istream& stream, const std::string& source,
                        const CarmenReaderOptions& options = {});

// Opens `path` and reads it as above; throws CarmenLogError if it cannot be opened.
CarmenLog ReadCarmenLogFile(const std::string& path, const CarmenReaderOptions& options = {});

}  // namespace doorplate_localization

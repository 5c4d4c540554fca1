#include "doorplate_localization/slam/carmen_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "doorplate_localization/common/limits.h"

namespace doorplate_localization {
namespace {

std::string Where(const std::string& source, int line_number) {
  return source + ":" + std::to_string(line_number) + ": ";
}

// Splits on blanks without copying more than the tokens.
std::vector<std::string> Tokens(const std::string& line) {
  std::vector<std::string> tokens;
  std::istringstream in(line);
  std::string token;
  while (in >> token) tokens.push_back(token);
  return tokens;
}

double ParseDouble(const std::string& text, const std::string& where, const std::string& field) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (end == begin || *end != '\0' || errno == ERANGE || !std::isfinite(value)) {
    throw CarmenLogError(where + field + ": not a finite number: '" + text + "'");
  }
  return value;
}

CarmenScan ParseFlaser(const std::vector<std::string>& t, const std::string& where,
                       const CarmenReaderOptions& options) {
  if (t.size() < 2) throw CarmenLogError(where + "FLASER: missing beam count");
  const double count = ParseDouble(t[1], where, "beam count");
  if (count < 2 || count > 100000 || count != std::floor(count)) {
    throw CarmenLogError(where + "beam count: must be an integer in [2, 100000], got " + t[1]);
  }
  const int n = static_cast<int>(count);
  // FLASER n r_1 .. r_n x y theta odom_x odom_y odom_theta [ipc_timestamp [ipc_hostname logger_timestamp]]:
  // n + 8, n + 9 or n + 11 fields. Any other count means the ranges do not match n (a beam lost or added),
  // which would otherwise shift every later field and be blamed on the wrong one.
  const int fields = static_cast<int>(t.size());
  if (fields != n + 8 && fields != n + 9 && fields != n + 11) {
    throw CarmenLogError(where + "FLASER with " + std::to_string(n) + " beams needs " + std::to_string(n + 8) +
                         " fields (ranges and two poses), " + std::to_string(n + 9) + " (and ipc_timestamp) or " +
                         std::to_string(n + 11) + " (and ipc_hostname, logger_timestamp), got " +
                         std::to_string(fields) + ": does the number of ranges match the beam count?");
  }
  CarmenScan out;
  LaserScan& scan = out.scan;
  const int steps = (n % 2 == 0) ? n : n - 1;  // 180 -> 1°, 360 -> 0.5°, 361 -> 0.5° with both ends
  scan.angle_min_rad = options.first_beam_angle_rad;
  scan.angle_increment_rad = options.field_of_view_rad / steps;
  scan.min_range_m = options.min_range_m;
  scan.ranges_m.resize(n);
  for (int i = 0; i < n; ++i) {
    const double range = ParseDouble(t[2 + i], where, "range " + std::to_string(i));
    // A range a float cannot hold (1e308) is no laser's: converting it would be undefined behaviour.
    if (std::fabs(range) > std::numeric_limits<float>::max()) {
      throw CarmenLogError(where + "range " + std::to_string(i) + ": " + t[2 + i] + " does not fit a float range");
    }
    scan.ranges_m[i] = static_cast<float>(range);
  }
  // Positions beyond limits::kMaxCoordinateM (a pose shifted by 1e15 m) would make the SLAM's grids
  // absurdly large: refused here, naming the line and the field.
  const auto coordinate = [&](int index, const std::string& field) {
    const double value = ParseDouble(t[index], where, field);
    const std::string problem = limits::CheckCoordinate(value);
    if (!problem.empty()) throw CarmenLogError(where + field + ": " + problem);
    return value;
  };
  const auto pose = [&](int first, const char* name) {
    return Pose2D{coordinate(first, std::string(name) + " x"), coordinate(first + 1, std::string(name) + " y"),
                  ParseDouble(t[first + 2], where, std::string(name) + " theta")};
  };
  out.laser_pose = pose(2 + n, "laser pose");
  out.odometry_pose = pose(5 + n, "odometry pose");
  if (static_cast<int>(t.size()) > n + 8) {
    out.timestamp_s = ParseDouble(t[n + 8], where, "ipc_timestamp");
  }
  return out;
}

}  // namespace

CarmenLog ReadCarmenLog(std::istream& stream, const std::string& source,
                        const CarmenReaderOptions& options) {
  CarmenLog log;
  std::string line;
  int line_number = 0;
  float largest = 0.0f;
  while (std::getline(stream, line)) {
    ++line_number;
    if (line.compare(0, 7, "FLASER ") != 0) continue;
    CarmenScan scan = ParseFlaser(Tokens(line), Where(source, line_number), options);
    scan.line_number = line_number;
    scan.scan_index = static_cast<int>(log.scans.size());
    for (float r : scan.scan.ranges_m) largest = std::max(largest, r);
    log.scans.push_back(std::move(scan));
  }
  if (stream.bad()) throw CarmenLogError(source + ": read error after line " + std::to_string(line_number));

  double no_return = options.no_return_range_m;
  if (no_return <= 0.0 && largest >= options.min_no_return_range_m) no_return = largest;
  if (no_return > 0.0) {
    // Readings are printed with two or three decimals: anything within 5 mm of the value is it.
    const float threshold = static_cast<float>(no_return - 0.005);
    for (CarmenScan& scan : log.scans) {
      for (float& r : scan.scan.ranges_m) {
        if (r >= threshold) r = std::numeric_limits<float>::infinity();
      }
    }
    log.no_return_range_m = no_return;
  }
  return log;
}

CarmenLog ReadCarmenLogFile(const std::string& path, const CarmenReaderOptions& options) {
  std::ifstream in(path);
  if (!in) throw CarmenLogError(path + ": cannot open");
  return ReadCarmenLog(in, path, options);
}

}  // namespace doorplate_localization

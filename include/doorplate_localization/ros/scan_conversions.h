// Checks of incoming LaserScan messages, shared by every nodelet that consumes scans.
#pragma once

#include <string>

#include <sensor_msgs/LaserScan.h>

namespace doorplate_localization {

// Returns "" if the scan's geometry is usable, else what is wrong with it ("no ranges", "angle_increment
// must be finite and non-zero, got nan", more than limits::kMaxScanBeams ranges, angles that do not agree
// with the number of ranges: "10 ranges, but angle_min -3.14159 .. angle_max 3.14159 at increment 0.0174533
// make 361 beams" (one beam either way is allowed: drivers differ on whether angle_max is the last beam's)). Individual NaN/±inf/negative ranges do NOT make a scan
// unusable: consumers skip those beams (REP-117).
std::string ValidateScan(const sensor_msgs::LaserScan& scan);

// True if range r is a usable return of `scan`: finite and within [range_min, range_max].
bool IsValidRange(const sensor_msgs::LaserScan& scan, float r);

}  // namespace doorplate_localization

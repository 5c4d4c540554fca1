// What the localization experiment feeds the filter from the text extractor without ROS: a PlateReport
// (camera bearing) as a PlateReading (base_link bearing; the session measures the range). The simulator's
// scans need no conversion (they are the core's LaserScan with the mounting pose). The Text AMCL nodelet does the same from messages
// and tf; here the mounting poses come from the simulated world's sensor options.
// Frames: base_link (x forward, y left, REP-103); bearings in radians counter-clockwise; ranges in metres.
#pragma once

#include <optional>
#include <vector>

#include "doorplate_localization/mcl/localization_scan.h"
#include "doorplate_localization/sensors/plate_reading.h"
#include "doorplate_localization/sim/laser_simulator.h"
#include "doorplate_localization/sim/sensor_options.h"
#include "doorplate_localization/mcl/text_amcl_session.h"
#include "doorplate_localization/sim/simulator.h"
#include "doorplate_localization/text/plate_tracker.h"
#include "doorplate_localization/text/text_extractor.h"

namespace doorplate_localization {

// A plate report of the camera mounted with yaw `camera_yaw_rad` in base_link (left camera: +pi/2) as a
// filter reading (PlateReadingFromCamera): text, confidence (the report's vote share × mean OCR confidence), base_link bearing =
// camera yaw + the report's bearing (both counter-clockwise), no range (TextAmclSession measures it from its
// scans, as in the nodelet), and the camera side from the sign of the yaw. The camera's optical centre is
// taken as base_link's origin (as above).
PlateReading ToPlateReading(const PlateReport& report, double camera_yaw_rad);

// One camera image of `sim` through `extractor`: its plate reports as readings (ToPlateReading).
std::vector<PlateReading> ReadCameraFrame(Simulator& sim, TextExtractor& extractor, double camera_yaw_rad);

// One camera image's readings (ReadCameraFrame) go to `session` (a TextAmclSession or a BuildingSession)
// with the odometry of this moment (the session measures their range and weighs them). The experiments'
// one camera input (localize, goto), as the nodelet's OnDetections is the user's.
struct CameraFeed {
  int reports = 0;       // plate reports of this image
  int plate_updates = 0; // of them, readings the filter weighed and used
};
template <class Session>
CameraFeed FeedCameraFrame(Simulator& sim, TextExtractor& extractor, double camera_yaw_rad, Session& session) {
  CameraFeed feed;
  const std::vector<PlateReading> readings = ReadCameraFrame(sim, extractor, camera_yaw_rad);
  if (readings.empty()) return feed;
  feed.reports = static_cast<int>(readings.size());
  session.AddOdometry(sim.time_s(), sim.odom_pose());
  for (const PlateReadingOutcome& p : session.AddPlates(sim.time_s(), readings).plates) {
    if (p.disposition == PlateDisposition::kWeighed && p.result.used) ++feed.plate_updates;
  }
  return feed;
}

}  // namespace doorplate_localization

// A doorplate landmark as one SLAM particle holds it (text_slam.h). Each particle's landmarks are an
// immutable vector behind a shared pointer: resampling copies the pointer, and a particle that changes
// its landmarks makes a new vector (copy-on-write; maps hold tens of plates, so a copy is cheap).
// Frames: map frame (the odometry frame at the first scan). Units: metres, radians.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

struct SlamLandmark {
  int id = -1;                // same id in every particle: the order in which landmarks were created
  std::string text;           // the room number read
  Vec2 position;              // plate centre on the wall, map frame: the mean of its measurements
  double yaw_rad = 0.0;       // direction the plate faces (the wall normal towards the corridor)
  int side = 0;               // +1 first read on the robot's left, -1 on its right
  int observations = 0;       // measurements averaged into `position`
};

using SlamLandmarks = std::vector<SlamLandmark>;
using SlamLandmarksHandle = std::shared_ptr<const SlamLandmarks>;  // null: no landmarks yet

}  // namespace doorplate_localization

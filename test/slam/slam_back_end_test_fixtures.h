// Fixtures shared by the back end's tests (slam_back_end_test.cpp, slam_back_end_mapped_ground_test.cpp).
#pragma once

#include <cmath>
#include <vector>

#include "doorplate_localization/common/geometry2d.h"
#include "slam_test_worlds.h"

namespace doorplate_localization {
namespace test {

// The back end's tests' laser: 180 beams, 16 m range.
constexpr int kBackEndBeams = 180;
constexpr double kBackEndMaxRangeM = 16.0;

// A node's points as that laser sees `walls` from `pose`, no noise.
inline std::vector<Vec2> PointsAt(const std::vector<Segment>& walls, const Pose2D& pose) {
  return Points(Scan(walls, pose, kBackEndBeams, kBackEndMaxRangeM));
}

// A few nodes turning on the spot and driving in the 6 m × 4 m room (Room()), with exact odometry.
inline std::vector<Pose2D> RoomRun() {
  return {{0, 0, 0}, {0.3, 0, M_PI / 4}, {0.6, 0.1, M_PI / 2}, {0.6, -0.4, M_PI}};
}

}  // namespace test
}  // namespace doorplate_localization

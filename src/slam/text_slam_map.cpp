// TextSlam::BuildTextMap: the best particle's landmarks as a text map (docs/text-map-format.md), walls
// found by clustering the plates, and the adjacent distances of eq. 13 from the map and from odometry.
#include <algorithm>
#include <cmath>
#include <string>

#include "doorplate_localization/slam/text_slam.h"

namespace doorplate_localization {
namespace {

constexpr double kSameWallCos = 0.866;      // facing directions within 30°
constexpr double kSameWallOffsetM = 0.5;    // and on one line within this across it

// Labels plates facing the same way on the same line with one wall index each, in order of id.
std::vector<int> ClusterWalls(const std::vector<SlamLandmark>& plates) {
  std::vector<int> wall(plates.size(), -1);
  int walls = 0;
  for (std::size_t i = 0; i < plates.size(); ++i) {
    if (wall[i] >= 0) continue;
    wall[i] = walls;
    const Vec2 normal{std::cos(plates[i].yaw_rad), std::sin(plates[i].yaw_rad)};
    for (std::size_t j = i + 1; j < plates.size(); ++j) {
      if (wall[j] >= 0) continue;
      if (std::cos(plates[j].yaw_rad - plates[i].yaw_rad) < kSameWallCos) continue;
      if (std::abs(Dot(plates[j].position - plates[i].position, normal)) > kSameWallOffsetM) continue;
      wall[j] = walls;
    }
    ++walls;
  }
  return wall;
}

}  // namespace

TextMap TextSlam::BuildTextMap() const {
  TextMap map;
  map.room_pattern = options_.room_pattern;  // every landmark's text fits it (AddPlate ignores the others)
  const std::vector<SlamLandmark> plates = BestLandmarks();
  const std::vector<int> wall = ClusterWalls(plates);
  for (std::size_t i = 0; i < plates.size(); ++i) {
    TextLandmark l;
    l.text = plates[i].text;
    l.pose = {plates[i].position.x, plates[i].position.y, plates[i].yaw_rad};
    l.wall = "wall" + std::to_string(wall[i]);
    l.observations = plates[i].observations;
    l.position_stddev_m = options_.plate_sigma_m / std::sqrt(std::max(1, plates[i].observations));
    map.landmarks.push_back(l);
  }
  ComputeAdjacentDistances(&map);  // source "map"
  // The same neighbours measured by odometry (eq. 13): the plates' odometry-frame positions at their
  // first readings.
  const std::size_t from_map = map.adjacent.size();
  for (std::size_t k = 0; k < from_map; ++k) {
    AdjacentDistance d = map.adjacent[k];
    const int a = plates[d.from].id, b = plates[d.to].id;
    if (a >= static_cast<int>(first_reading_in_odom_.size()) || b >= static_cast<int>(first_reading_in_odom_.size())) {
      continue;
    }
    d.distance_m = Norm(first_reading_in_odom_[b] - first_reading_in_odom_[a]);
    d.source = "odometry";
    map.adjacent.push_back(d);
  }
  return map;
}

}  // namespace doorplate_localization

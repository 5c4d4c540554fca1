#include "doorplate_localization/ros/map_conversions.h"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>

#include "doorplate_localization/common/limits.h"

#include "doorplate_localization/ros/pose_conversions.h"

namespace doorplate_localization {

std::string FromOccupancyGridMsg(const nav_msgs::OccupancyGrid& msg, OccupancyGrid* grid) {
  std::ostringstream problem;
  const auto& info = msg.info;
  const size_t expected = static_cast<size_t>(info.width) * info.height;
  if (!std::isfinite(info.resolution) || info.resolution <= 0.0f) {
    problem << "info.resolution must be finite and > 0, got " << info.resolution;
  } else if (const std::string bad = limits::CheckMapResolution(info.resolution); !bad.empty()) {
    problem << "info.resolution " << bad;
  } else if (info.width == 0 || info.height == 0) {
    problem << "info.width and info.height must be > 0, got " << info.width << " x " << info.height;
  } else if (const std::string too_big = limits::CheckMapCells(info.width, info.height); !too_big.empty()) {
    problem << "info.width x info.height: " << too_big;  // before the grid is allocated
  } else if (msg.data.size() != expected) {
    problem << "data has " << msg.data.size() << " cells, info says " << info.width << " x " << info.height
            << " = " << expected;
  } else if (!IsFinitePose(info.origin) || QuaternionNorm(info.origin.orientation) < 1e-6) {
    problem << "info.origin must be a finite pose with a non-zero quaternion";
  } else if (const std::string bad_x = limits::CheckCoordinate(info.origin.position.x); !bad_x.empty()) {
    problem << "info.origin.position.x " << bad_x;
  } else if (const std::string bad_y = limits::CheckCoordinate(info.origin.position.y); !bad_y.empty()) {
    problem << "info.origin.position.y " << bad_y;
  }
  if (!problem.str().empty()) return problem.str();
  OccupancyGrid out(static_cast<int>(info.width), static_cast<int>(info.height), info.resolution,
                    ToPose2D(info.origin));
  for (size_t i = 0; i < expected; ++i) {
    const int v = msg.data[i];
    out.cells[i] = (v < 0 || v > 100) ? OccupancyGrid::kUnknown : static_cast<std::int8_t>(v);
  }
  *grid = std::move(out);
  return "";
}

nav_msgs::OccupancyGrid ToOccupancyGridMsg(const OccupancyGrid& grid, const std::string& frame_id,
                                           const ros::Time& stamp) {
  nav_msgs::OccupancyGrid msg;
  msg.header.frame_id = frame_id;
  msg.header.stamp = stamp;
  msg.info.map_load_time = stamp;
  msg.info.resolution = static_cast<float>(grid.resolution_m);
  msg.info.width = static_cast<std::uint32_t>(grid.width);
  msg.info.height = static_cast<std::uint32_t>(grid.height);
  msg.info.origin = ToPoseMsg(grid.origin);
  msg.data.assign(grid.cells.begin(), grid.cells.end());
  return msg;
}

visualization_msgs::MarkerArray ToTextLandmarkMarkers(const TextMap& map, const std::string& frame_id,
                                                      const ros::Time& stamp) {
  visualization_msgs::MarkerArray array;
  visualization_msgs::Marker clear;
  clear.header.frame_id = frame_id;
  clear.header.stamp = stamp;
  clear.action = visualization_msgs::Marker::DELETEALL;
  array.markers.push_back(clear);
  for (size_t i = 0; i < map.landmarks.size(); ++i) {
    const TextLandmark& plate = map.landmarks[i];
    visualization_msgs::Marker arrow;
    arrow.header = clear.header;
    arrow.ns = "plate_pose";
    arrow.id = static_cast<int>(i);
    arrow.type = visualization_msgs::Marker::ARROW;
    arrow.action = visualization_msgs::Marker::ADD;
    arrow.pose = ToPoseMsg(plate.pose, plate.height_m);
    arrow.scale.x = 0.4;   // length, m
    arrow.scale.y = 0.05;  // shaft and head width, m
    arrow.scale.z = 0.05;
    arrow.color.r = 0.9f;
    arrow.color.g = 0.6f;
    arrow.color.b = 0.1f;
    arrow.color.a = 1.0f;
    visualization_msgs::Marker text = arrow;
    text.ns = "plate_text";
    text.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
    text.text = plate.text;
    text.pose.orientation = ToYawQuaternionMsg(0.0);
    text.pose.position.z = plate.height_m + 0.25;
    text.scale.x = text.scale.y = 0.0;
    text.scale.z = 0.3;  // text height, m
    text.color.r = text.color.g = text.color.b = 1.0f;
    array.markers.push_back(arrow);
    array.markers.push_back(text);
  }
  return array;
}

}  // namespace doorplate_localization

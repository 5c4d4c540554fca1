// Occupancy grids and text-landmark maps <-> ROS messages, shared by the mapping and localization nodelets
// (library doorplate_ros_conversions). Pure functions: no node handle, no clock; stamps and frame ids are
// passed in. Units: metres, radians; map frames follow REP-105 (the grid origin is the pose of cell (0, 0)'s
// corner in the map frame).
#pragma once

#include <string>

#include <nav_msgs/OccupancyGrid.h>
#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/maps/text_map.h"

namespace doorplate_localization {

// Returns "" and fills *grid from a nav_msgs/OccupancyGrid (values -1 unknown, 0..100; others are read as
// unknown), else what is wrong ("info.resolution must be finite and > 0, got 0", "data has 6 cells, info
// says 3 x 4 = 12", a size, resolution or origin beyond common/limits.h's bounds: "info.width x info.height:
// 20000 x 20000 = 4e+08 cells, more than the limit of 100000000 (limits::kMaxMapCells)", checked before
// anything is allocated); *grid is left alone on error. The origin's yaw is kept; its z, roll and pitch are
// ignored.
std::string FromOccupancyGridMsg(const nav_msgs::OccupancyGrid& msg, OccupancyGrid* grid);

// The grid as map_server / gmapping publish it: same row-major cell order and values, origin yaw as a
// quaternion, info.map_load_time = `stamp`.
nav_msgs::OccupancyGrid ToOccupancyGridMsg(const OccupancyGrid& grid, const std::string& frame_id,
                                           const ros::Time& stamp);

// Markers of the text landmarks for rviz (topic text_landmarks): a DELETEALL marker first (a republished
// map may have fewer landmarks), then per landmark i an arrow along the plate's facing direction at the
// plate's height (ns "plate_pose", id i) and its text above it (ns "plate_text", id i, TEXT_VIEW_FACING).
visualization_msgs::MarkerArray ToTextLandmarkMarkers(const TextMap& map, const std::string& frame_id,
                                                      const ros::Time& stamp);

}  // namespace doorplate_localization

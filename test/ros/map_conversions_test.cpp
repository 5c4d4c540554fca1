// Tests of the shared grid and landmark-marker conversions (map_conversions.h) on tiny hand-made maps.
// Merged from Text AMCL's and the mapping nodelet's tests.
#include "doorplate_localization/ros/map_conversions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <tf2/utils.h>

namespace doorplate_localization {
namespace {

TEST(FromOccupancyGridMsg, RoundTripsAGridAndReadsOutOfRangeValuesAsUnknown) {
  OccupancyGrid grid(3, 2, 0.05, Pose2D{-1.0, -0.5, 0.1}, OccupancyGrid::kFree);
  grid.At(2, 1) = OccupancyGrid::kOccupied;
  grid.At(0, 1) = OccupancyGrid::kUnknown;
  nav_msgs::OccupancyGrid msg = ToOccupancyGridMsg(grid, "map", ros::Time(3.0));
  EXPECT_EQ(msg.header.frame_id, "map");
  msg.data[1] = 120;  // not a nav_msgs value
  OccupancyGrid back;
  ASSERT_EQ(FromOccupancyGridMsg(msg, &back), "");
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.height, 2);
  EXPECT_NEAR(back.resolution_m, 0.05, 1e-7);
  EXPECT_NEAR(back.origin.x_m, -1.0, 1e-12);
  EXPECT_NEAR(back.origin.theta_rad, 0.1, 1e-12);
  EXPECT_EQ(back.At(2, 1), OccupancyGrid::kOccupied);
  EXPECT_EQ(back.At(0, 1), OccupancyGrid::kUnknown);
  EXPECT_EQ(back.At(1, 0), OccupancyGrid::kUnknown);
  EXPECT_EQ(back.At(0, 0), OccupancyGrid::kFree);
}

TEST(FromOccupancyGridMsg, NamesTheBrokenFieldAndLeavesTheGridAlone) {
  nav_msgs::OccupancyGrid msg = ToOccupancyGridMsg(OccupancyGrid(3, 4, 0.1, Pose2D{}), "map", ros::Time());
  OccupancyGrid untouched(1, 1, 1.0, Pose2D{});
  msg.data.resize(6);
  EXPECT_EQ(FromOccupancyGridMsg(msg, &untouched), "data has 6 cells, info says 3 x 4 = 12");
  msg.info.resolution = 0.0f;
  EXPECT_EQ(FromOccupancyGridMsg(msg, &untouched), "info.resolution must be finite and > 0, got 0");
  msg = ToOccupancyGridMsg(OccupancyGrid(3, 4, 0.1, Pose2D{}), "map", ros::Time());
  msg.info.origin.orientation.w = 0.0;  // an all-zero quaternion
  EXPECT_EQ(FromOccupancyGridMsg(msg, &untouched), "info.origin must be a finite pose with a non-zero quaternion");
  EXPECT_EQ(untouched.width, 1);
}

TEST(FromOccupancyGridMsg, RefusesAbsurdSizesResolutionsAndOriginsNamingTheFieldAndTheLimit) {
  OccupancyGrid untouched(1, 1, 1.0, Pose2D{});
  nav_msgs::OccupancyGrid msg = ToOccupancyGridMsg(OccupancyGrid(3, 4, 0.1, Pose2D{}), "map", ros::Time());
  msg.info.width = msg.info.height = 20000;  // data still holds 12 cells: the size is refused first
  std::string problem = FromOccupancyGridMsg(msg, &untouched);
  EXPECT_NE(problem.find("info.width x info.height: 20000 x 20000"), std::string::npos) << problem;
  EXPECT_NE(problem.find("limits::kMaxMapCells"), std::string::npos) << problem;
  msg.info.width = 3;
  msg.info.height = 4;
  msg.info.resolution = 1e-6f;
  problem = FromOccupancyGridMsg(msg, &untouched);
  EXPECT_NE(problem.find("info.resolution must be finite and in [0.001, 100]"), std::string::npos) << problem;
  msg.info.resolution = 0.1f;
  msg.info.origin.position.y = -1e300;
  problem = FromOccupancyGridMsg(msg, &untouched);
  EXPECT_NE(problem.find("info.origin.position.y must be finite and within +-1e+06 m"), std::string::npos) << problem;
  msg.info.origin.position.y = 9.9e5;  // within the bound
  EXPECT_EQ(FromOccupancyGridMsg(msg, &untouched), "");
  EXPECT_EQ(untouched.width, 3);
}

TEST(ToOccupancyGridMsg, KeepsCellsGeometryAndFrame) {
  OccupancyGrid grid(3, 2, 0.1, {-1.0, 2.0, 0.0});
  grid.At(2, 1) = OccupancyGrid::kOccupied;
  grid.At(0, 0) = OccupancyGrid::kFree;
  const nav_msgs::OccupancyGrid msg = ToOccupancyGridMsg(grid, "map", ros::Time(5.0));
  EXPECT_EQ(msg.header.frame_id, "map");
  EXPECT_EQ(msg.header.stamp, ros::Time(5.0));
  EXPECT_EQ(msg.info.map_load_time, ros::Time(5.0));
  EXPECT_EQ(msg.info.width, 3u);
  EXPECT_EQ(msg.info.height, 2u);
  EXPECT_FLOAT_EQ(msg.info.resolution, 0.1f);
  EXPECT_EQ(msg.info.origin.position.x, -1.0);
  EXPECT_EQ(msg.info.origin.orientation.w, 1.0);
  ASSERT_EQ(msg.data.size(), 6u);
  EXPECT_EQ(msg.data[0], 0);
  EXPECT_EQ(msg.data[5], 100);  // row-major, row 1 column 2
  EXPECT_EQ(msg.data[1], -1);
}

TEST(ToTextLandmarkMarkers, ClearsThenDrawsAnArrowAndTheTextOfEveryPlate) {
  TextMap map;
  map.landmarks.push_back({"101", Pose2D{2.3, 2.0, -M_PI / 2}, 1.5, "north", 0, 0.0});
  map.landmarks.push_back({"102", Pose2D{0.8, 0.0, M_PI / 2}, 1.5, "south", 0, 0.0});
  const visualization_msgs::MarkerArray array = ToTextLandmarkMarkers(map, "map", ros::Time(2.0));
  ASSERT_EQ(array.markers.size(), 5u);
  EXPECT_EQ(array.markers[0].action, visualization_msgs::Marker::DELETEALL);
  const visualization_msgs::Marker& arrow = array.markers[3];
  const visualization_msgs::Marker& text = array.markers[4];
  EXPECT_EQ(arrow.type, visualization_msgs::Marker::ARROW);
  EXPECT_EQ(arrow.ns, "plate_pose");
  EXPECT_EQ(arrow.id, 1);
  EXPECT_NEAR(tf2::getYaw(arrow.pose.orientation), M_PI / 2, 1e-12);
  EXPECT_DOUBLE_EQ(arrow.pose.position.z, 1.5);  // at the plate's height
  EXPECT_EQ(text.type, visualization_msgs::Marker::TEXT_VIEW_FACING);
  EXPECT_EQ(text.ns, "plate_text");
  EXPECT_EQ(text.text, "102");
  EXPECT_DOUBLE_EQ(text.pose.position.x, 0.8);
  EXPECT_GT(text.pose.position.z, 1.5);
  EXPECT_EQ(text.header.frame_id, "map");
}

TEST(ToTextLandmarkMarkers, UsesTheGivenFrameAndPutsEachPlateWhereItIs) {
  TextMap map;
  map.frame_id = "world";
  map.landmarks.push_back({"101", {1.0, 2.0, -M_PI / 2}, 1.5, "wall0", 3, 0.0});
  const visualization_msgs::MarkerArray array = ToTextLandmarkMarkers(map, map.frame_id, ros::Time(1.0));
  ASSERT_EQ(array.markers.size(), 3u);
  EXPECT_EQ(array.markers[0].action, visualization_msgs::Marker::DELETEALL);
  EXPECT_EQ(array.markers[1].ns, "plate_pose");
  EXPECT_EQ(array.markers[1].header.frame_id, "world");
  EXPECT_EQ(array.markers[1].pose.position.y, 2.0);
  EXPECT_EQ(array.markers[2].type, visualization_msgs::Marker::TEXT_VIEW_FACING);
  EXPECT_EQ(array.markers[2].text, "101");
}

}  // namespace
}  // namespace doorplate_localization

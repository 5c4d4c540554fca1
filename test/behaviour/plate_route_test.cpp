#include "doorplate_localization/behaviour/plate_route.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "plate_fixture.h"

namespace doorplate_localization {
namespace {

using test::Plate;

// South wall (facing +y): "102" x=1, "104" x=4, "106" x=9 with uneven spacing; north wall: "101" x=2.
// The odometry measured 3.2 m for 102-104 while mapping (the map says 3).
TextMap RouteMap() {
  TextMap map;
  map.landmarks = {Plate("102", 1.0, 0.0, M_PI / 2, "south"), Plate("104", 4.0, 0.0, M_PI / 2, "south"),
                   Plate("106", 9.0, 0.0, M_PI / 2, "south"), Plate("101", 2.0, 2.0, -M_PI / 2, "north")};
  ComputeAdjacentDistances(&map);
  map.adjacent.push_back({0, 1, 3.2, "odometry"});
  return map;
}

TEST(AdjacentRoute, SumsTheAdjacentDistancesBetweenTwoPlatesInEitherDirection) {
  TextMap map = RouteMap();
  map.adjacent.pop_back();  // map distances only
  std::string reason;
  const std::optional<PlateRoute> forward = AdjacentRoute(map, 0, 2, &reason);  // eq. 15, i < j
  ASSERT_TRUE(forward) << reason;
  EXPECT_NEAR(forward->distance_m, 3.0 + 5.0, 1e-9);
  EXPECT_EQ(forward->plates, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(forward->source, "map");
  const std::optional<PlateRoute> backward = AdjacentRoute(map, 2, 0, &reason);  // eq. 15, j < i
  ASSERT_TRUE(backward) << reason;
  EXPECT_NEAR(backward->distance_m, 8.0, 1e-9);
  EXPECT_EQ(backward->plates, (std::vector<int>{2, 1, 0}));
  const std::optional<PlateRoute> same = AdjacentRoute(map, 1, 1, &reason);
  ASSERT_TRUE(same);
  EXPECT_EQ(same->distance_m, 0.0);
}

TEST(AdjacentRoute, UsesTheOdometryDistanceOfAPairWhenTheMapHasOne) {
  std::string reason;
  const std::optional<PlateRoute> route = AdjacentRoute(RouteMap(), 0, 2, &reason);
  ASSERT_TRUE(route) << reason;
  EXPECT_NEAR(route->distance_m, 3.2 + 5.0, 1e-9);
  EXPECT_EQ(route->source, "mixed");
}

TEST(AdjacentRoute, PlatesOnDifferentWallsHaveNoRouteAndTheReasonSaysSo) {
  std::string reason;
  EXPECT_FALSE(AdjacentRoute(RouteMap(), 0, 3, &reason));
  EXPECT_NE(reason.find("different walls"), std::string::npos) << reason;
  EXPECT_THROW(AdjacentRoute(RouteMap(), 0, 7, &reason), std::out_of_range);
}

// The robot read "104" on its left while driving with odom heading 1.0 rad (odom is not aligned with map).
MatchedPlateReading ReadingOf104(bool plate_on_left) {
  MatchedPlateReading reading;
  reading.landmark = 1;
  reading.odom_pose = {10.0, -5.0, 1.0};
  reading.plate_on_left = plate_on_left;
  return reading;
}

TEST(PlanFromReading, TheGoalLiesTheRouteDistanceAheadOrBehindInTheOdomFrameFacingThePlatesWall) {
  const RoomGoalPlanner planner(RoomGoalPlannerOptions{}, RouteMap(), "route");
  // A south plate on the robot's left: the robot drives west (-x in the map), so "106" (east) is behind it
  // and "102" (west) ahead.
  const RoomGoalResult behind = PlanFromReading(planner, "106", ReadingOf104(true));
  ASSERT_TRUE(behind.goal) << behind.refusal;
  EXPECT_EQ(behind.goal->landmark, 2);
  EXPECT_NEAR(behind.goal->pose.x_m, 10.0 - 5.0 * std::cos(1.0), 1e-9);
  EXPECT_NEAR(behind.goal->pose.y_m, -5.0 - 5.0 * std::sin(1.0), 1e-9);
  EXPECT_NEAR(behind.goal->pose.theta_rad, 1.0 + M_PI / 2, 1e-9);  // the plates are on the left
  EXPECT_NE(behind.goal->note.find("5.00 m behind"), std::string::npos) << behind.goal->note;
  const RoomGoalResult ahead = PlanFromReading(planner, "102", ReadingOf104(true));
  ASSERT_TRUE(ahead.goal) << ahead.refusal;
  EXPECT_NEAR(ahead.goal->pose.x_m, 10.0 + 3.2 * std::cos(1.0), 1e-9);  // the odometry distance
  EXPECT_NE(ahead.goal->note.find("odometry adjacent distances #1 -> #0"), std::string::npos) << ahead.goal->note;
  // Seen on the right, the robot drives east: "106" is ahead and the goal faces right.
  const RoomGoalResult right = PlanFromReading(planner, "106", ReadingOf104(false));
  ASSERT_TRUE(right.goal);
  EXPECT_NEAR(right.goal->pose.x_m, 10.0 + 5.0 * std::cos(1.0), 1e-9);
  EXPECT_NEAR(right.goal->pose.theta_rad, 1.0 - M_PI / 2, 1e-9);
}

TEST(PlanFromReading, RefusesRoomsNotLinkedToTheReadPlateAndUnknownRooms) {
  const RoomGoalPlanner planner(RoomGoalPlannerOptions{}, RouteMap(), "route.yaml");
  const RoomGoalResult other_wall = PlanFromReading(planner, "101", ReadingOf104(true));
  EXPECT_FALSE(other_wall.goal);
  EXPECT_NE(other_wall.refusal.find("room 101 cannot be reached by odometry (eq. 15)"), std::string::npos)
      << other_wall.refusal;
  EXPECT_NE(other_wall.refusal.find("#1 '104'"), std::string::npos) << other_wall.refusal;
  const RoomGoalResult unknown = PlanFromReading(planner, "555", ReadingOf104(true));
  EXPECT_FALSE(unknown.goal);
  EXPECT_NE(unknown.refusal.find("room 555 is not in the text map route.yaml"), std::string::npos);
}

TEST(PlanFromReading, ARequestWithoutTheSeparatorsFindsThePrintedRoom) {
  TextMap map;
  map.landmarks = {Plate("E14-293", 1.0, 0.0, M_PI / 2, "south"), Plate("E14-295", 4.0, 0.0, M_PI / 2, "south"),
                   Plate("E14-295A", 9.0, 0.0, M_PI / 2, "south")};
  ComputeAdjacentDistances(&map);
  const RoomGoalPlanner planner(RoomGoalPlannerOptions{}, map, "e14");
  MatchedPlateReading reading;
  reading.landmark = 0;
  reading.plate_on_left = false;  // a south plate on the right: driving east, towards +x
  const RoomGoalResult result = PlanFromReading(planner, "E14295", reading);
  ASSERT_TRUE(result.goal) << result.refusal;
  EXPECT_EQ(result.goal->landmark, 1);  // not the look-alike E14-295A
  EXPECT_NEAR(result.goal->pose.x_m, 3.0, 1e-9);
}

}  // namespace
}  // namespace doorplate_localization

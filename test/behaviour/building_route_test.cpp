#include "doorplate_localization/behaviour/building_route.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace doorplate_localization {
namespace {

// A 20 m x 2 m corridor (free, walls around) with plates on its north wall at x = 3, 7, ..., 19 numbered
// <floor>01, <floor>02, ...
FloorMaps Floor(const std::string& id) {
  FloorMaps floor;
  floor.id = id;
  OccupancyGrid& g = floor.grid;
  g.resolution_m = 0.1;
  g.origin = {-1.0, -1.0, 0.0};
  g.width = 220;
  g.height = 40;
  g.cells.assign(static_cast<size_t>(g.width) * g.height, OccupancyGrid::kOccupied);
  for (int y = 10; y < 30; ++y) {
    for (int x = 10; x < 210; ++x) g.cells[static_cast<size_t>(y) * g.width + x] = OccupancyGrid::kFree;
  }
  auto text = std::make_shared<TextMap>();
  for (int k = 0; k < 5; ++k) {
    TextLandmark plate;
    plate.text = id + "0" + std::to_string(k + 1);
    plate.pose = {3.0 + 4.0 * k, 2.0, -M_PI / 2};
    plate.wall = "north";
    text->landmarks.push_back(plate);
  }
  floor.text_map = text;
  return floor;
}

// Floors 2 and 3; lift W at the west end (x = 1) and lift E at the east end (x = 18) on both floors.
std::shared_ptr<BuildingMaps> Building(bool lift_east_on_both = true) {
  auto maps = std::make_shared<BuildingMaps>();
  maps->name = "test_building";
  maps->floors = {Floor("2"), Floor("3")};
  maps->lifts.push_back({"W", {{"2", {1.0, 1.0, M_PI}}, {"3", {1.0, 1.0, M_PI}}}});
  if (lift_east_on_both) maps->lifts.push_back({"E", {{"2", {18.0, 1.0, 0.0}}, {"3", {18.0, 1.0, 0.0}}}});
  return maps;
}

TEST(BuildingRoutePlanner, ARoomOnTheRobotsFloorNeedsNoLift) {
  const BuildingRoutePlanner planner(BuildingRouteOptions{}, Building());
  const BuildingRouteResult result = planner.Plan("203", 0, {2.0, 1.0, 0.0});
  ASSERT_TRUE(result.route.has_value()) << result.refusal;
  EXPECT_FALSE(result.route->via_lift);
  EXPECT_EQ(result.route->room_floor, 0);
  EXPECT_NEAR(result.route->goal.pose.x_m, 11.0, 1e-9);
  EXPECT_NEAR(result.route->length_m, 9.0, 0.5);
  EXPECT_EQ(result.route->instruction, "room 203 is on this floor (2)");
}

TEST(BuildingRoutePlanner, ARoomOnAnotherFloorTakesTheLiftOfTheShortestRoute) {
  const BuildingRoutePlanner planner(BuildingRouteOptions{}, Building());
  // From x = 12 on floor 2 to room 305 (x = 19) on floor 3: lift E (6 m + 1 m) beats lift W (11 m + 18 m).
  const BuildingRouteResult result = planner.Plan("305", 0, {12.0, 1.0, 0.0});
  ASSERT_TRUE(result.route.has_value()) << result.refusal;
  EXPECT_TRUE(result.route->via_lift);
  EXPECT_EQ(result.route->room_floor, 1);
  EXPECT_EQ(result.route->lift, "E");
  EXPECT_NEAR(result.route->lift_stop_here.x_m, 18.0, 1e-9);
  EXPECT_NEAR(result.route->goal.pose.x_m, 19.0, 1e-9);
  EXPECT_NEAR(result.route->length_m, 7.5, 0.7);
  EXPECT_NE(result.route->instruction.find("take lift E from floor 2 to floor 3"), std::string::npos)
      << result.route->instruction;
  // From the west end the west lift is shorter for room 301 (x = 3).
  const BuildingRouteResult west = planner.Plan("301", 0, {2.0, 1.0, 0.0});
  ASSERT_TRUE(west.route.has_value()) << west.refusal;
  EXPECT_EQ(west.route->lift, "W");
}

TEST(BuildingRoutePlanner, ARoomOnNoFloorIsRefusedNamingTheBuilding) {
  const BuildingRoutePlanner planner(BuildingRouteOptions{}, Building());
  const BuildingRouteResult result = planner.Plan("999", 0, {2.0, 1.0, 0.0});
  EXPECT_FALSE(result.route.has_value());
  EXPECT_NE(result.refusal.find("999"), std::string::npos) << result.refusal;
  EXPECT_NE(result.refusal.find("nor on any other floor of building test_building"), std::string::npos)
      << result.refusal;
}

TEST(BuildingRoutePlanner, FloorsNoLiftJoinsAreRefusedSayingSo) {
  auto maps = Building(false);
  maps->lifts.front().stops.pop_back();  // lift W no longer stops on floor 3
  maps->lifts.front().stops.push_back({"4", {1.0, 1.0, 0.0}});
  const BuildingRoutePlanner planner(BuildingRouteOptions{}, maps);
  const BuildingRouteResult result = planner.Plan("305", 0, {12.0, 1.0, 0.0});
  EXPECT_FALSE(result.route.has_value());
  EXPECT_NE(result.refusal.find("no lift stops on floors 2 and 3"), std::string::npos) << result.refusal;
}

TEST(BuildingRoutePlanner, RefusesAFloorWithoutATextMap) {
  auto maps = Building();
  maps->floors[1].text_map = nullptr;
  EXPECT_THROW(BuildingRoutePlanner(BuildingRouteOptions{}, maps), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/behaviour/room_goal_planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "plate_fixture.h"

namespace doorplate_localization {
namespace {

using test::Plate;

// A 2 m wide corridor along x: "101" on the north wall (facing -y), "102" on the south wall (facing +y), and
// "220" once on each wall.
TextMap SmallMap() {
  TextMap map;
  map.landmarks = {Plate("101", 3.0, 2.0, -M_PI / 2, "north"), Plate("102", 5.0, 0.0, M_PI / 2, "south"),
                   Plate("220", 9.0, 0.0, M_PI / 2, "south"), Plate("220", 12.0, 2.0, -M_PI / 2, "north")};
  return map;
}

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(RoomGoalPlanner, TheGoalIsInFrontOfThePlateAtTheWallDistanceFacingTheDoor) {
  RoomGoalPlannerOptions options;
  options.wall_distance_m = 0.5;
  const RoomGoalPlanner planner(options, SmallMap(), "small.text_map.yaml");
  const RoomGoalResult north = planner.Plan("101", std::nullopt);
  ASSERT_TRUE(north.goal) << north.refusal;
  EXPECT_EQ(north.goal->room, "101");
  EXPECT_EQ(north.goal->landmark, 0);
  EXPECT_NEAR(north.goal->pose.x_m, 3.0, 1e-9);
  EXPECT_NEAR(north.goal->pose.y_m, 1.5, 1e-9);
  EXPECT_NEAR(north.goal->pose.theta_rad, M_PI / 2, 1e-9);  // looking at the north wall
  EXPECT_TRUE(north.goal->note.empty());
  const RoomGoalResult south = planner.Plan(" 102\n", Pose2D{});  // surrounding whitespace is ignored
  ASSERT_TRUE(south.goal) << south.refusal;
  EXPECT_NEAR(south.goal->pose.x_m, 5.0, 1e-9);
  EXPECT_NEAR(south.goal->pose.y_m, 0.5, 1e-9);
  EXPECT_NEAR(south.goal->pose.theta_rad, -M_PI / 2, 1e-9);
}

TEST(RoomGoalPlanner, RefusesAnUnknownRoomNamingTheTextMapAndTheKnownRooms) {
  const RoomGoalPlanner planner(RoomGoalPlannerOptions{}, SmallMap(), "maps/small.text_map.yaml");
  const RoomGoalResult result = planner.Plan("999", Pose2D{});
  EXPECT_FALSE(result.goal);
  EXPECT_EQ(result.refusal,
            "room 999 is not in the text map maps/small.text_map.yaml; known rooms: 101, 102, 220");
  const RoomGoalResult empty = planner.Plan("  ", Pose2D{});
  EXPECT_FALSE(empty.goal);
  EXPECT_TRUE(Contains(empty.refusal, "empty room number")) << empty.refusal;
}

TEST(RoomGoalPlanner, ARepeatedRoomGoesToTheNearestPlateAndSaysWhichPlatesThereWere) {
  const RoomGoalPlanner planner(RoomGoalPlannerOptions{}, SmallMap(), "small");
  const RoomGoalResult near_south = planner.Plan("220", Pose2D{8.0, 1.0, 0.0});
  ASSERT_TRUE(near_south.goal) << near_south.refusal;
  EXPECT_EQ(near_south.goal->landmark, 2);
  EXPECT_TRUE(Contains(near_south.goal->note, "room 220 is on 2 plates")) << near_south.goal->note;
  EXPECT_TRUE(Contains(near_south.goal->note, "#3 '220' on wall north")) << near_south.goal->note;
  EXPECT_TRUE(Contains(near_south.goal->note, "going to the nearest, #2")) << near_south.goal->note;
  const RoomGoalResult near_north = planner.Plan("220", Pose2D{13.0, 1.0, 0.0});
  ASSERT_TRUE(near_north.goal);
  EXPECT_EQ(near_north.goal->landmark, 3);
}

TEST(RoomGoalPlanner, ARepeatedRoomIsRefusedUnderTheRefuseRuleOrWithoutAPoseListingTheRequestsThatSelectOne) {
  RoomGoalPlannerOptions refuse;
  refuse.duplicate_rule = "refuse";
  const RoomGoalResult refused = RoomGoalPlanner(refuse, SmallMap(), "small").Plan("220", Pose2D{8.0, 1.0, 0.0});
  EXPECT_FALSE(refused.goal);
  EXPECT_TRUE(Contains(refused.refusal, "ask for one of them: '220@south', '220@north'")) << refused.refusal;
  const RoomGoalResult no_pose = RoomGoalPlanner(RoomGoalPlannerOptions{}, SmallMap(), "small").Plan("220", std::nullopt);
  EXPECT_FALSE(no_pose.goal);
  EXPECT_TRUE(Contains(no_pose.refusal, "pose is unknown")) << no_pose.refusal;
}

TEST(RoomGoalPlanner, AWallSuffixSelectsOnePlateOfARepeatedRoom) {
  RoomGoalPlannerOptions refuse;
  refuse.duplicate_rule = "refuse";
  const RoomGoalPlanner planner(refuse, SmallMap(), "small");
  const RoomGoalResult north = planner.Plan("220@north", std::nullopt);
  ASSERT_TRUE(north.goal) << north.refusal;
  EXPECT_EQ(north.goal->landmark, 3);
  EXPECT_EQ(north.goal->room, "220");
  const RoomGoalResult east = planner.Plan("220@east", std::nullopt);
  EXPECT_FALSE(east.goal);
  EXPECT_TRUE(Contains(east.refusal, "room 220 has no plate on wall 'east'")) << east.refusal;
}

// A building with real identifier formats: "E14-295" and "32-069T" on the north wall, "32-076" and "312A"
// on the south wall, "B/1404" once on each.
TextMap RealFormatsMap() {
  TextMap map;
  map.landmarks = {Plate("E14-295", 3.0, 2.0, -M_PI / 2, "north"), Plate("32-069T", 6.0, 2.0, -M_PI / 2, "north"),
                   Plate("32-076", 6.0, 0.0, M_PI / 2, "south"), Plate("312A", 9.0, 0.0, M_PI / 2, "south"),
                   Plate("B/1404", 12.0, 0.0, M_PI / 2, "south"), Plate("B/1404", 14.0, 2.0, -M_PI / 2, "north")};
  return map;
}

TEST(RoomGoalPlanner, ARoomNumberWithOrWithoutSeparatorsReachesTheSamePlate) {
  const RoomGoalPlanner planner(RoomGoalPlannerOptions{}, RealFormatsMap(), "real.text_map.yaml");
  for (const char* request : {"E14-295", "E14295", "e14 295", " E14:295\n"}) {
    const RoomGoalResult result = planner.Plan(request, std::nullopt);
    ASSERT_TRUE(result.goal) << request << ": " << result.refusal;
    EXPECT_EQ(result.goal->landmark, 0) << request;
  }
  const RoomGoalResult stacked = planner.Plan("32069T", std::nullopt);
  ASSERT_TRUE(stacked.goal) << stacked.refusal;
  EXPECT_EQ(stacked.goal->landmark, 1);
  const RoomGoalResult wall = planner.Plan("B1404@north", std::nullopt);  // a wall suffix still selects one
  ASSERT_TRUE(wall.goal) << wall.refusal;
  EXPECT_EQ(wall.goal->landmark, 5);
}

TEST(RoomGoalPlanner, LookAlikeRoomsStayApart) {
  const RoomGoalPlanner planner(RoomGoalPlannerOptions{}, RealFormatsMap(), "real.text_map.yaml");
  const RoomGoalResult other = planner.Plan("32-076", std::nullopt);
  ASSERT_TRUE(other.goal) << other.refusal;
  EXPECT_EQ(other.goal->landmark, 2);  // not 32-069T
  const RoomGoalResult look_alike = planner.Plan("312B", std::nullopt);
  EXPECT_FALSE(look_alike.goal);
  EXPECT_EQ(look_alike.refusal, "room 312B is not in the text map real.text_map.yaml; known rooms: 312A, 32-069T, "
                                "32-076, B/1404, E14-295");
}

TEST(RoomGoalPlanner, InvalidOptionsNameTheField) {
  RoomGoalPlannerOptions options;
  options.duplicate_rule = "first";
  EXPECT_THROW(
      {
        try {
          RoomGoalPlanner(options, SmallMap(), "small");
        } catch (const std::invalid_argument& e) {
          EXPECT_TRUE(Contains(e.what(), "RoomGoalPlannerOptions.duplicate_rule")) << e.what();
          throw;
        }
      },
      std::invalid_argument);
  options = RoomGoalPlannerOptions{};
  options.wall_distance_m = -1.0;
  EXPECT_THROW(RoomGoalPlanner(options, SmallMap(), "small"), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

// Tests of GoToRoomNodelet's building goal (building_goal.h) on the built-in two-floor hospital
// (maps/hospital_two_floors.building.yaml: floors "2" and "3" of the same layout, lifts A and B in the lobby).
#include "building_goal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

namespace doorplate_localization {
namespace {

bool StartsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

class BuildingGoalTest : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    const std::string path = std::string(DOORPLATE_SOURCE_DIR) + "/maps/hospital_two_floors.building.yaml";
    maps_ = std::make_shared<const BuildingMaps>(LoadBuildingMaps(LoadBuildingFile(path), path));
  }
  // Converged on `floor` (the localizer's messages).
  void Localized(BuildingGoal* goal, const std::string& floor) {
    goal->SetLocalizerFloor(floor);
    goal->SetLocalizerState("converged");
  }
  static std::shared_ptr<const BuildingMaps> maps_;
  const Pose2D in_lobby_{22.0, 27.5, 0.0};  // a free pose in the lift lobby, the same on both floors
};
std::shared_ptr<const BuildingMaps> BuildingGoalTest::maps_;

TEST_F(BuildingGoalTest, ARoomOnNoFloorIsRefusedAtOnce) {
  BuildingGoal goal({}, maps_);
  EXPECT_EQ(goal.Start("999"), "room 999 is on no floor of building hospital_two_floors (floors: 2, 3)");
  EXPECT_EQ(goal.phase(), BuildingGoalPhase::kDone);
  EXPECT_EQ(goal.Status(), "refused: room 999 is on no floor of building hospital_two_floors (floors: 2, 3)");
  EXPECT_FALSE(goal.searching());
}

TEST_F(BuildingGoalTest, SearchesUntilTheLocalizerHasConvergedThenGoesToARoomOnItsFloor) {
  BuildingGoal goal({}, maps_);
  EXPECT_EQ(goal.Start("305"), "");
  EXPECT_TRUE(goal.searching());
  goal.SetLocalizerFloor("2");
  goal.SetLocalizerState("tracking");
  EXPECT_FALSE(goal.TryStartLeg(in_lobby_));
  EXPECT_EQ(goal.Status(),
            "localizing: room 305: searching for plates until the localizer has converged (localizer: floor 2, "
            "tracking)");
  Localized(&goal, "3");
  EXPECT_FALSE(goal.TryStartLeg(std::nullopt)) << "no map pose yet";
  ASSERT_TRUE(goal.TryStartLeg(in_lobby_));
  EXPECT_EQ(goal.phase(), BuildingGoalPhase::kToRoom);
  EXPECT_FALSE(goal.searching());
  EXPECT_EQ(goal.leg_floor(), 1);
  EXPECT_EQ(goal.leg().room, "305");
  EXPECT_EQ(goal.Status(), "to_room: room 305 is on this floor (3)");
  goal.OnLegEnded(true, "arrived: room 305, 0.020 m from the goal, yaw error 0.010 rad");
  EXPECT_EQ(goal.phase(), BuildingGoalPhase::kDone);
  EXPECT_EQ(goal.Status(), "arrived: room 305, 0.020 m from the goal, yaw error 0.010 rad");
}

TEST_F(BuildingGoalTest, ARoomOnAnotherFloorGoesByTheLiftWaitsForTheRideAndSearchesOnTheRoomsFloor) {
  BuildingGoal goal({}, maps_);
  ASSERT_EQ(goal.Start("305"), "");
  Localized(&goal, "2");
  ASSERT_TRUE(goal.TryStartLeg(in_lobby_));
  EXPECT_EQ(goal.phase(), BuildingGoalPhase::kToLift);
  EXPECT_EQ(goal.leg_floor(), 0);
  ASSERT_TRUE(goal.route().has_value());
  const std::string lift = goal.route()->lift;
  EXPECT_EQ(goal.leg().room, "lift " + lift);
  EXPECT_EQ(goal.leg().pose.x_m, goal.route()->lift_stop_here.x_m);
  EXPECT_TRUE(
      StartsWith(goal.Status(), "to_lift: room 305 is on floor 3: take lift " + lift + " from floor 2 to floor 3"))
      << goal.Status();
  std::string problem;
  EXPECT_FALSE(goal.OnRide(lift + " 3", &problem)) << "not at the lift yet";
  EXPECT_EQ(problem, "not waiting for a lift");

  goal.OnLegEnded(true, "arrived: room lift " + lift + ", ...");
  EXPECT_EQ(goal.phase(), BuildingGoalPhase::kWaitingForLift);
  EXPECT_FALSE(goal.searching()) << "the robot waits at the lift";
  EXPECT_EQ(goal.Status(),
            "waiting_for_lift: waiting for lift " + lift + " to floor 3 (room 305) at its stop on floor 2");
  EXPECT_FALSE(goal.OnRide("A", &problem));
  EXPECT_EQ(problem, "expected '<lift id> <floor id>', e.g. 'A 3', got 'A'");
  EXPECT_FALSE(goal.OnRide(lift + " 2", &problem));
  EXPECT_EQ(problem, "room 305 is on floor 3, not 2");
  const std::string other = lift == "A" ? "B" : "A";
  EXPECT_FALSE(goal.OnRide(other + " 3", &problem));
  EXPECT_EQ(problem, "the robot waits for lift " + lift + ", not " + other);
  EXPECT_EQ(goal.phase(), BuildingGoalPhase::kWaitingForLift);

  ASSERT_TRUE(goal.OnRide(lift + " 3", &problem));
  EXPECT_TRUE(goal.searching());
  EXPECT_FALSE(goal.TryStartLeg(in_lobby_)) << "the localizer's converged state from before the ride no longer holds";
  EXPECT_EQ(goal.Status(), "localizing: room 305: rode lift " + lift +
                               " to floor 3; searching for plates until the localizer has converged on floor 3 "
                               "(localizer: floor 2, ?)");
  Localized(&goal, "3");
  ASSERT_TRUE(goal.TryStartLeg(Pose2D{23.0, 28.8, -M_PI / 2}));
  EXPECT_EQ(goal.phase(), BuildingGoalPhase::kToRoom);
  EXPECT_EQ(goal.leg_floor(), 1);
  EXPECT_EQ(goal.leg().room, "305");
}

TEST_F(BuildingGoalTest, ConvergingOnAnotherFloorThanTheLiftWentToFails) {
  BuildingGoal goal({}, maps_);
  ASSERT_EQ(goal.Start("205"), "");
  Localized(&goal, "3");
  ASSERT_TRUE(goal.TryStartLeg(in_lobby_));
  goal.OnLegEnded(true, "arrived");
  std::string problem;
  ASSERT_TRUE(goal.OnRide(goal.route()->lift + " 2", &problem));
  Localized(&goal, "3");
  EXPECT_FALSE(goal.TryStartLeg(in_lobby_));
  EXPECT_EQ(goal.phase(), BuildingGoalPhase::kDone);
  EXPECT_EQ(goal.Status(), "failed: room 205: the localizer converged on floor 3, not on floor 2 where the lift went");
}

TEST_F(BuildingGoalTest, AFailedLegEndsTheGoalWithItsStatusAndCancelIdles) {
  BuildingGoal goal({}, maps_);
  ASSERT_EQ(goal.Start("305"), "");
  Localized(&goal, "2");
  ASSERT_TRUE(goal.TryStartLeg(in_lobby_));
  goal.OnLegEnded(false, "failed: room lift A: blocked for 30 s");
  EXPECT_EQ(goal.phase(), BuildingGoalPhase::kDone);
  EXPECT_EQ(goal.Status(), "failed: room lift A: blocked for 30 s");
  goal.Cancel();
  EXPECT_EQ(goal.Status(), "idle");
  EXPECT_FALSE(goal.searching());
}

}  // namespace
}  // namespace doorplate_localization

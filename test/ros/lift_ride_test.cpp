// Tests of the ride_lift message (lift_ride.h): its parse, and where a ride ends on a tiny two-lift building.
#include "doorplate_localization/ros/lift_ride.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace doorplate_localization {
namespace {

// Floors "2" and "3"; lift A stops on both at (23, 28.8) facing +y, lift C only on floor 2.
BuildingFile TwoFloors() {
  BuildingFile b;
  b.name = "h";
  b.floors = {{"2", "", "", "w2.yaml"}, {"3", "", "", "w3.yaml"}};
  b.lifts = {{"A", {{"2", Pose2D{23.0, 28.8, M_PI / 2}}, {"3", Pose2D{23.0, 28.8, M_PI / 2}}}},
             {"C", {{"2", Pose2D{5.0, 1.0, 0.0}}, {"4", Pose2D{5.0, 1.0, 0.0}}}}};
  return b;
}

TEST(ParseLiftRide, ReadsTheLiftAndTheFloorAndRefusesAnythingElse) {
  LiftRideRequest ride;
  EXPECT_EQ(ParseLiftRide("A 3", &ride), "");
  EXPECT_EQ(ride.lift, "A");
  EXPECT_EQ(ride.floor, "3");
  EXPECT_EQ(ParseLiftRide("  B   B1 ", &ride), "");
  EXPECT_EQ(ride.floor, "B1");
  for (const char* bad : {"", "A", "A 3 now"}) {
    LiftRideRequest untouched = ride;
    EXPECT_EQ(ParseLiftRide(bad, &untouched),
              std::string("expected '<lift id> <floor id>', e.g. 'A 3', got '") + bad + "'");
    EXPECT_EQ(untouched.lift, "B");
  }
}

TEST(PlanLiftRide, EndsAtTheLiftsStopOnTheOtherFloorFacingAwayFromTheDoor) {
  int floor = -1;
  Pose2D pose;
  EXPECT_EQ(PlanLiftRide(TwoFloors(), {"A", "3"}, "2", Pose2D{22.2, 28.0, 0.0}, 1.5, &floor, &pose), "");
  EXPECT_EQ(floor, 1);
  EXPECT_DOUBLE_EQ(pose.x_m, 23.0);
  EXPECT_DOUBLE_EQ(pose.y_m, 28.8);
  EXPECT_NEAR(pose.theta_rad, -M_PI / 2, 1e-12);
}

TEST(PlanLiftRide, RefusesNamingWhatIsWrong) {
  int floor = -1;
  Pose2D pose{1.0, 2.0, 3.0};
  const BuildingFile b = TwoFloors();
  const Pose2D at_a{23.0, 28.0, 0.0};
  EXPECT_EQ(PlanLiftRide(b, {"B", "3"}, "2", at_a, 1.5, &floor, &pose), "no lift 'B' in building h (lifts: A, C)");
  EXPECT_EQ(PlanLiftRide(b, {"A", "9"}, "2", at_a, 1.5, &floor, &pose), "no floor '9' in building h (floors: 2, 3)");
  EXPECT_EQ(PlanLiftRide(b, {"A", "2"}, "2", at_a, 1.5, &floor, &pose), "the robot is on floor 2 already");
  EXPECT_EQ(PlanLiftRide(b, {"C", "3"}, "2", at_a, 1.5, &floor, &pose), "lift C does not stop on floor 3");
  EXPECT_EQ(PlanLiftRide(b, {"A", "3"}, "2", Pose2D{20.0, 28.8, 0.0}, 1.5, &floor, &pose),
            "the robot is 3.00 m from the stop of lift A on floor 2 at (23.00, 28.80); it rides only within 1.50 m");
  EXPECT_EQ(floor, -1);
  EXPECT_DOUBLE_EQ(pose.x_m, 1.0);
}

}  // namespace
}  // namespace doorplate_localization

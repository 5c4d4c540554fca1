#include "doorplate_localization/mcl/building_session.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "mcl_fixtures.h"

namespace doorplate_localization {
namespace {

// Two floors with the same 20 m symmetric corridor: the laser cannot tell them (or the corridor's ends)
// apart. Floor "2" has rooms 2xx, floor "3" the same plates numbered 3xx.
struct TwoFloors {
  test::SymmetricCorridor corridor = test::MakeSymmetricCorridor(20.0);
  std::shared_ptr<BuildingMaps> maps = std::make_shared<BuildingMaps>();

  TwoFloors() {
    for (const char* id : {"2", "3"}) {
      auto text = std::make_shared<TextMap>(*corridor.text_map);
      for (TextLandmark& plate : text->landmarks) plate.text = std::string(id) + plate.text.substr(1);
      maps->floors.push_back({id, corridor.occupancy, text});
    }
  }
  const TextLandmark& Plate(int floor, int index) const { return maps->floors[floor].text_map->landmarks[index]; }

  static BuildingSessionOptions Options() {
    BuildingSessionOptions o;
    o.session.setup.filter.max_particles = 2000;
    o.session.setup.filter.random_seed = 3;
    o.session.start_with_global_localization = true;
    // This periodic corridor pins the pose along it only at plates: between them the cluster spreads to
    // ~0.5 m; the tests are about floors, so a looser convergence test.
    o.session.setup.filter.converged_stddev_m = 0.8;
    o.session.setup.filter.converged_heading_stddev_rad = 0.5;
    return o;
  }
};

// Drives the robot along the corridor's centre line from x0 to x1 (heading +x), scans every 0.2 m, and
// reports each north plate (rooms on the left) as it comes abeam, read as on floor `read_floor`. Odometry
// = the true pose minus (odom_origin_x, 0): the session never sees the map frame.
void Drive(const TwoFloors& b, BuildingSession* session, double x0, double x1, int read_floor, double* t,
           double odom_origin_x = 2.0) {
  for (double x = x0; x <= x1 + 1e-9; x += 0.2) {
    const Pose2D truth{x, 1.0, 0.0};
    const Pose2D odom{x - odom_origin_x, 0.0, 0.0};
    *t += 0.5;
    session->AddScan(*t, odom, test::SyntheticScan(*b.corridor.grid, truth));
    const Pose2D before{x - 0.2, 1.0, 0.0};
    const int plate = test::PlateComingAbeam(*b.maps->floors[read_floor].text_map, before, truth);
    if (plate >= 0 && x > x0) session->AddPlates(*t, {test::ReadingOf(b.Plate(read_floor, plate), truth)});
  }
}

TEST(BuildingSession, FromAnUnknownFloorThePlatesPickTheFloorAndPlaceTheRobotOnIt) {
  const TwoFloors b;
  BuildingSession session(TwoFloors::Options(), b.maps);
  EXPECT_EQ(session.floor(), 0);
  EXPECT_FALSE(session.floor_certain());
  double t = 0.0;
  Drive(b, &session, 2.0, 14.0, /*read_floor=*/1, &t);
  EXPECT_EQ(session.floor_id(), "3");
  EXPECT_TRUE(session.floor_certain());
  EXPECT_EQ(session.floor_switches(), 1);
  const Pose2D estimate = session.PoseAtOdometry({12.0, 0.0, 0.0});
  EXPECT_NEAR(estimate.x_m, 14.0, 0.3);
  EXPECT_NEAR(estimate.y_m, 1.0, 0.3);
  EXPECT_EQ(session.Status().state, LocalizationState::kConverged);
}

// dynamic_reconfigure (issue 19): every floor's session continues with the new options, keeping its
// particles, and the floor, its certainty and the switch count carry over.
TEST(BuildingSession, ContinuedWithNewOptionsEveryFloorKeepsItsParticlesAndTheFloorStays) {
  const TwoFloors b;
  BuildingSession session(TwoFloors::Options(), b.maps);
  double t = 0.0;
  Drive(b, &session, 2.0, 14.0, /*read_floor=*/1, &t);
  ASSERT_EQ(session.floor_id(), "3");
  TextAmclSessionOptions o = TwoFloors::Options().session;
  o.setup.filter.update_min_d_m = 0.5;
  o.setup.likelihood_field.sigma_hit_m = 0.3;
  const BuildingSession continued(session, o);
  EXPECT_EQ(continued.floor_id(), "3");
  EXPECT_TRUE(continued.floor_certain());
  EXPECT_EQ(continued.floor_switches(), 1);
  EXPECT_EQ(continued.session().options().setup.filter.update_min_d_m, 0.5);
  ASSERT_EQ(continued.session().particles().size(), session.session().particles().size());
  EXPECT_EQ(continued.session().particles().front().pose.x_m, session.session().particles().front().pose.x_m);
  EXPECT_EQ(continued.Estimate().pose.x_m, session.Estimate().pose.x_m);
  o.setup.filter.kld_z = -1.0;  // refused as by the first constructor, naming the floor
  EXPECT_THROW(BuildingSession(session, o), std::invalid_argument);
}

TEST(BuildingSession, ConvergedWaitsUntilTheFloorIsCertain) {
  const TwoFloors b;
  BuildingSessionOptions o = TwoFloors::Options();  // floor unknown, but the pose on the first map given
  o.session.start_with_global_localization = false;
  o.session.initial_pose = {2.0, 1.0, 0.0};
  o.session.initial_covariance = Eigen::Vector3d(0.01, 0.01, 0.001).asDiagonal();
  BuildingSession session(o, b.maps);
  double t = 0.0;
  Drive(b, &session, 2.0, 2.6, 0, &t);  // no plate yet: the pose has converged, the floor is unknown
  EXPECT_EQ(session.session().Status().state, LocalizationState::kConverged);
  EXPECT_FALSE(session.floor_certain());
  EXPECT_EQ(session.Status().state, LocalizationState::kTracking);
  Drive(b, &session, 2.8, 14.0, /*read_floor=*/0, &t);  // floor 2's plates on floor 2's map
  EXPECT_EQ(session.floor_switches(), 0);
  EXPECT_TRUE(session.floor_certain());
  EXPECT_EQ(session.Status().state, LocalizationState::kConverged);
  // One reading of floor 3 (a misread, or the first after a lift ride) takes the certainty away, not the map.
  session.AddPlates(t, {test::ReadingOf(b.Plate(1, 7), {14.0, 1.0, 0.0})});
  EXPECT_EQ(session.floor_id(), "2");
  EXPECT_FALSE(session.floor_certain());
  EXPECT_NE(session.Status().state, LocalizationState::kConverged);
}

TEST(BuildingSession, AfterALiftRideThePlatesOfTheNewFloorSwitchTheMapWithoutARestart) {
  const TwoFloors b;
  BuildingSessionOptions o = TwoFloors::Options();
  o.start_floor = "2";
  o.session.start_with_global_localization = false;
  o.session.initial_pose = {2.0, 1.0, 0.0};
  o.session.initial_covariance = Eigen::Vector3d(0.01, 0.01, 0.001).asDiagonal();
  BuildingSession session(o, b.maps);
  EXPECT_TRUE(session.floor_certain());
  double t = 0.0;
  Drive(b, &session, 2.0, 8.0, 0, &t);
  // The lift: the robot is now on floor 3 at x = 2 (odometry did not see the ride) and drives on.
  BuildingSession* s = &session;
  const double odom_offset = 6.0;  // odometry at the ride
  for (double x = 2.0; x <= 16.0 + 1e-9; x += 0.2) {
    const Pose2D truth{x, 1.0, 0.0};
    t += 0.5;
    s->AddScan(t, {odom_offset + x - 2.0, 0.0, 0.0}, test::SyntheticScan(*b.corridor.grid, truth));
    const int plate = test::PlateComingAbeam(*b.maps->floors[1].text_map, {x - 0.2, 1.0, 0.0}, truth);
    if (plate >= 0 && x > 2.0) s->AddPlates(t, {test::ReadingOf(b.Plate(1, plate), truth)});
  }
  EXPECT_EQ(session.floor_id(), "3");
  EXPECT_EQ(session.floor_switches(), 1);
  const Pose2D estimate = session.PoseAtOdometry({odom_offset + 14.0, 0.0, 0.0});
  EXPECT_NEAR(estimate.x_m, 16.0, 0.3);
  EXPECT_NEAR(estimate.y_m, 1.0, 0.3);
}

TEST(BuildingSession, AOneFloorBuildingGivesTheSameEstimatesAsItsTextAmclSession) {
  const TwoFloors b;
  auto one = std::make_shared<BuildingMaps>();
  one->floors.push_back(b.maps->floors[0]);
  const BuildingSessionOptions o = TwoFloors::Options();
  BuildingSession building(o, one);
  TextAmclSession plain(o.session, one->floors[0].grid, one->floors[0].text_map);
  double t = 0.0;
  for (double x = 2.0; x <= 12.0 + 1e-9; x += 0.2) {
    const Pose2D truth{x, 1.0, 0.0};
    t += 0.5;
    const LaserScan scan = test::SyntheticScan(*b.corridor.grid, truth);
    building.AddScan(t, {x, 0.0, 0.0}, scan);
    plain.AddScan(t, {x, 0.0, 0.0}, scan);
    const int plate = test::PlateComingAbeam(*one->floors[0].text_map, {x - 0.2, 1.0, 0.0}, truth);
    if (plate >= 0 && x > 2.0) {
      const PlateReading reading = test::ReadingOf(b.Plate(0, plate), truth);
      building.AddPlates(t, {reading});
      plain.AddPlates(t, {reading});
    }
  }
  EXPECT_TRUE(building.floor_certain());
  EXPECT_EQ(building.Estimate().pose.x_m, plain.Estimate().pose.x_m);
  EXPECT_EQ(building.Estimate().pose.y_m, plain.Estimate().pose.y_m);
  EXPECT_EQ(building.Status().state, plain.Status().state);
}

TEST(BuildingSession, RefusesAnUnknownStartFloorNamingTheFloors) {
  const TwoFloors b;
  BuildingSessionOptions o = TwoFloors::Options();
  o.start_floor = "4";
  try {
    BuildingSession session(o, b.maps);
    FAIL() << "accepted start floor 4";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("start_floor: no floor '4' (floors: 2, 3)"), std::string::npos) << e.what();
  }
  EXPECT_THROW(BuildingSession(TwoFloors::Options(), std::make_shared<BuildingMaps>()), std::invalid_argument);
}

TEST(BuildingSession, AFloorMapTheFilterRefusesIsRefusedAtConstructionNamingTheFloor) {
  TwoFloors b;
  b.maps->floors[1].text_map = std::make_shared<TextMap>();  // no plates: nothing to read on floor 3
  try {
    BuildingSession session(TwoFloors::Options(), b.maps);
    FAIL() << "accepted floor 3 without plates";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("floor '3': ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace doorplate_localization

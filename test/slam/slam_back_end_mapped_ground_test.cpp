// SlamBackEnd's scan budget on mapped ground (SlamBackEndOptions::max_nodes_per_place, place_*): which
// earlier nodes fill a place, and where a node added there without its scan ends up. The rest of the back
// end: slam_back_end_test.cpp.
#include "doorplate_localization/slam/slam_back_end.h"

#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "slam_back_end_test_fixtures.h"
#include "slam_test_worlds.h"

namespace doorplate_localization {
namespace {

using test::PointsAt;
using test::RoomRun;

TEST(SlamBackEnd, APlaceHoldingMaxNodesPerPlaceNamesItsNearestNodeWithPointsAsAnchor) {
  SlamBackEndOptions o;
  o.max_nodes_per_place = 2;
  o.loop_closure_min_separation = 1;  // every earlier node is an earlier visit
  SlamBackEnd back_end(o);
  const auto add = [&](const Pose2D& pose) { return back_end.AddNode(PointsAt(test::Room(), pose), pose, pose); };
  EXPECT_TRUE(add({0, 0, 0}));
  EXPECT_FALSE(back_end.FullPlaceAnchor({0.1, 0, 0}, {0.1, 0, 0}).has_value()) << "one node: room for another";
  EXPECT_TRUE(add({0.3, 0, 0}));
  ASSERT_TRUE(back_end.FullPlaceAnchor({0.25, 0, 0}, {0.25, 0, 0}).has_value());
  EXPECT_EQ(*back_end.FullPlaceAnchor({0.25, 0, 0}, {0.25, 0, 0}), 1);
  EXPECT_EQ(*back_end.FullPlaceAnchor({0.05, 0.1, 0.5}, {0.05, 0.1, 0.5}), 0);
  EXPECT_FALSE(back_end.FullPlaceAnchor({0.15, 0, M_PI}, {0.15, 0, M_PI}).has_value()) << "facing the other way: another place";
  EXPECT_FALSE(back_end.FullPlaceAnchor({0.7, 0, 0}, {0.7, 0, 0}).has_value()) << "only node 1 within place_radius_m";
  EXPECT_FALSE(add({0.2, 0.05, 0.1})) << "a full place: the node keeps no points";
  EXPECT_EQ(back_end.nodes_on_mapped_ground(), 1);
  EXPECT_EQ(back_end.mapped_ground_alignments(), 1);
  EXPECT_EQ(*back_end.FullPlaceAnchor({0.2, 0.05, 0.1}, {0.2, 0.05, 0.1}), 1) << "a node without points is never an anchor";

  SlamBackEndOptions one_visit = o;  // the default separation: nodes of the same visit never fill a place
  one_visit.loop_closure_min_separation = 20;
  SlamBackEnd turning(one_visit);
  for (int i = 0; i < 13; ++i) {
    const Pose2D on_the_spot{0, 0, 0.25 * i};
    EXPECT_TRUE(turning.AddNode(PointsAt(test::Room(), on_the_spot), on_the_spot, on_the_spot));
  }

  o.max_nodes_per_place = 0;  // off
  SlamBackEnd unbounded(o);
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(unbounded.AddNode(PointsAt(test::Room(), {0, 0, 0}), {0, 0, 0}, {0, 0, 0}));
  EXPECT_FALSE(unbounded.FullPlaceAnchor({0, 0, 0}, {0, 0, 0}).has_value());
}

TEST(SlamBackEnd, OnePassWhoseFrontEndPoseStandsStillWhileOdometryDrivesOnFillsNoPlace) {
  SlamBackEndOptions o;
  o.max_nodes_per_place = 2;
  o.loop_closure_min_separation = 2;
  SlamBackEnd back_end(o);
  // A featureless stretch: the front end keeps the pose at x = 0 while odometry drives 0.5 m per node.
  for (int i = 0; i < 6; ++i) {
    EXPECT_TRUE(back_end.AddNode(PointsAt(test::Room(), {0, 0, 0}), {0.5 * i, 0, 0}, {0, 0, 0})) << "node " << i;
  }
  EXPECT_EQ(back_end.nodes_on_mapped_ground(), 0);
  // Back at the start after a lap (odometry 0.2 m off after ~25 m driven): the same place, a second visit.
  back_end.AddNode(PointsAt(test::Room(), {0, 0, 0}), {12.5, 0, 0}, {0, 0, 0});
  const Pose2D lap_done{0.2, 0.1, 0};
  ASSERT_TRUE(back_end.FullPlaceAnchor({0, 0, 0}, lap_done).has_value());
  o.place_max_odometry_displacement_fraction = 0;  // only odometry within place_radius_m is a revisit
  SlamBackEnd strict(o);
  for (int i = 0; i < 6; ++i) strict.AddNode(PointsAt(test::Room(), {0, 0, 0}), {0.5 * i, 0, 0}, {0, 0, 0});
  strict.AddNode(PointsAt(test::Room(), {0, 0, 0}), {12.5, 0, 0}, {0, 0, 0});
  EXPECT_FALSE(strict.FullPlaceAnchor({0, 0, 0}, {5.0, 0, 0}).has_value()) << "the lap came back 5 m off";
  EXPECT_TRUE(strict.FullPlaceAnchor({0, 0, 0}, {2.3, 0, 0}).has_value()) << "within place_radius_m of nodes 4, 5";
}

// The nodelet soak (docs/results/nodelet_soak.md, 2026-12-07): the robot moved without the mapper being told
// (a kidnap) comes back to its places with odometry displaced by the move, which the displacement rule alone
// takes for one pass driving on. A pass after a turn-around is another visit whatever that displacement.
TEST(SlamBackEnd, APassAfterATurnAroundIsAnotherVisitEvenWhenOdometryWasDisplaced) {
  const auto second_pass_anchor = [](double place_turn_around_rad) {
    SlamBackEndOptions o;
    o.max_nodes_per_place = 1;
    o.loop_closure_min_separation = 2;
    o.place_turn_around_rad = place_turn_around_rad;
    SlamBackEnd back_end(o);
    Pose2D odometry_offset;  // odometry = front end until the kidnap
    const auto add = [&](const Pose2D& pose) {
      const Pose2D odometry{pose.x_m + odometry_offset.x_m, pose.y_m, pose.theta_rad};
      back_end.AddNode(PointsAt(test::Room(), pose), odometry, pose);
    };
    for (int i = 0; i <= 6; ++i) add({0.5 * i, 0.0, 0.0});          // out, facing +x
    for (int k = 1; k <= 6; ++k) add({3.0, 0.0, k * M_PI / 6});      // turn round on the spot
    for (int i = 5; i >= 0; --i) add({0.5 * i, 0.0, M_PI});          // back
    odometry_offset.x_m = 20.0;                                      // moved: odometry does not know
    for (int k = 7; k <= 12; ++k) add({0.0, 0.0, k * M_PI / 6});     // turn round again
    return back_end.FullPlaceAnchor({1.0, 0.0, 0.0}, {21.0, 0.0, 0.0});  // out again, at x = 1
  };
  const std::optional<int> anchor = second_pass_anchor(SlamBackEndOptions{}.place_turn_around_rad);
  ASSERT_TRUE(anchor.has_value()) << "the node of the first pass at x = 1 fills the place";
  EXPECT_EQ(*anchor, 2);
  EXPECT_FALSE(second_pass_anchor(0.0).has_value()) << "odometry 20 m off after ~8 m driven: the same pass";
}

TEST(SlamBackEnd, NodesOnMappedGroundArePlacedByTheirAlignmentWithThePlaceNotByTheFrontEnd) {
  SlamBackEndOptions o;
  o.max_nodes_per_place = 1;
  o.loop_closure_min_separation = 1;
  o.place_max_heading_diff_rad = 0.3;  // RoomRun's nodes are each a place of their own
  SlamBackEnd back_end(o);
  const std::vector<Pose2D> truth = RoomRun();
  for (const Pose2D& pose : truth) back_end.AddNode(PointsAt(test::Room(), pose), pose, pose);
  // Back at the first pose; odometry and the front end say 0.1 m further east and 0.05 rad off.
  const Pose2D back{0.05, 0.0, 0.0}, off{0.15, 0.0, 0.05};
  const Pose2D odometry = truth.back().Compose(truth.back().Between(back)).Compose(back.Between(off));
  EXPECT_FALSE(back_end.AddNode(PointsAt(test::Room(), back), odometry, off));
  ASSERT_EQ(back_end.mapped_ground_alignments(), 1);
  const SlamBackEndResult result = back_end.Optimize();
  ASSERT_EQ(result.poses.size(), truth.size() + 1);
  EXPECT_EQ(result.nodes_on_mapped_ground, 1);
  EXPECT_NEAR(result.poses.back().x_m, back.x_m, 0.03);
  EXPECT_NEAR(result.poses.back().theta_rad, back.theta_rad, 0.01);
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/slam/scan_icp.h"

#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "slam_test_worlds.h"

namespace doorplate_localization {
namespace {

constexpr double kMaxRangeM = 16.0;

// The echoes (base_link, beam order) of a 360-beam laser at `pose` in `walls`.
std::vector<Vec2> PointsAt(const std::vector<Segment>& walls, const Pose2D& pose, int beams = 360) {
  return test::Points(test::Scan(walls, pose, beams, kMaxRangeM));
}

// A 2 m wide corridor along x from -100 m to `end_x` m, closed there by an end wall.
std::vector<Segment> ClosedCorridor(double end_x) {
  return {{{-100, -1.025}, {end_x, -1.025}}, {{-100, 1.025}, {end_x, 1.025}}, {{end_x, -1.025}, {end_x, 1.025}}};
}

// Eigen-decomposition of the translational block of an information matrix (ascending eigenvalues).
Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> Translational(const Eigen::Matrix3d& information) {
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(information.topLeftCorner<2, 2>());
}

TEST(ScanIcp, ReferenceNormalsAreAcrossTheWallTheyWereFittedTo) {
  const IcpReference reference(PointsAt(test::Corridor(), {0, 0, 0}), ScanIcpOptions{});
  ASSERT_GT(reference.size(), 50);
  for (int i = 0; i < reference.size(); ++i) {
    EXPECT_NEAR(std::abs(reference.normals()[i].y), 1.0, 1e-6) << "point " << i;
    EXPECT_NEAR(std::abs(reference.points()[i].y), 1.025, 1e-6) << "point " << i;
  }
  // Nearest: the wall point right below a query 0.1 m above the wall, none within 5 cm.
  const int k = reference.Nearest({0.0, 0.925}, 0.3);
  ASSERT_GE(k, 0);
  EXPECT_NEAR(reference.points()[k].x, 0.0, 0.05);
  EXPECT_EQ(reference.Nearest({0.0, 0.5}, 0.05), -1);
}

TEST(ScanIcp, AKnownOffsetInAClosedRoomIsRecovered) {
  const Pose2D offset{0.2, -0.1, 0.05};  // query frame in the reference frame
  const ScanIcpOptions options;
  const IcpReference reference(PointsAt(test::Room(), {0, 0, 0}), options);
  const ScanIcpResult r = AlignScans(reference, PointsAt(test::Room(), offset), {0, 0, 0}, options);
  ASSERT_TRUE(r.aligned);
  EXPECT_NEAR(r.relative.x_m, offset.x_m, 0.01);
  EXPECT_NEAR(r.relative.y_m, offset.y_m, 0.01);
  EXPECT_NEAR(r.relative.theta_rad, offset.theta_rad, 0.005);
  EXPECT_GT(r.inlier_fraction, 0.8);
  EXPECT_LT(r.rms_m, 0.01);
  // A room constrains every direction.
  EXPECT_FALSE(r.degenerate);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(r.information);
  EXPECT_GT(eig.eigenvalues()(0), 0.0);
}

TEST(ScanIcp, AlongAFeaturelessCorridorTheInformationVanishesAndTheGuessIsKept) {
  // Truth: the query scan is 0.3 m ahead, 5 cm left and turned 0.02 rad; the guess is 0.5 m ahead.
  const Pose2D truth{0.3, 0.05, 0.02}, guess{0.5, 0.0, 0.0};
  const ScanIcpOptions options;
  const IcpReference reference(PointsAt(test::Corridor(), {0, 0, 0}), options);
  const ScanIcpResult r = AlignScans(reference, PointsAt(test::Corridor(), truth), guess, options);
  ASSERT_TRUE(r.aligned);
  // Across the corridor and in heading the walls decide; along it nothing does.
  EXPECT_NEAR(r.relative.y_m, truth.y_m, 0.01);
  EXPECT_NEAR(r.relative.theta_rad, truth.theta_rad, 0.005);
  EXPECT_NEAR(r.relative.x_m, guess.x_m, 0.05);
  const auto eig = Translational(r.information);
  EXPECT_GT(std::abs(eig.eigenvectors().col(0).x()), 0.99);  // weakest direction: along x
  EXPECT_LT(eig.eigenvalues()(0), 0.01 * eig.eigenvalues()(1));
  EXPECT_GT(eig.eigenvalues()(1), 100.0);  // across: well known (σ < 10 cm)
}

TEST(ScanIcp, AnEndWallInRangeFixesTheAlongCorridorOffset) {
  // Same corridor and motion, but closed by an end wall 6 m ahead of the reference scan.
  const Pose2D truth{0.3, 0.05, 0.02}, guess{0.5, 0.0, 0.0};
  const ScanIcpOptions options;
  const IcpReference reference(PointsAt(ClosedCorridor(6.0), {0, 0, 0}), options);
  const ScanIcpResult r = AlignScans(reference, PointsAt(ClosedCorridor(6.0), truth), guess, options);
  ASSERT_TRUE(r.aligned);
  EXPECT_NEAR(r.relative.x_m, truth.x_m, 0.01);
  EXPECT_NEAR(r.relative.y_m, truth.y_m, 0.01);
  EXPECT_NEAR(r.relative.theta_rad, truth.theta_rad, 0.005);
  const auto eig = Translational(r.information);
  EXPECT_GT(eig.eigenvalues()(0), 0.03 * eig.eigenvalues()(1));  // ~6%: the wall spans ~20 beams
  EXPECT_GT(r.information(0, 0), 100.0);  // along: σ < 10 cm from one alignment
}

TEST(ScanIcp, TooFewOverlappingPointsAreNotAligned) {
  const ScanIcpOptions options;
  const std::vector<Vec2> room = PointsAt(test::Room(), {0, 0, 0});
  // The reference saw only 2 m of the south wall (~15% of the beams): most of the query has nothing to match.
  std::vector<Vec2> south;
  for (const Vec2& p : room) {
    if (p.y < -1.9 && std::abs(p.x) < 1.0) south.push_back(p);
  }
  ASSERT_GT(south.size(), 20u);
  ASSERT_LT(south.size(), room.size() / 5);
  const ScanIcpResult partial = AlignScans(IcpReference(south, options), room, {0, 0, 0}, options);
  EXPECT_FALSE(partial.aligned);
  EXPECT_LT(partial.inlier_fraction, options.min_inlier_fraction);
  EXPECT_EQ(partial.information, Eigen::Matrix3d::Zero());

  // A guess 10 m off leaves no correspondence at all.
  const IcpReference whole(room, options);
  const ScanIcpResult far = AlignScans(whole, room, {10, 0, 0}, options);
  EXPECT_FALSE(far.aligned);
  EXPECT_EQ(far.inlier_fraction, 0.0);

  // The same scans with the right guess do align (the checks above are about overlap, not the data).
  EXPECT_TRUE(AlignScans(whole, room, {0, 0, 0}, options).aligned);
}

TEST(ScanIcp, AQueryPointWhoseNearestEchoHasNoLineGetsNoCorrespondence) {
  // A wall along y = -1 (a line at every echo) and, 0.2 m above it, a clump of clutter: three echoes in
  // beam order that are too far apart to make a line (each has fewer than 3 neighbours within the gap).
  std::vector<Vec2> points;
  for (int i = 0; i <= 40; ++i) points.push_back({-2.0 + 0.1 * i, -1.0});
  const std::vector<Vec2> clutter = {{0.0, -0.8}, {0.3, -0.5}, {-0.3, -0.5}};
  points.insert(points.end(), clutter.begin(), clutter.end());
  ScanIcpOptions options;
  options.normal_gap_m = 0.15;
  options.normal_gap_per_m = 0.0;
  const IcpReference reference(points, options);
  ASSERT_EQ(reference.size(), 39);  // the clutter and the wall's two ends (one neighbour each) have none
  // Right at the clutter echo: the wall point 0.2 m below it is the nearest point with a line...
  const int k = reference.Nearest({0.0, -0.8}, 0.3);
  ASSERT_GE(k, 0);
  EXPECT_NEAR(reference.points()[k].y, -1.0, 1e-12);
  // ...but the nearest echo is the clutter, which has none: no correspondence.
  EXPECT_EQ(reference.NearestIfLine({0.0, -0.8}, 0.3), -1);
  // Near the wall the nearest echo is a wall point: the same answer as Nearest.
  EXPECT_EQ(reference.NearestIfLine({0.05, -0.95}, 0.3), reference.Nearest({0.05, -0.95}, 0.3));
  EXPECT_EQ(reference.NearestIfLine({0.0, 2.0}, 0.3), -1);  // nothing within reach
}

TEST(ScanIcp, EachReferencePointWeighsOnceHoweverManyQueryPointsItServes) {
  // The query is the reference scan with every east-wall echo (x = 3.025) taken 8 times: a surface seen
  // far more densely than the rest. Shared, each reference point still weighs once, so the information is
  // that of the plain scan; counted, the east wall's x-normals outvote the other walls.
  const std::vector<Vec2> scan = PointsAt(test::Room(), {0, 0, 0}, 180);
  std::vector<Vec2> query;
  for (const Vec2& p : scan) {
    for (int copy = 0; copy < (p.x > 3.0 ? 8 : 1); ++copy) query.push_back(p);
  }
  ASSERT_GT(query.size(), scan.size() + 50);
  ScanIcpOptions shared, counted;
  shared.share_reference_points = true;
  counted.share_reference_points = false;
  const IcpReference reference(scan, shared);
  const ScanIcpResult with_sharing = AlignScans(reference, query, {0, 0, 0}, shared);
  const ScanIcpResult without = AlignScans(reference, query, {0, 0, 0}, counted);
  const ScanIcpResult plain = AlignScans(reference, scan, {0, 0, 0}, counted);  // one query point each
  ASSERT_TRUE(with_sharing.aligned && without.aligned && plain.aligned);
  EXPECT_TRUE(with_sharing.information.isApprox(plain.information, 1e-6))
      << with_sharing.information << "\nvs\n" << plain.information;
  const auto ratio = [](const ScanIcpResult& r) { return r.information(0, 0) / r.information(1, 1); };
  EXPECT_GT(ratio(without), 1.5 * ratio(plain));
  EXPECT_NEAR(with_sharing.relative.x_m, 0.0, 1e-6);
  EXPECT_NEAR(with_sharing.relative.y_m, 0.0, 1e-6);
}

TEST(ScanIcp, AWeakAlongCorridorConstraintIsTreatedAsNone) {
  // A featureless corridor and a small box (a person walking with the robot) 2 m ahead of the robot in
  // both scans: the robot moved 0.3 m, the box too. The box is the only thing that says anything about
  // x, and it says "no motion". Its few echoes are below `degenerate_min_fraction` of the weight: the
  // alignment keeps the guess along the corridor and reports no information there.
  const auto box_at = [](double x) {
    return std::vector<Segment>{{{x, -0.5}, {x + 0.15, -0.5}}, {{x + 0.15, -0.5}, {x + 0.15, -0.35}},
                                {{x + 0.15, -0.35}, {x, -0.35}}, {{x, -0.35}, {x, -0.5}}};
  };
  std::vector<Segment> reference_world = test::Corridor(), query_world = test::Corridor();
  for (const Segment& s : box_at(2.0)) reference_world.push_back(s);
  for (const Segment& s : box_at(2.3)) query_world.push_back(s);
  const Pose2D truth{0.3, 0.0, 0.0};
  ScanIcpOptions degenerate_aware, plain;
  degenerate_aware.degenerate_min_fraction = 0.02;
  plain.degenerate_min_fraction = 0.0;
  const IcpReference reference(PointsAt(reference_world, {0, 0, 0}), plain);
  const std::vector<Vec2> query = PointsAt(query_world, truth);

  const ScanIcpResult kept = AlignScans(reference, query, truth, degenerate_aware);
  ASSERT_TRUE(kept.aligned);
  EXPECT_NEAR(kept.relative.x_m, truth.x_m, 1e-4);   // along: the guess, untouched
  EXPECT_NEAR(kept.relative.y_m, truth.y_m, 0.005);  // across and in heading: the walls
  EXPECT_NEAR(kept.relative.theta_rad, 0.0, 0.002);
  EXPECT_NEAR(kept.information(0, 0), 0.0, 1e-6 * kept.information(1, 1));
  EXPECT_TRUE(kept.degenerate);

  // Without the test the box drags the estimate back towards "no motion", with confidence.
  const ScanIcpResult dragged = AlignScans(reference, query, truth, plain);
  ASSERT_TRUE(dragged.aligned);
  EXPECT_LT(dragged.relative.x_m, truth.x_m - 0.1);
  EXPECT_GT(dragged.information(0, 0), 10.0);  // σ < 0.3 m claimed
}

}  // namespace
}  // namespace doorplate_localization

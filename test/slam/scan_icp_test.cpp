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

}  // namespace
}  // namespace doorplate_localization

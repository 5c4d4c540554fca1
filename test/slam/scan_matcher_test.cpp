#include "doorplate_localization/slam/scan_matcher.h"

#include <cmath>

#include <gtest/gtest.h>

#include "slam_test_worlds.h"

namespace doorplate_localization {
namespace {

using test::Corridor;
using test::MapFrom;
using test::Points;
using test::Room;
using test::Scan;

double Distance(const Pose2D& a, const Pose2D& b) { return std::hypot(a.x_m - b.x_m, a.y_m - b.y_m); }
double AngleBetween(const Pose2D& a, const Pose2D& b) { return std::abs(NormalizeAngle(a.theta_rad - b.theta_rad)); }

TEST(ScanMatcher, RecoversAKnownOffsetInARoom) {
  const TiledGrid map = MapFrom(Room(), {{-1, -0.5, 0}, {0.5, -1, 1.0}, {-2, 1, -0.5}});
  const ScanMatcher matcher(ScanMatcherOptions{}, TiledGridOptions{});
  const Pose2D truth{0.2, 0.1, 0.3};
  const Pose2D guess{truth.x_m + 0.15, truth.y_m - 0.1, truth.theta_rad + 0.08};
  const MatchResult r = matcher.Match(map, Points(Scan(Room(), truth)), guess, {0.3, 0.2}, guess, {0.3, 0.3});
  EXPECT_EQ(r.status, MatchResult::Status::kMatched);
  EXPECT_LT(Distance(r.pose, truth), 0.01);
  EXPECT_LT(AngleBetween(r.pose, truth), 0.005);
  EXPECT_GT(r.matched_fraction, 0.9);
}

TEST(ScanMatcher, ScoreAndLikelihoodPeakAtTheTruePose) {
  const TiledGrid map = MapFrom(Room(), {{-1, -0.5, 0}, {0.5, -1, 1.0}});
  const ScanMatcher matcher(ScanMatcherOptions{}, TiledGridOptions{});
  const Pose2D truth{0.0, 0.0, 0.0};
  const std::vector<Vec2> points = Points(Scan(Room(), truth));
  const Pose2D off{0.1, 0.0, 0.0};
  EXPECT_GT(matcher.Score(map, points, truth), matcher.Score(map, points, off));
  EXPECT_GT(matcher.LogLikelihood(map, points, truth), matcher.LogLikelihood(map, points, off));
}

TEST(ScanMatcher, InACorridorKeepsTheOdometryAlongItAndCorrectsAcrossIt) {
  const TiledGrid map = MapFrom(Corridor(), test::PosesAlongX(-4, 4, 0.05));
  const ScanMatcher matcher(ScanMatcherOptions{}, TiledGridOptions{});
  const Pose2D truth{0.0, 0.0, 0.0};
  const Pose2D prior{0.25, 0.12, 0.04};  // odometry: 25 cm along, 12 cm across, 0.04 rad off
  const MatchResult r = matcher.Match(map, Points(Scan(Corridor(), truth)), prior, {0.3, 0.1}, prior, {0.15, 0.05});
  EXPECT_EQ(r.status, MatchResult::Status::kMatched);
  EXPECT_NEAR(r.pose.x_m, prior.x_m, 0.02);      // along: nothing to match, the prior stays
  EXPECT_NEAR(r.pose.y_m, truth.y_m, 0.02);      // across: the walls correct it
  EXPECT_NEAR(r.pose.theta_rad, truth.theta_rad, 0.01);
}

TEST(ScanMatcher, AWeakMatchKeepsThePrior) {
  const TiledGrid empty{TiledGridOptions{}};
  const ScanMatcher matcher(ScanMatcherOptions{}, TiledGridOptions{});
  const Pose2D prior{1, 2, 0.3};
  const MatchResult r = matcher.Match(empty, Points(Scan(Room(), {0, 0, 0})), prior, {0.2, 0.1}, prior, {0.1, 0.1});
  EXPECT_EQ(r.status, MatchResult::Status::kWeak);
  EXPECT_EQ(r.pose.x_m, prior.x_m);
  EXPECT_EQ(r.pose.theta_rad, prior.theta_rad);
  EXPECT_EQ(r.matched_fraction, 0.0);
}

TEST(ScanMatcher, AResultFarOutsideTheSearchedWindowIsRejectedAsAJump) {
  const TiledGrid map = MapFrom(Room(), {{-1, -0.5, 0}, {0.5, -1, 1.0}});
  ScanMatcherOptions options;
  options.jump_guard_margin_m = 0.0;
  options.jump_guard_margin_rad = 0.0;
  const ScanMatcher matcher(options, TiledGridOptions{});
  const Pose2D truth{0.0, 0.0, 0.0};
  const Pose2D prior{0.25, 0.0, 0.0};
  // The hill climb leaves the 5 cm window to reach the truth 25 cm away: a jump.
  const MatchResult r = matcher.Match(map, Points(Scan(Room(), truth)), prior, {0.05, 0.01}, prior, {1.0, 1.0});
  EXPECT_EQ(r.status, MatchResult::Status::kRejectedJump);
  EXPECT_EQ(r.pose.x_m, prior.x_m);
}

TEST(ScanMatcher, WindowsScaleWithTheMotionSpreadWithinLimits) {
  ScanMatcherOptions options;
  const ScanMatcher matcher(options, TiledGridOptions{});
  EXPECT_NEAR(matcher.WideWindow({0.05, 0.02}).linear_m, options.search_sigmas * 0.05, 1e-12);
  EXPECT_NEAR(matcher.WideWindow({0.0, 0.0}).linear_m, options.min_search_linear_m, 1e-12);
  EXPECT_NEAR(matcher.WideWindow({10.0, 10.0}).angular_rad, options.max_search_angular_rad, 1e-12);
  EXPECT_NEAR(matcher.NarrowWindow().angular_rad, options.min_search_angular_rad, 1e-12);
}

}  // namespace
}  // namespace doorplate_localization

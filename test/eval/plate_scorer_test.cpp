#include "plate_scorer.h"

#include <gtest/gtest.h>

#include "eval_test_worlds.h"

namespace doorplate_localization {
namespace {

// 10 m × 2 m; "201" at x = 3 and "203" at x = 6 on the north wall, "202" at x = 3 on the south wall.
// The default camera looks left (+y when the robot faces +x), 640 px wide, principal point column 320.
class PlateScorerTest : public ::testing::Test {
 protected:
  PlateScorerTest()
      : world_(test::CorridorWithPlates(10.0, 2.0, {{1, 3.0, "201"}, {1, 6.0, "203"}, {0, 3.0, "202"}})),
        camera_(world_, world_.sensors.camera),
        scorer_(world_, camera_) {}

  // A report with a 60 × 24 px box centred on plate `index`'s projection at `pose`, shifted by (dx, dy).
  PlateReport ReportOn(int index, const Pose2D& pose, const std::string& text, int dx = 0, int dy = 0) const {
    cv::Point2d px;
    EXPECT_TRUE(scorer_.Visible(index, pose, &px));
    PlateReport report;
    report.text = text;
    report.box_px = cv::Rect(static_cast<int>(px.x) - 30 + dx, static_cast<int>(px.y) - 12 + dy, 60, 24);
    return report;
  }

  void DrivePast(double from_x, double to_x, bool on_leg = true) {
    for (double x = from_x; x <= to_x; x += 0.05) scorer_.ObserveFrame({x, 0.6, 0.0}, on_leg);
  }

  World world_;
  CameraRenderer camera_;
  PlateScorer scorer_;
};

TEST_F(PlateScorerTest, ListsThePlatesWithTheirPositions) {
  ASSERT_EQ(scorer_.plates().size(), 3u);
  EXPECT_EQ(scorer_.plates()[0].text, "201");
  EXPECT_NEAR(scorer_.plates()[0].position.x, 3.0, 1e-9);
  EXPECT_NEAR(scorer_.plates()[0].position.y, 2.0, 1e-9);
  EXPECT_NEAR(scorer_.plates()[0].facing.y, -1.0, 1e-9);
}

TEST_F(PlateScorerTest, OnlyPlatesOnTheWallInFrontOfTheCameraAreVisible) {
  const Pose2D pose{3.0, 0.6, 0.0};
  cv::Point2d px;
  ASSERT_TRUE(scorer_.Visible(0, pose, &px));
  EXPECT_NEAR(px.x, 320.0, 1.0);           // abeam: on the centre column
  EXPECT_FALSE(scorer_.Visible(1, pose, nullptr));  // 3 m further along: outside the 60° view
  EXPECT_FALSE(scorer_.Visible(2, pose, nullptr));  // behind the camera
  EXPECT_TRUE(scorer_.Visible(2, {3.0, 1.4, M_PI}, nullptr));  // turned around: the south plate
  EXPECT_EQ(scorer_.CountVisible(pose), 1);
}

TEST_F(PlateScorerTest, APlateHiddenBehindAWallIsNotVisible) {
  World world = world_;
  world.walls.push_back({"screen", {{2.5, 1.5}, {3.5, 1.5}}, true, {200, 200, 200}});
  world.surfaces.clear();
  BuildSurfaces(world);
  const CameraRenderer camera(world, world.sensors.camera);
  const PlateScorer scorer(world, camera);
  EXPECT_FALSE(scorer.Visible(0, {3.0, 0.6, 0.0}, nullptr));
}

TEST_F(PlateScorerTest, APlateIsPassedWhenItCrossesTheCentreColumnOnALeg) {
  DrivePast(0.7, 2.5);
  EXPECT_FALSE(scorer_.pass().plates[0].passed);  // in view, not yet across the centre
  DrivePast(2.55, 4.0, /*on_leg=*/false);
  EXPECT_FALSE(scorer_.pass().plates[0].passed);  // crossed while turning: does not count
  scorer_.BeginPass();
  DrivePast(2.5, 4.0);
  EXPECT_TRUE(scorer_.pass().plates[0].passed);
  EXPECT_FALSE(scorer_.pass().plates[1].passed);
  EXPECT_EQ(scorer_.pass().plates_passed, 1);
}

TEST_F(PlateScorerTest, MatchesABoxToThePlateInsideItOrTheNearestWithinHalfABoxWidthPlusItsHeight) {
  const Pose2D pose{3.2, 0.6, 0.0};
  EXPECT_EQ(scorer_.MatchBox(ReportOn(0, pose, "201").box_px, pose), 0);
  EXPECT_EQ(scorer_.MatchBox(ReportOn(0, pose, "201", 0, 25).box_px, pose), 0);  // outside, 25 px <= 54 from centre
  EXPECT_EQ(scorer_.MatchBox(ReportOn(0, pose, "201", 45).box_px, pose), 0);     // a fragment: 45 px <= 30 + 24
  EXPECT_EQ(scorer_.MatchBox(ReportOn(0, pose, "201", 60).box_px, pose), -1);    // outside, 60 px > 54 from centre
  EXPECT_EQ(scorer_.MatchBox(cv::Rect(500, 20, 60, 24), pose), -1);              // nothing there
}

TEST_F(PlateScorerTest, CountsCorrectFalseSpuriousAndDuplicateReports) {
  const Pose2D pose{3.0, 0.6, 0.0};
  DrivePast(2.5, 3.2);  // passes "201"
  EXPECT_EQ(scorer_.ScoreReport(ReportOn(0, pose, "201"), pose).kind, ReportKind::kCorrect);
  const ReportVerdict wrong = scorer_.ScoreReport(ReportOn(0, pose, "207"), pose);
  EXPECT_EQ(wrong.kind, ReportKind::kFalseRead);
  EXPECT_TRUE(wrong.duplicate);
  PlateReport nowhere;
  nowhere.text = "201";
  nowhere.box_px = cv::Rect(20, 400, 60, 24);
  EXPECT_EQ(scorer_.ScoreReport(nowhere, pose).kind, ReportKind::kSpurious);
  const PassScore& s = scorer_.pass();
  EXPECT_EQ(s.plates_passed, 1);
  EXPECT_EQ(s.plates_correct, 1);
  EXPECT_EQ(s.false_reads, 1);
  EXPECT_EQ(s.spurious, 1);
  EXPECT_EQ(s.duplicates, 1);
  EXPECT_EQ(s.reports, 3);
  EXPECT_EQ(s.plates[0].reported_texts, (std::vector<std::string>{"201", "207"}));
}

TEST_F(PlateScorerTest, ACorrectReportBeforeThePlateIsPassedCountsOnceItIsPassed) {
  const Pose2D pose{2.9, 0.6, 0.0};
  scorer_.ScoreReport(ReportOn(0, pose, "201"), pose);
  EXPECT_EQ(scorer_.pass().plates_correct, 0);  // not passed yet
  DrivePast(2.9, 3.5);
  EXPECT_EQ(scorer_.pass().plates_correct, 1);
}

}  // namespace
}  // namespace doorplate_localization

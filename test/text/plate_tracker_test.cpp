#include "doorplate_localization/text/plate_tracker.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

constexpr double kFrameS = 0.1;

PlateObservation At(int center_x, const std::string& text = "214", double confidence = 0.9, int y = 210) {
  return PlateObservation{cv::Rect(center_x - 30, y, 60, 30), text, confidence, text};
}

// Feeds one box per frame at the given centres; returns every report.
std::vector<PlateReport> Drive(PlateTracker& tracker, const std::vector<int>& centers_x, double t0 = 0.0) {
  std::vector<PlateReport> all;
  double t = t0;
  for (const int x : centers_x) {
    for (const PlateReport& r : tracker.Update({At(x)}, t)) all.push_back(r);
    t += kFrameS;
  }
  return all;
}

// Feeds one box per frame at (centre x, reading) with confidence 0.5; returns every report.
std::vector<PlateReport> DriveReading(PlateTracker& tracker, const std::vector<std::pair<int, std::string>>& frames) {
  std::vector<PlateReport> reports;
  double t = 0.0;
  for (const auto& [x, text] : frames) {
    for (const auto& r : tracker.Update({At(x, text, 0.5)}, t)) reports.push_back(r);
    t += kFrameS;
  }
  return reports;
}

std::vector<int> Steps(int from, int to, int step) {
  std::vector<int> xs;
  for (int x = from; step > 0 ? x <= to : x >= to; x += step) xs.push_back(x);
  return xs;
}

TEST(PlateTracker, ReportsOnceWhenTheBoxCrossesTheCentreRightToLeft) {
  PlateTracker tracker({});
  std::vector<PlateReport> reports = Drive(tracker, Steps(560, 60, -40));
  // The box stays in view after the crossing and must not be reported again.
  ASSERT_EQ(reports.size(), 1u);
  const PlateReport& r = reports[0];
  EXPECT_EQ(r.text, "214");
  EXPECT_DOUBLE_EQ(r.vote_share, 1.0);
  EXPECT_NEAR(r.mean_confidence, 0.9, 1e-9);
  EXPECT_NEAR(r.confidence, 0.9, 1e-9);
  EXPECT_EQ(r.box_px.x + r.box_px.width / 2, 280);  // first centre left of cx = 320
  EXPECT_EQ(r.voted_frame_count, 8);                 // 560, 520, ..., 280
  EXPECT_EQ(r.observed_frame_count, 8);
  EXPECT_NEAR(r.stamp_s, 7 * kFrameS, 1e-9);
  EXPECT_NEAR(r.bearing_rad, std::atan(40.0 / 554.2562584220407), 1e-9);
  EXPECT_GT(r.bearing_rad, 0.0);  // left of the image centre
}

TEST(PlateTracker, CrossingLeftToRightGivesANegativeBearing) {
  PlateTracker tracker({});
  const std::vector<PlateReport> reports = Drive(tracker, Steps(100, 500, 45));
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_LT(reports[0].bearing_rad, 0.0);
}

TEST(PlateTracker, NeverReportsABoxThatDoesNotCrossTheCentre) {
  PlateTracker tracker({});
  EXPECT_TRUE(Drive(tracker, Steps(600, 380, -20)).empty());
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(tracker.Update({}, 2.0 + i * kFrameS).empty());
  EXPECT_EQ(tracker.num_tracks(), 0u);  // the vanished track was dropped without a report
}

TEST(PlateTracker, TheMajorityOfConfidenceWeightedVotesWins) {
  PlateTracker tracker({});
  const std::vector<std::pair<int, std::string>> frames = {
      {500, "214"}, {460, "274"}, {420, "214"}, {380, "214"}, {340, "274"}, {300, "214"}};
  const std::vector<PlateReport> reports = DriveReading(tracker, frames);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].text, "214");
  EXPECT_NEAR(reports[0].vote_share, 4.0 / 6.0, 1e-9);
  EXPECT_NEAR(reports[0].confidence, 0.5 * 4.0 / 6.0, 1e-9);
}

TEST(PlateTracker, SpellingsOfOneRoomVoteTogetherAndTheCommonestSpellingIsReported) {
  PlateTracker tracker({});
  // E14-295 in three spellings (4 frames) against a look-alike E14-296 (2 frames, more than any spelling).
  const std::vector<std::pair<int, std::string>> frames = {
      {500, "E14296"}, {460, "E14-295"}, {420, "E14295"}, {380, "E14-296"}, {340, "E14-295"}, {300, "E14:295"}};
  const std::vector<PlateReport> reports = DriveReading(tracker, frames);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].text, "E14-295");
  EXPECT_NEAR(reports[0].vote_share, 4.0 / 6.0, 1e-9);
  EXPECT_NEAR(reports[0].mean_confidence, 0.5, 1e-9);
}

TEST(PlateTracker, BoxesWithoutAValidReadingAreTrackedButDoNotVote) {
  PlateTracker tracker({});
  std::vector<PlateReport> reports;
  const std::vector<std::pair<int, std::string>> frames = {
      {440, ""}, {400, "214"}, {360, ""}, {320 - 20, ""}, {260, "214"}, {220, ""}};
  double t = 0.0;
  for (const auto& [x, text] : frames) {
    for (const auto& r : tracker.Update({At(x, text, 0.8)}, t)) reports.push_back(r);
    t += kFrameS;
  }
  // Crossed at 300 with one vote (min_voted_frames = 2); reported at 260 with the second.
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].voted_frame_count, 2);
  EXPECT_EQ(reports[0].observed_frame_count, 5);
  EXPECT_EQ(reports[0].box_px.x + reports[0].box_px.width / 2, 260);
}

TEST(PlateTracker, ACrossedTrackThatVanishesBeforeEnoughReadingsIsNotReported) {
  PlateTracker tracker({});
  std::vector<PlateReport> reports;
  const std::vector<std::pair<int, std::string>> frames = {{400, ""}, {360, ""}, {300, "214"}, {260, ""}};
  double t = 0.0;
  for (const auto& [x, text] : frames) {
    for (const auto& r : tracker.Update({At(x, text)}, t)) reports.push_back(r);
    t += kFrameS;
  }
  for (int i = 0; i < 4; ++i, t += kFrameS) {
    for (const auto& r : tracker.Update({}, t)) reports.push_back(r);
  }
  EXPECT_TRUE(reports.empty());
  EXPECT_EQ(tracker.num_tracks(), 0u);
}

TEST(PlateTracker, FollowsTwoPlatesSeparately) {
  PlateTracker tracker({});
  std::vector<std::string> texts;
  double t = 0.0;
  for (int x = 400; x >= 30; x -= 30, t += kFrameS) {
    for (const auto& r : tracker.Update({At(x, "214"), At(x + 250, "216")}, t)) texts.push_back(r.text);
  }
  EXPECT_EQ(texts, (std::vector<std::string>{"214", "216"}));
}

TEST(PlateTracker, DoesNotAssociateBoxesFarApartOrAtAnotherHeight) {
  PlateTracker tracker({});
  tracker.Update({At(400)}, 0.0);
  tracker.Update({At(400 - 200)}, 0.1);  // jump larger than max_center_jump_px: a new track
  EXPECT_EQ(tracker.num_tracks(), 2u);
  PlateTracker tracker2({});
  tracker2.Update({At(400)}, 0.0);
  tracker2.Update({At(380, "214", 0.9, 300)}, 0.1);  // another row of the image
  EXPECT_EQ(tracker2.num_tracks(), 2u);
}

TEST(PlateTracker, AStampGoingBackwardsResetsTheTracks) {
  PlateTracker tracker({});
  EXPECT_TRUE(Drive(tracker, {500, 460, 420}, 10.0).empty());
  // Simulator restarted at t = 0: the old track's votes must not carry over.
  const std::vector<PlateReport> reports = Drive(tracker, {380, 340, 300}, 0.0);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].voted_frame_count, 3);
}

// A robot stopped with a plate abeam: its box jitters about the centre line, and is lost for more than
// max_missed_frames frames now and then (frames without a detection), so new tracks keep crossing.
std::vector<PlateReport> StandBeforeAPlate(PlateTracker& tracker, double seconds, double* t) {
  std::vector<PlateReport> all;
  for (int frame = 0; *t < seconds; ++frame, *t += kFrameS) {
    const bool lost = frame % 10 >= 6;  // 4 frames in 10 without a box
    const std::vector<PlateObservation> boxes =
        lost ? std::vector<PlateObservation>{} : std::vector<PlateObservation>{At(frame % 2 ? 330 : 310)};
    for (const PlateReport& r : tracker.Update(boxes, *t)) all.push_back(r);
  }
  return all;
}

TEST(PlateTracker, ARobotStandingBeforeAPlateWhoseBoxIsLostAndFoundReportsItOnce) {
  PlateTracker tracker({});
  double t = 0.0;
  EXPECT_EQ(StandBeforeAPlate(tracker, 20.0, &t).size(), 1u);
  PlateTrackerOptions off;
  off.min_reread_gap_s = 0.0;
  PlateTracker every_track(off);
  t = 0.0;
  EXPECT_GT(StandBeforeAPlate(every_track, 20.0, &t).size(), 5u);  // each new track crossed the line
}

TEST(PlateTracker, APlatePassedAgainAfterTheRereadGapIsReportedAgain) {
  PlateTracker tracker({});
  EXPECT_EQ(Drive(tracker, Steps(560, 60, -40), 0.0).size(), 1u);
  // Out of view for 3 s (> min_reread_gap_s), then passed the other way: a new pass, a new report.
  EXPECT_EQ(Drive(tracker, Steps(60, 560, 40), 4.5).size(), 1u);
  // Lost for 4 frames (its track dropped), back within 1 s of the last sighting: the same pass.
  for (double t = 5.8; t < 6.2; t += kFrameS) EXPECT_TRUE(tracker.Update({}, t).empty());
  EXPECT_EQ(tracker.num_tracks(), 0u);
  EXPECT_TRUE(Drive(tracker, Steps(560, 60, -40), 6.3).empty());
}

TEST(PlateTracker, BearingIsPositiveLeftOfThePrincipalPoint) {
  PlateTrackerOptions options;
  options.fx_px = 500.0;
  options.cx_px = 300.0;
  const PlateTracker tracker(options);
  EXPECT_NEAR(tracker.BearingRad(300.0 - 500.0), M_PI / 4.0, 1e-12);
  EXPECT_NEAR(tracker.BearingRad(800.0), -M_PI / 4.0, 1e-12);
}

TEST(PlateTracker, RejectsANonPositiveFocalLengthNamingTheField) {
  PlateTrackerOptions options;
  options.fx_px = 0.0;
  try {
    PlateTracker tracker(options);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("fx_px"), std::string::npos);
  }
}

// Drives one plate past the camera, reading only the boxes PlanReadings asks for; returns how many
// boxes were read and every report.
int DriveWithSchedule(PlateTracker& tracker, const std::vector<int>& centers_x,
                      std::vector<PlateReport>* reports, const std::string& text = "214") {
  int reads = 0;
  double t = 0.0;
  for (const int x : centers_x) {
    PlateObservation o = At(x, text);
    if (!tracker.PlanReadings({o.box_px}, t).at(0)) {
      o.text = o.raw_text = "";
      o.confidence = 0.0;
      o.read_attempted = false;
    } else {
      ++reads;
    }
    for (const PlateReport& r : tracker.Update({o}, t)) reports->push_back(r);
    t += kFrameS;
  }
  return reads;
}

TEST(PlateTracker, TheDefaultScheduleReadsEveryFrameUntilThePlateIsReported) {
  PlateTracker tracker({});
  std::vector<PlateReport> reports;
  // 13 frames; the crossing (320 → 280) is the 8th, after which the reported plate is not read again.
  EXPECT_EQ(DriveWithSchedule(tracker, Steps(560, 60, -40), &reports), 8);
  EXPECT_EQ(reports.size(), 1u);
}

TEST(PlateTracker, ASlowRecognisersScheduleReadsAPlateAFewTimesAndStillReportsIt) {
  PlateTrackerOptions options;
  options.read_every_n_frames = 2;
  options.enough_votes = 3;
  PlateTracker tracker(options);
  std::vector<PlateReport> reports;
  // Frames 1, 3, 5 are read; three agreeing votes are enough: no more reads though 13 frames pass.
  EXPECT_EQ(DriveWithSchedule(tracker, Steps(560, 60, -40), &reports), 3);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].text, "214");
  EXPECT_EQ(reports[0].voted_frame_count, 3);
  EXPECT_EQ(reports[0].observed_frame_count, 8);  // reported at the crossing, the 8th frame
}

TEST(PlateTracker, AnUnreadableBoxIsTriedAtMostMaxReadingsPerTrackTimes) {
  PlateTrackerOptions options;
  options.max_readings_per_track = 4;
  PlateTracker tracker(options);
  std::vector<PlateReport> reports;
  EXPECT_EQ(DriveWithSchedule(tracker, Steps(560, 60, -40), &reports, ""), 4);
  EXPECT_TRUE(reports.empty());
}

TEST(PlateTracker, PlanningDoesNotChangeTheTracker) {
  PlateTracker tracker({});
  tracker.Update({At(500)}, 0.0);
  const std::vector<bool> plan = tracker.PlanReadings({At(460).box_px, At(100, "", 0.0, 400).box_px}, 0.1);
  EXPECT_EQ(plan, std::vector<bool>({true, true}));
  EXPECT_EQ(tracker.num_tracks(), 1u);
}

TEST(PlateTracker, RefusesANegativeRereadGapNamingTheField) {
  PlateTrackerOptions options;
  options.min_reread_gap_s = -1.0;
  EXPECT_THROW(
      {
        try {
          PlateTracker tracker(options);
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("min_reread_gap_s"), std::string::npos) << e.what();
          throw;
        }
      },
      std::invalid_argument);
}

TEST(PlateTracker, RefusesABadScheduleNamingTheField) {
  PlateTrackerOptions options;
  options.read_every_n_frames = 0;
  try {
    PlateTracker tracker(options);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("read_every_n_frames"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace doorplate_localization

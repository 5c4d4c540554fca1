// Smoke test of the text-reading experiment: one sweep of a tiny corridor with Tesseract in the loop.
#include "ocr_eval.h"

#include <gtest/gtest.h>

#include <string>

#include "eval_test_worlds.h"

namespace doorplate_localization {
namespace {

// 6 m × 2 m: two plates on the north wall (read on the way out), one on the south wall (on the way back).
// The camera runs at 15 Hz to keep the test short (the tracker needs two readings a plate).
World ThreePlateCorridor() {
  World world = test::CorridorWithPlates(6.0, 2.0, {{1, 2.0, "201"}, {1, 4.0, "203"}, {0, 3.0, "204"}});
  world.sensors.camera.rate_hz = 15.0;
  return world;
}

OcrEvalOptions OnePass() {
  OcrEvalOptions options;
  options.passes = 1;
  options.seed = 5;
  options.speed_mps = 0.5;
  options.detector_every_n_frames = 20;
  options.max_pass_time_s = 120.0;
  return options;
}

TEST(OcrEval, ReadsEveryPlateOfATinyCorridorOnceWithoutFalseReadsAndTellsItsProgress) {
  OcrEvalOptions options = OnePass();
  options.progress_every_s = 5.0;  // simulated seconds; stderr is a file here: plain lines
  testing::internal::CaptureStderr();
  const OcrEvalResult result = RunOcrEval(ThreePlateCorridor(), options);
  const std::string progress = testing::internal::GetCapturedStderr();
  EXPECT_NE(progress.find("ocr: pass 1/1, 5 s simulated, "), std::string::npos) << progress;
  EXPECT_NE(progress.find(" plates passed, "), std::string::npos) << progress;
  ASSERT_EQ(result.passes.size(), 1u);
  const OcrPassResult& pass = result.passes[0];
  EXPECT_TRUE(pass.sweep_done);
  EXPECT_EQ(pass.score.plates_passed, 3);
  EXPECT_EQ(pass.score.plates_correct, 3);
  EXPECT_EQ(pass.score.false_reads, 0);
  EXPECT_EQ(pass.score.spurious, 0);
  EXPECT_EQ(pass.score.duplicates, 0);
  EXPECT_EQ(pass.score.reports, 3);
  EXPECT_TRUE(result.events.empty());
  EXPECT_GT(pass.frames, 15 * 20);  // ~5 m out and back at ≤ 0.5 m/s and the turn, camera at 15 Hz
  // Figure 12: the three detector modes ran on every 20th frame; the band sees fewest boxes.
  ASSERT_EQ(result.detectors.size(), 3u);
  EXPECT_EQ(result.detectors[0].frames, (pass.frames + 19) / 20);
  EXPECT_GT(result.detectors[2].frames_plate_in_view, 0);
  EXPECT_LE(result.detectors[2].boxes, result.detectors[1].boxes);
  EXPECT_LE(result.detectors[1].boxes, result.detectors[0].boxes);
}

TEST(OcrEval, APlateWhoseReadingsAreAllRejectedIsReportedAsMissed) {
  // A known-room list without "201" but with three rooms one edit away from it (207, 203, 204): the
  // validator drops every "201" reading as ambiguous, so that plate is passed but never read.
  OcrEvalOptions options = OnePass();
  options.detector_every_n_frames = 0;
  options.extractor.validator.known_rooms = {"207", "203", "204"};
  const OcrEvalResult result = RunOcrEval(ThreePlateCorridor(), options);
  const PassScore& score = result.passes[0].score;
  EXPECT_EQ(score.plates_passed, 3);
  EXPECT_EQ(score.plates_correct, 2);
  EXPECT_TRUE(score.plates[0].passed);
  EXPECT_EQ(score.plates[0].correct_reports, 0);
  EXPECT_EQ(score.false_reads, 0);
  ASSERT_EQ(result.events.size(), 1u);
  EXPECT_EQ(result.events[0].kind, "missed");
  EXPECT_EQ(result.events[0].truth, "201");
}

}  // namespace
}  // namespace doorplate_localization

#include "ocr_eval_json.h"

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

// Two passes over two plates: pass 0 reads both, pass 1 misreads "202" as "207" and reads a poster.
OcrEvalResult TwoPassResult() {
  OcrEvalResult r;
  r.world_name = "w";
  r.plates = {{"201", "n1", {1, 2}, 1.6, {0, -1}}, {"202", "s1", {3, 0}, 1.6, {0, 1}}};
  for (int pass = 0; pass < 2; ++pass) {
    OcrPassResult p;
    p.seed = 10 + pass;
    p.frames = 100;
    p.sweep_done = true;
    p.score.plates_passed = 2;
    p.score.plates_correct = pass == 0 ? 2 : 1;
    p.score.false_reads = pass;
    p.score.spurious = pass;
    p.score.reports = pass == 0 ? 2 : 4;
    p.score.plates = {{true, 1, {"201"}}, {true, pass == 0 ? 1 : 0, {pass == 0 ? "202" : "207"}}};
    r.passes.push_back(p);
  }
  r.events.push_back({"false_read", 1, 12.5, "207", "202", "s1", cv::Rect(1, 2, 3, 4), ""});
  DetectorModeStats band;
  band.name = "mser_nms_band";
  band.frames = 10;
  band.frames_plate_in_view = 4;
  band.boxes = 5;
  band.boxes_plate_in_view = 4;
  band.seconds = 0.05;
  r.detectors.push_back(band);
  r.extractor_seconds = 2.0;
  return r;
}

std::string JsonText(const OcrEvalResult& result) {
  OcrEvalRunInfo info;
  info.world_file = "worlds/w.yaml";
  info.options.passes = 2;
  return ResultJsonText(OcrEvalJson(result, info));
}

TEST(OcrEvalJson, SumsThePassesIntoTheTotals) {
  const std::string json = JsonText(TwoPassResult());
  EXPECT_NE(json.find("\"plates_total\": 4,"), std::string::npos);
  EXPECT_NE(json.find("\"plates_correct\": 3,"), std::string::npos);
  EXPECT_NE(json.find("\"accuracy\": 0.75,"), std::string::npos);
  EXPECT_NE(json.find("\"false_reads\": 1,"), std::string::npos);
  EXPECT_NE(json.find("\"frames\": 200,"), std::string::npos);
  EXPECT_NE(json.find("\"extractor_ms_per_frame\": 10,"), std::string::npos);
  EXPECT_NE(json.find("\"world_file\": \"worlds/w.yaml\""), std::string::npos);
}

TEST(OcrEvalJson, SplitsTheDetectorBoxesByPlateInView) {
  const std::string json = JsonText(TwoPassResult());
  EXPECT_NE(json.find("\"boxes_per_frame\": 0.5,"), std::string::npos);
  EXPECT_NE(json.find("\"boxes_per_frame_plate_in_view\": 1,"), std::string::npos);
  EXPECT_NE(json.find("\"boxes_per_frame_no_plate\": 0.1666666667,"), std::string::npos);
  EXPECT_NE(json.find("\"ms_per_frame\": 5"), std::string::npos);
}

TEST(OcrEvalJson, ListsPerPlateDetailAndEvents) {
  const std::string json = JsonText(TwoPassResult());
  EXPECT_NE(json.find("\"reported\": [\n            \"207\"\n          ]"), std::string::npos) << json;
  EXPECT_NE(json.find("\"kind\": \"false_read\""), std::string::npos);
  EXPECT_NE(json.find("\"box_px\": [\n        1,\n        2,\n        3,\n        4\n      ]"), std::string::npos) << json;
}

}  // namespace
}  // namespace doorplate_localization

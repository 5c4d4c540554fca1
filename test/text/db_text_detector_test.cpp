// Needs the learned models (scripts/fetch_ocr_models.sh); without them the detection tests are skipped
// with the reason, and the missing-model and option errors are still tested.
#include "doorplate_localization/text/db_text_detector.h"

#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "doorplate_localization/text/ppocr_recognizer.h"
#include "text_fixtures.h"

namespace doorplate_localization {
namespace {

bool ModelInstalled() { return std::ifstream(ResolveOcrModelDir("") + "/ppocrv4_det.onnx").good(); }

bool Contains(const cv::Rect& outer, const cv::Rect& inner, int slack_px) {
  return (inner & outer).area() >= inner.area() * 9 / 10 && outer.width <= inner.width + 2 * slack_px &&
         outer.height <= inner.height + 2 * slack_px;
}

class DbTextDetectorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!ModelInstalled()) GTEST_SKIP() << "PP-OCR models not installed in " << ResolveOcrModelDir("");
  }
};

TEST_F(DbTextDetectorTest, BoxesEachTextLineTightlyAndIgnoresPlainShapes) {
  cv::Mat image = test::MakeWall();
  test::DrawDistractors(image);
  test::DrawPlate(image, "E14-295", cv::Point(330, test::kBandCenterY));
  test::DrawPlate(image, "WOMEN", cv::Point(330, 80), 0.8);
  DbTextDetectorOptions options;
  options.band.enabled = false;
  const std::vector<TextRegion> regions = DbTextDetector(options).Detect(test::Grey(image));
  ASSERT_EQ(regions.size(), 2u);
  const cv::Rect number = test::TextRect("E14-295", cv::Point(330, test::kBandCenterY));
  const cv::Rect word = test::TextRect("WOMEN", cv::Point(330, 80), 0.8);
  const bool first_is_word = regions[0].box_px.y < regions[1].box_px.y;
  EXPECT_TRUE(Contains(regions[first_is_word ? 1 : 0].box_px, number, number.height));
  EXPECT_TRUE(Contains(regions[first_is_word ? 0 : 1].box_px, word, word.height));
}

TEST_F(DbTextDetectorTest, SearchesOnlyTheBandAndReturnsFullImageCoordinates) {
  cv::Mat image = test::MakeWall();
  test::DrawPlate(image, "214", cv::Point(320, test::kBandCenterY));
  test::DrawPlate(image, "EXIT", cv::Point(320, 440));  // below the default band
  const std::vector<TextRegion> regions = DbTextDetector(DbTextDetectorOptions{}).Detect(test::Grey(image));
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_TRUE(Contains(regions[0].box_px, test::TextRect("214", cv::Point(320, test::kBandCenterY)), 30));
}

TEST_F(DbTextDetectorTest, AnEmptyWallHasNoText) {
  EXPECT_TRUE(DbTextDetector(DbTextDetectorOptions{}).Detect(test::Grey(test::MakeWall())).empty());
}

TEST_F(DbTextDetectorTest, RefusesAColourOrEmptyImage) {
  const DbTextDetector detector(DbTextDetectorOptions{});
  EXPECT_THROW(detector.Detect(cv::Mat()), std::invalid_argument);
  EXPECT_THROW(detector.Detect(test::MakeWall()), std::invalid_argument);
}

TEST(DbTextDetector, AMissingModelIsAnErrorNamingTheFile) {
  DbTextDetectorOptions options;
  options.model_dir = "/nonexistent/models";
  try {
    DbTextDetector detector(options);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/models/ppocrv4_det.onnx"), std::string::npos) << e.what();
  }
}

TEST(DbTextDetector, RefusesBadOptionsNamingTheField) {
  DbTextDetectorOptions options;
  options.binary_threshold = 1.5;
  try {
    DbTextDetector detector(options);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("binary_threshold"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace doorplate_localization

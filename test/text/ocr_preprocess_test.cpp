#include "doorplate_localization/text/ocr_preprocess.h"

#include <stdexcept>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "text_fixtures.h"

namespace doorplate_localization {
namespace {

// Bounding box of the black (text) pixels of a 0/255 image.
cv::Rect InkBox(const cv::Mat& binary) {
  cv::Mat ink = binary == 0;
  return cv::boundingRect(ink);
}

cv::Mat PlateCrop(cv::Scalar plate, cv::Scalar ink) {
  cv::Mat image = test::MakeWall();
  const cv::Rect plate_rect =
      test::DrawPlate(image, "214", cv::Point(320, test::kBandCenterY), 0.8, 2, plate, ink);
  const cv::Rect crop(plate_rect.x - 6, plate_rect.y - 6, plate_rect.width + 12, plate_rect.height + 12);
  return image(crop).clone();  // plate plus a strip of wall around it
}

TEST(PrepareCropForOcr, GivesDarkTextOfTheTargetHeightOnAWhiteBorder) {
  const OcrPreprocessOptions options;
  const cv::Mat out = PrepareCropForOcr(PlateCrop(cv::Scalar(240, 245, 245), cv::Scalar(20, 20, 20)), options);
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.type(), CV_8UC1);
  const cv::Rect ink = InkBox(out);
  EXPECT_NEAR(ink.height, options.target_text_height_px, 3);
  EXPECT_GE(ink.x, options.border_px);
  EXPECT_GE(ink.y, options.border_px);
  EXPECT_EQ(cv::countNonZero(out.row(0)), out.cols);  // white border
  EXPECT_EQ(cv::countNonZero((out != 0) & (out != 255)), 0);  // strictly binary
}

TEST(PrepareCropForOcr, TurnsLightTextOnADarkPlateIntoDarkText) {
  const cv::Mat out = PrepareCropForOcr(PlateCrop(cv::Scalar(50, 30, 30), cv::Scalar(235, 235, 235)), {});
  ASSERT_FALSE(out.empty());
  const cv::Rect ink = InkBox(out);
  EXPECT_NEAR(ink.height, OcrPreprocessOptions{}.target_text_height_px, 3);
  EXPECT_GT(cv::countNonZero(out), out.total() / 2);  // mostly white background
}

TEST(PrepareCropForOcr, InkThinningMakesTheStrokesThinnerButKeepsTheGlyphs) {
  const cv::Mat crop = PlateCrop(cv::Scalar(240, 245, 245), cv::Scalar(20, 20, 20));
  OcrPreprocessOptions bold;
  bold.ink_thinning_px = 0;
  OcrPreprocessOptions thin = bold;
  thin.ink_thinning_px = 1;
  const cv::Mat bold_out = PrepareCropForOcr(crop, bold), thin_out = PrepareCropForOcr(crop, thin);
  ASSERT_EQ(bold_out.size(), thin_out.size());
  const int bold_ink = cv::countNonZero(bold_out == 0), thin_ink = cv::countNonZero(thin_out == 0);
  EXPECT_LT(thin_ink, bold_ink * 9 / 10);
  EXPECT_GT(thin_ink, bold_ink / 3);
  EXPECT_NEAR(InkBox(thin_out).height, InkBox(bold_out).height, 3);
}

TEST(PrepareCropForOcr, ReturnsEmptyForACropWithoutText) {
  cv::Mat blank(30, 80, CV_8UC1, cv::Scalar(200));
  EXPECT_TRUE(PrepareCropForOcr(blank, {}).empty());
}

TEST(PrepareCropForOcr, RejectsEmptyAndFloatCrops) {
  EXPECT_THROW(PrepareCropForOcr(cv::Mat(), {}), std::invalid_argument);
  EXPECT_THROW(PrepareCropForOcr(cv::Mat(10, 10, CV_32FC1, cv::Scalar(0)), {}), std::invalid_argument);
}

TEST(ValidateOcrPreprocessOptions, RejectsATinyTargetHeight) {
  OcrPreprocessOptions options;
  options.target_text_height_px = 2;
  EXPECT_THROW(ValidateOcrPreprocessOptions(options), std::invalid_argument);
}

TEST(ValidateOcrPreprocessOptions, RejectsNegativeInkThinning) {
  OcrPreprocessOptions options;
  options.ink_thinning_px = -1;
  EXPECT_THROW(ValidateOcrPreprocessOptions(options), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

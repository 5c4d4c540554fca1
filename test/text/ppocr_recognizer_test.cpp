// Needs the learned models (scripts/fetch_ocr_models.sh, which install_deps.sh runs); without them the
// tests that read are skipped with the reason, and the missing-model error is still tested.
#include "doorplate_localization/text/ppocr_recognizer.h"

#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "text_fixtures.h"

namespace doorplate_localization {
namespace {

bool ModelsInstalled() {
  return std::ifstream(ResolveOcrModelDir("") + "/ppocrv4_rec_dict.txt").good();
}

// A plate crop as a detector boxes it: the text line with a margin of ~15 % of its height.
cv::Mat PlateCrop(const std::string& text, cv::Scalar plate, cv::Scalar ink, double scale = 1.0) {
  cv::Mat image = test::MakeWall();
  const cv::Point center(320, test::kBandCenterY);
  test::DrawPlate(image, text, center, scale, 2, plate, ink);
  const cv::Rect t = test::TextRect(text, center, scale);
  const int pad = t.height * 15 / 100 + 2;
  return image(cv::Rect(t.x - pad, t.y - pad, t.width + 2 * pad, t.height + 2 * pad)).clone();
}

class PpOcrRecognizerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!ModelsInstalled()) GTEST_SKIP() << "PP-OCR models not installed in " << ResolveOcrModelDir("");
    ocr_ = std::make_unique<PpOcrRecognizer>(PpOcrRecognizerOptions{});
  }
  std::unique_ptr<PpOcrRecognizer> ocr_;
};

TEST_F(PpOcrRecognizerTest, ReadsRealWorldIdentifierFormatsWithTheirSeparators) {
  for (const std::string room : {"214", "E14-295", "B2.114", "32-069T", "B/1404"}) {
    const OcrReading reading = ocr_->Read(PlateCrop(room, {240, 245, 245}, {25, 20, 20}));
    EXPECT_EQ(reading.text, room);
    EXPECT_GT(reading.confidence, 0.8) << room;
    EXPECT_LE(reading.confidence, 1.0) << room;
  }
}

TEST_F(PpOcrRecognizerTest, ReadsLightTextOnADarkPlateAndGreyCrops) {
  const cv::Mat crop = PlateCrop("3100", {120, 40, 60}, {235, 235, 235});
  EXPECT_EQ(ocr_->Read(crop).text, "3100");
  EXPECT_EQ(ocr_->Read(test::Grey(crop)).text, "3100");
}

TEST_F(PpOcrRecognizerTest, ReadsLowContrastGreyOnLightGrey) {
  EXPECT_EQ(ocr_->Read(PlateCrop("102A", {215, 215, 215}, {150, 150, 150}, 0.7)).text, "102A");
}

TEST_F(PpOcrRecognizerTest, OutputsOnlyAllowedCharactersAndFoldsLowerCase) {
  PpOcrRecognizerOptions options;
  options.allowed_characters = "0123456789";
  PpOcrRecognizer digits_only(options);
  const OcrReading reading = digits_only.Read(PlateCrop("E14-295", {240, 245, 245}, {25, 20, 20}));
  EXPECT_EQ(reading.text.find_first_not_of("0123456789"), std::string::npos) << reading.text;
  EXPECT_EQ(ocr_->Read(PlateCrop("lab", {240, 245, 245}, {25, 20, 20})).text, "LAB");
}

TEST_F(PpOcrRecognizerTest, ABlankCropReadsNothing) {
  const OcrReading reading = ocr_->Read(cv::Mat(40, 120, CV_8UC3, cv::Scalar(200, 200, 200)));
  EXPECT_EQ(reading.text, "");
  EXPECT_EQ(reading.confidence, 0.0);
}

TEST_F(PpOcrRecognizerTest, RefusesAnEmptyCrop) {
  EXPECT_THROW(ocr_->Read(cv::Mat()), std::invalid_argument);
  EXPECT_THROW(ocr_->Read(cv::Mat(10, 10, CV_32FC1)), std::invalid_argument);
}

TEST(PpOcrRecognizer, AMissingModelFolderIsAnErrorNamingTheFileAndTheInstallCommand) {
  PpOcrRecognizerOptions options;
  options.model_dir = "/nonexistent/models";
  try {
    PpOcrRecognizer ocr(options);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/models/ppocrv4_rec_dict.txt"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("fetch_ocr_models.sh"), std::string::npos) << e.what();
  }
}

TEST(PpOcrRecognizer, RefusesBadOptionsNamingTheField) {
  PpOcrRecognizerOptions options;
  options.input_widths_px = {320, 160};
  EXPECT_THROW({ PpOcrRecognizer ocr(options); }, std::invalid_argument);
  options = {};
  options.min_confidence = 1.5;
  try {
    PpOcrRecognizer ocr(options);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("min_confidence"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace doorplate_localization

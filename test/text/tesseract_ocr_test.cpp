// Needs Debian's tesseract-ocr-eng (LSTM model in /usr/share/tesseract-ocr/5/tessdata).
#include "doorplate_localization/text/tesseract_ocr.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "text_fixtures.h"

namespace doorplate_localization {
namespace {

// The plate as the detector would box it: the text line plus 15 % of its height on each side.
cv::Mat RenderedPlateCrop(const std::string& text, double scale = 1.0) {
  cv::Mat image = test::MakeWall();
  const cv::Point center(320, test::kBandCenterY);
  test::DrawPlate(image, text, center, scale);
  const cv::Rect t = test::TextRect(text, center, scale);
  const int pad = t.height * 15 / 100 + 2;
  return image(cv::Rect(t.x - pad, t.y - pad, t.width + 2 * pad, t.height + 2 * pad)).clone();
}

class TesseractOcrTest : public ::testing::Test {
 protected:
  TesseractOcr ocr_{TesseractOcrOptions{}};
};

TEST_F(TesseractOcrTest, ReadsRenderedRoomNumbersWithHighConfidence) {
  for (const std::string room : {"214", "2140", "301"}) {
    const OcrReading reading = ocr_.Read(RenderedPlateCrop(room));
    EXPECT_EQ(reading.text, room);
    EXPECT_GT(reading.confidence, 0.7) << room;
    EXPECT_LE(reading.confidence, 1.0) << room;
  }
}

TEST_F(TesseractOcrTest, ReadsSmallFarAwayPlates) {
  EXPECT_EQ(ocr_.Read(RenderedPlateCrop("301", 0.6)).text, "301");
}

TEST_F(TesseractOcrTest, ReadsTheDigitsOfARealSceneTextPhoto) {
  const std::string path = std::string(DOORPLATE_SOURCE_DIR) + "/test/data/text/scenetext04_gm125_digits.png";
  const cv::Mat crop = cv::imread(path, cv::IMREAD_COLOR);
  ASSERT_FALSE(crop.empty()) << path;
  EXPECT_EQ(ocr_.Read(crop).text, "125");
}

TEST_F(TesseractOcrTest, ReadsNothingOnABlankPlate) {
  const OcrReading reading = ocr_.Read(cv::Mat(40, 120, CV_8UC3, cv::Scalar(240, 240, 240)));
  EXPECT_EQ(reading.text, "");
  EXPECT_EQ(reading.confidence, 0.0);
}

TEST_F(TesseractOcrTest, RejectsAnEmptyCrop) {
  EXPECT_THROW(ocr_.Read(cv::Mat()), std::invalid_argument);
}

TEST(TesseractOcr, MissingModelThrowsNamingTheFile) {
  TesseractOcrOptions options;
  options.tessdata_dir = "/nonexistent/tessdata";
  try {
    TesseractOcr ocr(options);
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/tessdata/eng.traineddata"), std::string::npos)
        << e.what();
  }
}

TEST(ResolveTessdataDir, PrefersTheOptionThenTessdataPrefixThenDebiansFolder) {
  const char* saved = std::getenv("TESSDATA_PREFIX");
  const std::string saved_value = saved ? saved : "";
  TesseractOcrOptions options;
  unsetenv("TESSDATA_PREFIX");
  EXPECT_EQ(ResolveTessdataDir(options), "/usr/share/tesseract-ocr/5/tessdata");
  setenv("TESSDATA_PREFIX", "/opt/tessdata", 1);
  EXPECT_EQ(ResolveTessdataDir(options), "/opt/tessdata");
  options.tessdata_dir = "/my/tessdata";
  EXPECT_EQ(ResolveTessdataDir(options), "/my/tessdata");
  if (saved) {
    setenv("TESSDATA_PREFIX", saved_value.c_str(), 1);
  } else {
    unsetenv("TESSDATA_PREFIX");
  }
}

TEST(TesseractOcr, ItsMinimumConfidenceComesFromItsOptionsAndItReadsGrey) {
  TesseractOcrOptions options;
  options.min_confidence = 0.25;
  const TesseractOcr ocr(options);
  EXPECT_EQ(ocr.min_confidence(), 0.25);
  EXPECT_FALSE(ocr.reads_colour());
}

}  // namespace
}  // namespace doorplate_localization

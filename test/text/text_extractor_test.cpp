#include "doorplate_localization/text/text_extractor.h"

#include <stdexcept>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "text_fixtures.h"

namespace doorplate_localization {
namespace {

// A frame of the robot driving past a plate: "214" at column `plate_x` in the band, a poster above it.
cv::Mat Frame(int plate_x, std::uint32_t seed) {
  cv::Mat image = test::MakeWall(150, 2.0, seed);
  test::DrawPlate(image, "214", cv::Point(plate_x, test::kBandCenterY));
  test::DrawPlate(image, "EXIT 12", cv::Point(plate_x - 150, 60));
  return image;
}

std::vector<PlateReport> DrivePast(TextExtractor& extractor, int from_x, int to_x, int step) {
  std::vector<PlateReport> reports;
  double t = 0.0;
  std::uint32_t seed = 1;
  for (int x = from_x; step < 0 ? x >= to_x : x <= to_x; x += step, t += 0.1) {
    for (const PlateReport& r : extractor.Process(Frame(x, seed++), t)) reports.push_back(r);
  }
  return reports;
}

TEST(TextExtractor, ReportsThePlateOnceWithAPositiveBearingWhenItPassesRightToLeft) {
  TextExtractor extractor({});
  const std::vector<PlateReport> reports = DrivePast(extractor, 560, 80, -40);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].text, "214");
  EXPECT_GT(reports[0].bearing_rad, 0.0);
  EXPECT_LT(reports[0].bearing_rad, std::atan(40.0 / 554.0));  // the first frame past the centre
  EXPECT_GE(reports[0].voted_frame_count, 5);
  EXPECT_GT(reports[0].confidence, 0.7);
}

TEST(TextExtractor, ReportsANegativeBearingWhenThePlatePassesLeftToRight) {
  TextExtractor extractor({});
  const std::vector<PlateReport> reports = DrivePast(extractor, 100, 540, 50);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].text, "214");
  EXPECT_LT(reports[0].bearing_rad, 0.0);
}

TEST(TextExtractor, ExposesTheLastFramesObservations) {
  TextExtractor extractor({});
  extractor.Process(Frame(400, 3), 0.0);
  ASSERT_EQ(extractor.last_observations().size(), 1u);  // the poster is outside the band
  EXPECT_EQ(extractor.last_observations()[0].text, "214");
}

TEST(TextExtractor, RejectsEmptyAndFloatImagesAndKeepsWorking) {
  TextExtractor extractor({});
  EXPECT_THROW(extractor.Process(cv::Mat(), 0.0), std::invalid_argument);
  EXPECT_THROW(extractor.Process(cv::Mat(480, 640, CV_32FC3, cv::Scalar(0.5, 0.5, 0.5)), 0.1),
               std::invalid_argument);
  EXPECT_NO_THROW(extractor.Process(test::Grey(Frame(400, 4)), 0.2));  // mono8 works too
  EXPECT_EQ(extractor.last_observations().size(), 1u);
}

// Counts calls and answers "214": lets the test see how many boxes reach the OCR.
class CountingOcr : public OcrEngine {
 public:
  explicit CountingOcr(int* calls) : calls_(calls) {}
  OcrReading Read(const cv::Mat&) override {
    ++*calls_;
    return {"214", 0.9};
  }

 private:
  int* calls_;
};

TEST(TextExtractor, SendsAtMostMaxRegionsPerFrameBoxesToTheOcr) {
  cv::Mat image = test::MakeWall();
  for (const int x : {100, 300, 500}) test::DrawPlate(image, "214", cv::Point(x, test::kBandCenterY));
  TextExtractorOptions options;
  options.max_regions_per_frame = 2;
  int calls = 0;
  TextExtractor extractor(options, std::make_unique<MserBandDetector>(options.detector),
                          std::make_unique<CountingOcr>(&calls));
  extractor.Process(image, 0.0);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(extractor.last_observations().size(), 2u);
}

// Answers a fixed reading with a fixed minimum confidence: lets the tests set the recogniser's confidence.
class FixedOcr : public OcrEngine {
 public:
  FixedOcr(OcrReading reading, double min_confidence)
      : reading_(std::move(reading)), min_confidence_(min_confidence) {}
  OcrReading Read(const cv::Mat&) override { return reading_; }
  double min_confidence() const override { return min_confidence_; }

 private:
  OcrReading reading_;
  double min_confidence_;
};

TEST(TextExtractor, ReadFrameReadsAStillImageWithoutTouchingTheTracker) {
  TextExtractor extractor({});
  const std::vector<PlateObservation> reads = extractor.ReadFrame(Frame(400, 5));
  ASSERT_EQ(reads.size(), 1u);
  EXPECT_EQ(reads[0].text, "214");
  EXPECT_EQ(reads[0].raw_text, "214");
  EXPECT_GT(reads[0].raw_confidence, 0.0);
  // The tracker saw nothing: driving past afterwards still reports the plate exactly once.
  EXPECT_EQ(DrivePast(extractor, 560, 80, -40).size(), 1u);
}

TEST(TextExtractor, ReadingsBelowTheRecognisersMinimumConfidenceAreNotValidated) {
  TextExtractorOptions options;
  TextExtractor unsure(options, std::make_unique<MserBandDetector>(options.detector),
                       std::make_unique<FixedOcr>(OcrReading{"214", 0.4}, 0.5));
  const std::vector<PlateObservation> low = unsure.ReadFrame(Frame(400, 6));
  ASSERT_EQ(low.size(), 1u);
  EXPECT_EQ(low[0].raw_text, "214");  // kept for diagnostics
  EXPECT_EQ(low[0].text, "");
  TextExtractor sure(options, std::make_unique<MserBandDetector>(options.detector),
                     std::make_unique<FixedOcr>(OcrReading{"214", 0.6}, 0.5));
  EXPECT_EQ(sure.ReadFrame(Frame(400, 6)).at(0).text, "214");
}

TEST(TextExtractor, DetectorAndRecognizerNamesParseAndPrintBack) {
  EXPECT_EQ(ParseTextDetectorType("db", "detector"), TextDetectorType::kDb);
  EXPECT_EQ(ToString(ParseTextDetectorType("mser", "detector")), "mser");
  EXPECT_EQ(ParseTextRecognizerType("ppocr", "recognizer"), TextRecognizerType::kPpOcr);
  EXPECT_EQ(ToString(ParseTextRecognizerType("tesseract", "recognizer")), "tesseract");
  try {
    ParseTextRecognizerType("easyocr", "~recognizer");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("~recognizer"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("tesseract, ppocr"), std::string::npos) << e.what();
  }
}

TEST(TextExtractor, AskingForALearnedModelThatIsNotInstalledNamesItsFile) {
  TextExtractorOptions options;
  options.recognizer_type = TextRecognizerType::kPpOcr;
  options.ppocr.model_dir = "/nonexistent/models";
  EXPECT_THROW({ TextExtractor extractor(options); }, std::runtime_error);
}

}  // namespace
}  // namespace doorplate_localization

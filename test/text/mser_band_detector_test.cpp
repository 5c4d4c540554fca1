#include "doorplate_localization/text/mser_band_detector.h"

#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "doorplate_localization/text/tesseract_ocr.h"

#include "text_fixtures.h"

namespace doorplate_localization {
namespace {

using test::DrawDistractors;
using test::DrawPlate;
using test::Grey;
using test::MakeWall;
using test::TextRect;

// Expects `fn` to throw std::invalid_argument whose message names `field`.
template <typename Fn>
void ExpectInvalidNaming(Fn fn, const std::string& field) {
  try {
    fn();
    FAIL() << "expected std::invalid_argument naming " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(MserBandDetector, FindsThePlateTextInTheBandInFullImageCoordinates) {
  cv::Mat image = MakeWall();
  const cv::Point center(420, test::kBandCenterY);
  const cv::Rect plate = DrawPlate(image, "214", center);
  const auto regions = MserBandDetector({}).Detect(Grey(image));
  ASSERT_EQ(regions.size(), 1u);
  const cv::Rect& box = regions[0].box_px;
  const cv::Rect text = TextRect("214", center);
  EXPECT_EQ((box & text).area(), text.area()) << box << " should contain " << text;
  EXPECT_EQ((box & plate).area(), box.area()) << box << " should lie on the plate " << plate;
  EXPECT_GE(regions[0].num_chars, 3);
}

TEST(MserBandDetector, IgnoresTextAboveAndBelowTheBandUnlessTheBandIsDisabled) {
  cv::Mat image = MakeWall();
  DrawPlate(image, "301", cv::Point(200, 60));   // poster high on the wall
  DrawPlate(image, "EXIT", cv::Point(450, 420));  // sign low on a door
  EXPECT_TRUE(MserBandDetector({}).Detect(Grey(image)).empty());

  MserBandDetectorOptions full_image;
  full_image.band.enabled = false;
  EXPECT_EQ(MserBandDetector(full_image).Detect(Grey(image)).size(), 2u);
}

TEST(MserBandDetector, IgnoresHandleFrameAndVentBlobsInTheBand) {
  cv::Mat image = MakeWall();
  DrawDistractors(image);
  const cv::Rect plate = DrawPlate(image, "2140", cv::Point(380, test::kBandCenterY));
  const auto regions = MserBandDetector({}).Detect(Grey(image));
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ((regions[0].box_px & plate).area(), regions[0].box_px.area());
}

TEST(MserBandDetector, DropsTextCutByTheBandEdge) {
  cv::Mat image = MakeWall();
  DrawPlate(image, "214", cv::Point(320, 96));  // straddles the band's top row
  EXPECT_TRUE(MserBandDetector({}).Detect(Grey(image)).empty());
}

TEST(MserBandDetector, AcceptsABandGivenInPixels) {
  cv::Mat image = MakeWall();
  DrawPlate(image, "214", cv::Point(320, 400));
  MserBandDetectorOptions options;
  options.band.top_px = 350;
  options.band.bottom_px = 460;
  EXPECT_EQ(MserBandDetector(options).Detect(Grey(image)).size(), 1u);
}

TEST(MserBandDetector, RejectsAnEmptyOrOutOfImageBandNamingTheField) {
  MserBandDetectorOptions empty;
  empty.band.top_px = 200;
  empty.band.bottom_px = 200;
  ExpectInvalidNaming([&] { MserBandDetector{empty}; }, "band.bottom_px");

  MserBandDetectorOptions inverted;
  inverted.band.top_fraction = 0.6;
  inverted.band.bottom_fraction = 0.4;
  ExpectInvalidNaming([&] { MserBandDetector{inverted}; }, "band.bottom_fraction");

  MserBandDetectorOptions half_set;
  half_set.band.top_px = 10;
  ExpectInvalidNaming([&] { MserBandDetector{half_set}; }, "band.top_px");

  MserBandDetectorOptions too_low;
  too_low.band.top_px = 400;
  too_low.band.bottom_px = 600;
  const MserBandDetector detector(too_low);
  ExpectInvalidNaming([&] { detector.Detect(Grey(MakeWall())); }, "band.bottom_px");
}

TEST(MserBandDetector, RejectsEmptyAndColourImages) {
  const MserBandDetector detector({});
  EXPECT_THROW(detector.Detect(cv::Mat()), std::invalid_argument);
  EXPECT_THROW(detector.Detect(MakeWall()), std::invalid_argument);
}

TEST(MserBandDetector, BoxesTheTextLineOfARealPhotoThatTheOcrThenReads) {
  const std::string path = std::string(DOORPLATE_SOURCE_DIR) + "/test/data/text/scenetext04_gm125_plate.png";
  const cv::Mat photo = cv::imread(path, cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(photo.empty()) << path;
  MserBandDetectorOptions options;
  options.band.enabled = false;
  const auto regions = MserBandDetector(options).Detect(photo);
  ASSERT_EQ(regions.size(), 1u);
  const cv::Rect digits(102, 33, 74, 40);  // "125" in this crop, measured by hand
  EXPECT_EQ((regions[0].box_px & digits).area(), digits.area()) << regions[0].box_px;
  TesseractOcrOptions ocr_options;
  ocr_options.whitelist = "0123456789GM";
  EXPECT_EQ(TesseractOcr(ocr_options).Read(photo(regions[0].box_px)).text, "GM125");
}

TEST(ResolveBandRows, ConvertsFractionsOfTheImageHeightToRows) {
  const cv::Range rows = ResolveBandRows(BandOptions{}, 480);
  EXPECT_EQ(rows.start, 96);
  EXPECT_EQ(rows.end, 298);
  BandOptions disabled;
  disabled.enabled = false;
  EXPECT_EQ(ResolveBandRows(disabled, 480).size(), 480);
}

}  // namespace
}  // namespace doorplate_localization

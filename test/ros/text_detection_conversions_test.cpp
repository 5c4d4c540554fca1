// Tests of the shared checks of received doorplate detections (text_detection_conversions.h).
#include "doorplate_localization/ros/text_detection_conversions.h"

#include <gtest/gtest.h>

#include <limits>

namespace doorplate_localization {
namespace {

// What the text extractor reports for a plate read at the image centre (text_conversions' Report()).
TextDetection Report() {
  TextDetection d;
  d.text = "214";
  d.confidence = 0.72f;
  d.bearing_rad = -0.0108f;
  d.frame_count = 6;
  d.crossed_center = true;
  return d;
}

TEST(ValidateTextDetection, AcceptsAReportAndNamesTheBrokenField) {
  TextDetection msg = Report();
  EXPECT_EQ(ValidateTextDetection(msg), "");
  msg.bearing_rad = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(ValidateTextDetection(msg).find("bearing_rad"), std::string::npos);
  msg = Report();
  msg.bearing_rad = 2.0f;  // behind the camera
  EXPECT_NE(ValidateTextDetection(msg).find("within ±pi/2"), std::string::npos);
  msg = Report();
  msg.confidence = 1.5f;
  EXPECT_NE(ValidateTextDetection(msg).find("confidence"), std::string::npos);
  msg = Report();
  msg.text.clear();
  EXPECT_EQ(ValidateTextDetection(msg), "text is empty");
}

TEST(IsPlateReport, NeedsTheCentreCrossingAndAText) {
  TextDetection d = Report();
  EXPECT_TRUE(IsPlateReport(d));
  d.crossed_center = false;
  EXPECT_FALSE(IsPlateReport(d));
  d = Report();
  d.text.clear();  // a rejected reading
  EXPECT_FALSE(IsPlateReport(d));
}

TEST(CrossedPlateTexts, OnlyReadPlatesThatCrossedTheImageCentreCount) {
  TextDetectionArray array;
  TextDetection d;
  d.text = "105";
  d.crossed_center = true;
  array.detections.push_back(d);
  d.text = "";  // a rejected reading
  array.detections.push_back(d);
  d.text = "107";
  d.crossed_center = false;
  array.detections.push_back(d);
  EXPECT_EQ(CrossedPlateTexts(array), std::vector<std::string>{"105"});
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/ros/text_conversions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <boost/make_shared.hpp>
#include <sensor_msgs/image_encodings.h>

namespace doorplate_localization {
namespace {

PlateReport Report() {
  PlateReport r;
  r.text = "214";
  r.vote_share = 0.8;
  r.mean_confidence = 0.9;
  r.confidence = 0.72;
  r.voted_frame_count = 6;
  r.observed_frame_count = 7;
  r.box_px = cv::Rect(300, 190, 52, 24);
  r.bearing_rad = -0.0108;
  r.stamp_s = 12.5;
  r.track_id = 3;
  return r;
}

sensor_msgs::CameraInfo Info(uint32_t width = 640, uint32_t height = 480, double fx = 554.25, double cx = 320.0) {
  sensor_msgs::CameraInfo info;
  info.width = width;
  info.height = height;
  info.K = {fx, 0.0, cx, 0.0, fx, 240.0, 0.0, 0.0, 1.0};
  return info;
}

sensor_msgs::ImagePtr Image(const std::string& encoding, uint32_t width, uint32_t height, uint32_t channels) {
  auto image = boost::make_shared<sensor_msgs::Image>();
  image->encoding = encoding;
  image->width = width;
  image->height = height;
  image->step = width * channels;
  image->data.assign(static_cast<size_t>(image->step) * height, 0);
  return image;
}

CameraGeometry Geometry640x480() {
  CameraGeometry g;
  EXPECT_EQ(ReadCameraGeometry(Info(), &g), "");
  return g;
}

TEST(ToTextDetectionMsg, CopiesTextBoxBearingVotesAndMarksTheCrossing) {
  const TextDetection msg = ToTextDetectionMsg(Report());
  EXPECT_EQ(msg.text, "214");
  EXPECT_FLOAT_EQ(msg.confidence, 0.72f);
  EXPECT_EQ(msg.box.x_offset, 300u);
  EXPECT_EQ(msg.box.y_offset, 190u);
  EXPECT_EQ(msg.box.width, 52u);
  EXPECT_EQ(msg.box.height, 24u);
  EXPECT_FALSE(msg.box.do_rectify);
  EXPECT_FLOAT_EQ(msg.bearing_rad, -0.0108f);
  EXPECT_EQ(msg.frame_count, 6u);  // voted frames, not merely observed ones
  EXPECT_TRUE(msg.crossed_center);
}

TEST(ToTextDetectionMsg, RejectsABoxWithANegativeCorner) {
  PlateReport r = Report();
  r.box_px.x = -1;
  EXPECT_THROW(ToTextDetectionMsg(r), std::invalid_argument);
}

TEST(ToTextDetectionArrayMsg, CopiesTheImageHeaderAndOneDetectionPerReport) {
  std_msgs::Header header;
  header.stamp = ros::Time(12, 500000000);
  header.frame_id = "camera_optical";
  header.seq = 42;
  PlateReport other = Report();
  other.text = "216";
  const TextDetectionArray msg = ToTextDetectionArrayMsg({Report(), other}, header);
  EXPECT_EQ(msg.header.frame_id, "camera_optical");
  EXPECT_EQ(msg.header.stamp, header.stamp);
  ASSERT_EQ(msg.detections.size(), 2u);
  EXPECT_EQ(msg.detections[1].text, "216");
  EXPECT_TRUE(ToTextDetectionArrayMsg({}, header).detections.empty());  // a processed image without plates
}

TEST(FromTextDetectionMsg, RoundTripsTheFieldsTheMessageCarries) {
  const PlateReport back = FromTextDetectionMsg(ToTextDetectionMsg(Report()), ros::Time(12, 500000000));
  EXPECT_EQ(back.text, "214");
  EXPECT_NEAR(back.confidence, 0.72, 1e-6);
  EXPECT_EQ(back.box_px, Report().box_px);
  EXPECT_NEAR(back.bearing_rad, -0.0108, 1e-6);
  EXPECT_EQ(back.voted_frame_count, 6);
  EXPECT_DOUBLE_EQ(back.stamp_s, 12.5);
  EXPECT_EQ(back.track_id, 0);  // not carried
  EXPECT_EQ(back.observed_frame_count, 0);
}

TEST(ReadCameraGeometry, TakesSizeFocalLengthAndPrincipalColumnFromK) {
  CameraGeometry g;
  ASSERT_EQ(ReadCameraGeometry(Info(800, 600, 700.0, 401.5), &g), "");
  EXPECT_EQ(g.width_px, 800);
  EXPECT_EQ(g.height_px, 600);
  EXPECT_DOUBLE_EQ(g.fx_px, 700.0);
  EXPECT_DOUBLE_EQ(g.cx_px, 401.5);
}

TEST(ReadCameraGeometry, RejectsAnUncalibratedOrEmptyCameraAndKeepsThePreviousGeometry) {
  CameraGeometry g = Geometry640x480();
  EXPECT_NE(ReadCameraGeometry(Info(640, 480, 0.0), &g).find("K[0] (fx)"), std::string::npos);  // all-zero K
  EXPECT_NE(ReadCameraGeometry(Info(640, 480, 554.0, std::nan("")), &g).find("K[2] (cx)"), std::string::npos);
  EXPECT_NE(ReadCameraGeometry(Info(0, 480), &g).find("width and height"), std::string::npos);
  EXPECT_EQ(g.width_px, 640);
  EXPECT_DOUBLE_EQ(g.fx_px, 554.25);
}

TEST(ValidateCameraImage, AcceptsBgr8Rgb8AndMono8OfTheCameraInfoSize) {
  const CameraGeometry g = Geometry640x480();
  EXPECT_EQ(ValidateCameraImage(*Image("bgr8", 640, 480, 3), g), "");
  EXPECT_EQ(ValidateCameraImage(*Image("rgb8", 640, 480, 3), g), "");
  EXPECT_EQ(ValidateCameraImage(*Image("mono8", 640, 480, 1), g), "");
}

TEST(ValidateCameraImage, NamesEmptyUnsupportedTruncatedAndMismatchedImages) {
  const CameraGeometry g = Geometry640x480();
  EXPECT_NE(ValidateCameraImage(*Image("bgr8", 0, 0, 3), g).find("empty image"), std::string::npos);
  EXPECT_NE(ValidateCameraImage(*Image("32FC1", 640, 480, 4), g).find("unsupported encoding '32FC1'"),
            std::string::npos);
  EXPECT_NE(ValidateCameraImage(*Image("bgra8", 640, 480, 4), g).find("unsupported encoding"), std::string::npos);
  sensor_msgs::ImagePtr truncated = Image("bgr8", 640, 480, 3);
  truncated->data.resize(100);
  EXPECT_NE(ValidateCameraImage(*truncated, g).find("too small"), std::string::npos);
  sensor_msgs::ImagePtr narrow_step = Image("bgr8", 640, 480, 3);
  narrow_step->step = 640;  // one byte per pixel for a three-byte encoding
  EXPECT_NE(ValidateCameraImage(*narrow_step, g).find("too small"), std::string::npos);
  EXPECT_NE(ValidateCameraImage(*Image("bgr8", 320, 240, 3), g).find("camera_info says 640x480"),
            std::string::npos);
}

TEST(ToExtractorImage, SharesBgr8AndMono8AndTurnsRgb8IntoBgr8) {
  sensor_msgs::ImagePtr rgb = Image("rgb8", 4, 2, 3);
  rgb->data[0] = 10;  // pixel (0, 0): R = 10, G = 20, B = 30
  rgb->data[1] = 20;
  rgb->data[2] = 30;
  const cv_bridge::CvImageConstPtr bgr = ToExtractorImage(rgb);
  ASSERT_EQ(bgr->image.type(), CV_8UC3);
  EXPECT_EQ(bgr->image.at<cv::Vec3b>(0, 0), cv::Vec3b(30, 20, 10));

  sensor_msgs::ImagePtr bgr8 = Image("bgr8", 4, 2, 3);
  EXPECT_EQ(ToExtractorImage(bgr8)->image.data, bgr8->data.data());  // no copy
  sensor_msgs::ImagePtr mono = Image("mono8", 4, 2, 1);
  const cv_bridge::CvImageConstPtr grey = ToExtractorImage(mono);
  EXPECT_EQ(grey->image.type(), CV_8UC1);
  EXPECT_EQ(grey->image.data, mono->data.data());
}

TEST(ToTextDebugImageMsg, DrawsBandBoxesAndReportsOnABgr8CopyWithTheImageHeader) {
  const cv::Mat grey(480, 640, CV_8UC1, cv::Scalar(128));
  std_msgs::Header header;
  header.frame_id = "camera_optical";
  header.stamp = ros::Time(3, 0);
  PlateObservation read{cv::Rect(100, 200, 40, 20), "214", 0.9, "214"};
  PlateObservation rejected{cv::Rect(400, 200, 40, 20), "", 0.0, "EXIT"};
  const sensor_msgs::ImagePtr msg =
      ToTextDebugImageMsg(grey, header, cv::Range(96, 298), 320.0, {read, rejected}, {Report()});
  EXPECT_EQ(msg->encoding, sensor_msgs::image_encodings::BGR8);
  EXPECT_EQ(msg->width, 640u);
  EXPECT_EQ(msg->height, 480u);
  EXPECT_EQ(msg->header.frame_id, "camera_optical");
  EXPECT_EQ(msg->header.stamp, header.stamp);
  const cv::Mat drawn = cv_bridge::toCvCopy(msg)->image;
  const auto coloured = [&](int row, int col) {
    const cv::Vec3b p = drawn.at<cv::Vec3b>(row, col);
    return !(p[0] == p[1] && p[1] == p[2]);
  };
  EXPECT_TRUE(coloured(96, 10));    // band top
  EXPECT_TRUE(coloured(297, 10));   // band bottom (last row of the band)
  EXPECT_TRUE(coloured(50, 320));   // centre line
  EXPECT_TRUE(coloured(210, 100));  // left edge of the validated box
  EXPECT_TRUE(coloured(190, 330));  // top edge of the reported plate's thick box (x 300..352, y 190..214)
  EXPECT_FALSE(coloured(400, 10));  // untouched wall
  EXPECT_EQ(grey.at<uint8_t>(96, 10), 128);  // the input is not drawn on
}

TEST(ToTextDebugImageMsg, RejectsAnEmptyImage) {
  EXPECT_THROW(ToTextDebugImageMsg(cv::Mat(), std_msgs::Header(), cv::Range(0, 1), 0.0, {}, {}),
               std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization

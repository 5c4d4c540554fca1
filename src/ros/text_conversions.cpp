#include "doorplate_localization/ros/text_conversions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include <opencv2/imgproc.hpp>
#include <sensor_msgs/image_encodings.h>

namespace doorplate_localization {
namespace {

namespace enc = sensor_msgs::image_encodings;

const cv::Scalar kBandColour(0, 220, 255);      // yellow
const cv::Scalar kCentreColour(255, 120, 0);    // blue
const cv::Scalar kRejectedColour(160, 160, 160);
const cv::Scalar kReadColour(0, 200, 0);
const cv::Scalar kReportColour(0, 0, 255);

void Label(cv::Mat& image, const std::string& text, const cv::Point& bottom_left, const cv::Scalar& colour) {
  const cv::Point at(std::max(0, bottom_left.x), std::max(12, bottom_left.y));
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 3, cv::LINE_AA);
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, colour, 1, cv::LINE_AA);
}

}  // namespace

TextDetection ToTextDetectionMsg(const PlateReport& report) {
  const cv::Rect& box = report.box_px;
  if (box.x < 0 || box.y < 0 || box.width < 0 || box.height < 0) {
    std::ostringstream what;
    what << "ToTextDetectionMsg: box must have a non-negative corner and size, got " << box;
    throw std::invalid_argument(what.str());
  }
  TextDetection msg;
  msg.text = report.text;
  msg.confidence = static_cast<float>(report.confidence);
  msg.box.x_offset = static_cast<uint32_t>(box.x);
  msg.box.y_offset = static_cast<uint32_t>(box.y);
  msg.box.width = static_cast<uint32_t>(box.width);
  msg.box.height = static_cast<uint32_t>(box.height);
  msg.box.do_rectify = false;  // pixels of the raw image as published
  msg.bearing_rad = static_cast<float>(report.bearing_rad);
  msg.frame_count = static_cast<uint32_t>(std::max(0, report.voted_frame_count));
  msg.crossed_center = true;
  return msg;
}

TextDetectionArray ToTextDetectionArrayMsg(const std::vector<PlateReport>& reports, const std_msgs::Header& header) {
  TextDetectionArray msg;
  msg.header = header;
  msg.detections.reserve(reports.size());
  for (const PlateReport& report : reports) msg.detections.push_back(ToTextDetectionMsg(report));
  return msg;
}

PlateReport FromTextDetectionMsg(const TextDetection& msg, const ros::Time& stamp) {
  PlateReport report;
  report.text = msg.text;
  report.confidence = msg.confidence;
  report.box_px = cv::Rect(static_cast<int>(msg.box.x_offset), static_cast<int>(msg.box.y_offset),
                           static_cast<int>(msg.box.width), static_cast<int>(msg.box.height));
  report.bearing_rad = msg.bearing_rad;
  report.voted_frame_count = static_cast<int>(msg.frame_count);
  report.stamp_s = stamp.toSec();
  return report;
}

std::string ReadCameraGeometry(const sensor_msgs::CameraInfo& info, CameraGeometry* geometry) {
  std::ostringstream problem;
  if (info.width == 0 || info.height == 0) {
    problem << "width and height must be > 0, got " << info.width << "x" << info.height;
  } else if (!std::isfinite(info.K[0]) || info.K[0] <= 0.0) {
    problem << "K[0] (fx) must be finite and > 0, got " << info.K[0];
  } else if (!std::isfinite(info.K[2])) {
    problem << "K[2] (cx) must be finite, got " << info.K[2];
  } else {
    geometry->width_px = static_cast<int>(info.width);
    geometry->height_px = static_cast<int>(info.height);
    geometry->fx_px = info.K[0];
    geometry->cx_px = info.K[2];
  }
  return problem.str();
}

std::string ValidateCameraImage(const sensor_msgs::Image& image, const CameraGeometry& geometry) {
  std::ostringstream problem;
  const bool colour = image.encoding == enc::BGR8 || image.encoding == enc::RGB8;
  const size_t bytes_per_pixel = colour ? 3 : 1;
  if (image.width == 0 || image.height == 0) {
    problem << "empty image (" << image.width << "x" << image.height << ")";
  } else if (!colour && image.encoding != enc::MONO8) {
    problem << "unsupported encoding '" << image.encoding << "' (expected bgr8, rgb8 or mono8)";
  } else if (image.step < image.width * bytes_per_pixel ||
             image.data.size() < static_cast<size_t>(image.step) * image.height) {
    problem << "step " << image.step << " and data size " << image.data.size() << " too small for "
            << image.width << "x" << image.height << " " << image.encoding;
  } else if (static_cast<int>(image.width) != geometry.width_px ||
             static_cast<int>(image.height) != geometry.height_px) {
    problem << "image is " << image.width << "x" << image.height << " but camera_info says "
            << geometry.width_px << "x" << geometry.height_px;
  }
  return problem.str();
}

cv_bridge::CvImageConstPtr ToExtractorImage(const sensor_msgs::ImageConstPtr& image) {
  const std::string target = image->encoding == enc::MONO8 ? enc::MONO8 : enc::BGR8;
  return cv_bridge::toCvShare(image, target);
}

sensor_msgs::ImagePtr ToTextDebugImageMsg(const cv::Mat& image, const std_msgs::Header& header,
                                          const cv::Range& band_rows, double cx_px,
                                          const std::vector<PlateObservation>& observations,
                                          const std::vector<PlateReport>& reports) {
  if (image.empty() || (image.type() != CV_8UC3 && image.type() != CV_8UC1)) {
    throw std::invalid_argument("ToTextDebugImageMsg: expected a non-empty CV_8UC3 or CV_8UC1 image");
  }
  cv_bridge::CvImage debug(header, enc::BGR8);
  if (image.channels() == 1) {
    cv::cvtColor(image, debug.image, cv::COLOR_GRAY2BGR);
  } else {
    debug.image = image.clone();
  }
  cv::Mat& canvas = debug.image;
  for (const int row : {band_rows.start, band_rows.end - 1}) {
    cv::line(canvas, cv::Point(0, row), cv::Point(canvas.cols - 1, row), kBandColour, 1);
  }
  const int centre = static_cast<int>(std::lround(cx_px));
  cv::line(canvas, cv::Point(centre, 0), cv::Point(centre, canvas.rows - 1), kCentreColour, 1);
  for (const PlateObservation& o : observations) {
    const bool read = !o.text.empty();
    const cv::Scalar& colour = read ? kReadColour : kRejectedColour;
    cv::rectangle(canvas, o.box_px, colour, 1);
    Label(canvas, read ? o.text : "'" + o.raw_text + "'", o.box_px.tl() + cv::Point(0, -4), colour);
  }
  for (const PlateReport& r : reports) {
    cv::rectangle(canvas, r.box_px, kReportColour, 3);
    char label[96];
    std::snprintf(label, sizeof(label), "%s %+.3f rad", r.text.c_str(), r.bearing_rad);
    Label(canvas, label, r.box_px.br() + cv::Point(-r.box_px.width, 16), kReportColour);
  }
  return debug.toImageMsg();
}

}  // namespace doorplate_localization

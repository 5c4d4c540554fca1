// Conversions between the text extractor's types (text/plate_tracker.h) and ROS messages, and the checks
// of incoming camera messages done before an image reaches the extractor. Pure functions: no node handle,
// no clock. Units follow the messages: pixels of the full image (origin top-left, x right, y down), radians,
// seconds. Bearings are measured from the optical axis, positive towards the image's left (REP-103).
#pragma once

#include <string>
#include <vector>

#include <cv_bridge/cv_bridge.h>
#include <opencv2/core.hpp>
#include <ros/time.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <std_msgs/Header.h>

#include "doorplate_localization/TextDetection.h"
#include "doorplate_localization/TextDetectionArray.h"
#include "doorplate_localization/text/plate_tracker.h"

namespace doorplate_localization {

// A plate report as a TextDetection: text, confidence (the report's vote share × mean OCR confidence),
// box, bearing_rad, frame_count = voted_frame_count, crossed_center = true (a report is made when the
// plate crosses the centre line). Throws std::invalid_argument for a box with a negative corner or size
// (the extractor clips boxes to the image, so this means a broken report).
TextDetection ToTextDetectionMsg(const PlateReport& report);

// One array per processed image: `header` is the image's header (stamp, optical frame), one detection per
// report (often none).
TextDetectionArray ToTextDetectionArrayMsg(const std::vector<PlateReport>& reports, const std_msgs::Header& header);

// The reverse: text, confidence, box_px, bearing_rad, voted_frame_count and stamp_s = `stamp` (the array
// header's). The fields the message does not carry (vote_share, mean_confidence, observed_frame_count,
// track_id) are 0. (Consumers check a received detection with text_detection_conversions.h.)
PlateReport FromTextDetectionMsg(const TextDetection& msg, const ros::Time& stamp);

// What the extractor needs from camera_info: the image size and the pinhole focal length and principal
// point column (pixels), which turn image columns into bearings.
struct CameraGeometry {
  int width_px = 0;
  int height_px = 0;
  double fx_px = 0.0;
  double cx_px = 0.0;
};

// Returns "" and fills *geometry if `info` is usable, else the problem ("K[0] (fx) must be finite and > 0,
// got 0", "width and height must be > 0, got 0x480", ...). *geometry is left alone on error.
std::string ReadCameraGeometry(const sensor_msgs::CameraInfo& info, CameraGeometry* geometry);

// Returns "" if `image` can be given to the extractor, else the problem: an empty image, an encoding other
// than bgr8, rgb8 or mono8, a step or data size too small for width × height, or a size different from the
// camera_info's (`geometry`).
std::string ValidateCameraImage(const sensor_msgs::Image& image, const CameraGeometry& geometry);

// The image as the extractor takes it (CV_8UC3 BGR or CV_8UC1): bgr8 and mono8 are shared without a copy
// (the returned pointer keeps the message alive), rgb8 is converted to bgr8. Precondition:
// ValidateCameraImage(*image, ...) returned ""; throws cv_bridge::Exception otherwise.
cv_bridge::CvImageConstPtr ToExtractorImage(const sensor_msgs::ImageConstPtr& image);

// The extractor's debug view as a bgr8 image with `header`: the search band's rows (yellow lines), the
// centre line at cx_px (blue), every text box of the frame with its raw OCR reading (grey: rejected) or
// validated text (green), and the plates reported in this frame (red, thick, with the bearing).
// `image` is CV_8UC3 BGR or CV_8UC1; `band_rows` are image rows [start, end).
sensor_msgs::ImagePtr ToTextDebugImageMsg(const cv::Mat& image, const std_msgs::Header& header,
                                          const cv::Range& band_rows, double cx_px,
                                          const std::vector<PlateObservation>& observations,
                                          const std::vector<PlateReport>& reports);

}  // namespace doorplate_localization

// Synthetic camera images for the text tests: a grey wall with mild seeded noise, light doorplates with
// dark Hershey digits (what the simulator renders), and distractor blobs (door handle, frame edge).
#pragma once

#include <cstdint>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace doorplate_localization {
namespace test {

constexpr int kWidth = 640;
constexpr int kHeight = 480;
constexpr int kBandCenterY = 200;  // inside the default band rows [96, 298) of a 480-row image

// Grey wall (BGR) with Gaussian pixel noise of `noise_stddev` grey levels (seeded: deterministic).
inline cv::Mat MakeWall(int grey = 150, double noise_stddev = 2.0, std::uint32_t seed = 7) {
  cv::Mat wall(kHeight, kWidth, CV_8UC3, cv::Scalar(grey, grey, grey + 8));
  cv::Mat noise(wall.size(), CV_16SC3);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, noise_stddev);
  cv::Mat out;
  wall.convertTo(out, CV_16SC3);
  out += noise;
  out.convertTo(wall, CV_8UC3);
  return wall;
}

// Bounding box of `text` drawn with its baseline-centred box at `center` (what DrawPlate writes).
inline cv::Rect TextRect(const std::string& text, cv::Point center, double scale = 1.0, int thickness = 2) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, thickness, &baseline);
  return cv::Rect(center.x - size.width / 2, center.y - size.height / 2, size.width, size.height);
}

// A light plate with dark text centred at `center`; returns the plate rectangle.
inline cv::Rect DrawPlate(cv::Mat& image, const std::string& text, cv::Point center, double scale = 1.0,
                          int thickness = 2, cv::Scalar plate = cv::Scalar(240, 245, 245),
                          cv::Scalar ink = cv::Scalar(25, 20, 20)) {
  const cv::Rect t = TextRect(text, center, scale, thickness);
  const int margin_x = t.height * 3 / 4, margin_y = t.height / 2;
  const cv::Rect plate_rect(t.x - margin_x, t.y - margin_y, t.width + 2 * margin_x, t.height + 2 * margin_y);
  cv::rectangle(image, plate_rect, plate, cv::FILLED);
  cv::putText(image, text, cv::Point(t.x, t.y + t.height), cv::FONT_HERSHEY_SIMPLEX, scale, ink, thickness,
              cv::LINE_AA);
  return plate_rect;
}

// Non-text clutter in the band: a round door handle, a door frame edge and a dark square vent.
inline void DrawDistractors(cv::Mat& image, int center_y = kBandCenterY) {
  cv::circle(image, cv::Point(90, center_y), 14, cv::Scalar(40, 40, 40), cv::FILLED);
  cv::rectangle(image, cv::Rect(200, center_y - 80, 6, 160), cv::Scalar(60, 60, 60), cv::FILLED);
  cv::rectangle(image, cv::Rect(560, center_y - 25, 50, 50), cv::Scalar(30, 30, 30), cv::FILLED);
}

inline cv::Mat Grey(const cv::Mat& bgr) {
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  return grey;
}

}  // namespace test
}  // namespace doorplate_localization

#include "doorplate_localization/ros/text_detection_conversions.h"

#include <cmath>
#include <sstream>

namespace doorplate_localization {

bool IsPlateReport(const TextDetection& msg) { return msg.crossed_center && !msg.text.empty(); }

std::vector<std::string> CrossedPlateTexts(const TextDetectionArray& detections) {
  std::vector<std::string> texts;
  for (const TextDetection& d : detections.detections) {
    if (IsPlateReport(d)) texts.push_back(d.text);
  }
  return texts;
}

std::string ValidateTextDetection(const TextDetection& msg) {
  std::ostringstream problem;
  if (msg.text.empty()) {
    problem << "text is empty";
  } else if (!std::isfinite(msg.bearing_rad) || std::fabs(msg.bearing_rad) > M_PI / 2) {
    problem << "bearing_rad must be finite and within ±pi/2, got " << msg.bearing_rad;
  } else if (!(msg.confidence >= 0.0f && msg.confidence <= 1.0f)) {
    problem << "confidence must be in [0, 1], got " << msg.confidence;
  }
  return problem.str();
}

}  // namespace doorplate_localization

// Checks of received doorplate detections (doorplate_localization/TextDetection), shared by every consumer of
// text_detections: mapping, localization, go-to-room (library doorplate_ros_conversions; no OpenCV, no
// Tesseract). Bearings are radians from the optical axis, positive towards the image's left.
#pragma once

#include <string>
#include <vector>

#include "doorplate_localization/TextDetection.h"
#include "doorplate_localization/TextDetectionArray.h"

namespace doorplate_localization {

// Queue length of every text_detections publisher and subscriber. The extractor publishes one array per
// camera frame, nearly all empty; a consumer busy for a while (the SLAM's solve takes ~1 s, more on a loaded
// machine, and the sim may run at 5x) must not lose the one array that holds a plate report to the empty
// ones behind it. 200 arrays are 20 s of a 10 Hz camera and a few kB.
constexpr unsigned int kTextDetectionsQueueSize = 200;

// True for the text extractor's one report per plate: a detection that crossed the image centre with a
// non-empty text (an empty text is a rejected reading). Consumers use only these.
bool IsPlateReport(const TextDetection& msg);

// The room numbers of the plate reports (IsPlateReport) of one array, in order.
std::vector<std::string> CrossedPlateTexts(const TextDetectionArray& detections);

// Returns "" if a received detection is usable, else what is wrong with it: "text is empty",
// "bearing_rad must be finite and within ±pi/2, got nan", "confidence must be in [0, 1], got 1.5".
std::string ValidateTextDetection(const TextDetection& msg);

}  // namespace doorplate_localization

// libFuzzer target: the rosbag reading of doorplate_map_bag and doorplate_mission_report
// (src/ros/tools/bag_reader.h: ReadBagTf, ReadBag; mission_bags.h: ReadRecordedRun). The input is the bag file.
// Reads it as doorplate_map_bag does (all tf, then the scans and detections, each instantiated as its type)
// and as the mission report does (every topic it knows). Any file must read or throw BagReadError. Our code
// and roscpp's message deserializer (templates, compiled here) are instrumented; rosbag's library is not, so
// this finds what rosbag's parser does to a tool as well as our own errors.
#include <cstddef>
#include <cstdint>
#include <string>

#include <sensor_msgs/LaserScan.h>

#include "bag_reader.h"
#include "doorplate_localization/TextDetectionArray.h"
#include "fuzz_temp_dir.h"
#include "mission_bags.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace doorplate_localization;
  const std::string path = fuzz::WriteTempFile("fuzz.bag", reinterpret_cast<const char*>(data), size);
  try {
    const auto tf = ReadBagTf(path);
    (void)tf->allFramesAsString();
    ReadBag(path, {"/scan", "/text_detections"}, [](const rosbag::MessageInstance& m, const BagPosition&) {
      if (const auto scan = InstantiateChecked<sensor_msgs::LaserScan>(m)) {
        (void)scan->ranges.size();
      } else if (const auto array = InstantiateChecked<TextDetectionArray>(m)) {
        for (const TextDetection& d : array->detections) (void)d.text.size();
      }
    });
  } catch (const BagReadError&) {
  }
  try {
    (void)ReadRecordedRun(path);
  } catch (const BagReadError&) {
  }
  return 0;
}

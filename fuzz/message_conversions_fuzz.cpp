// libFuzzer target: the message conversions every nodelet runs on what arrives on its topics
// (src/ros/*conversions*.cpp): sensor_msgs/LaserScan (ValidateScan, ToLocalizationScan, ToMappingScan),
// nav_msgs/OccupancyGrid (FromOccupancyGridMsg and back), doorplate_localization/TextDetectionArray
// (ToPlateReadings, ToPlateSighting, CrossedPlateTexts) and the initial pose (FromInitialPoseMsg).
// The first byte picks the message; the rest fills its fields (FuzzedDataProvider: any float bit pattern,
// NaN, ±inf, vectors longer than the limits), and the message then goes through ros::serialization (out
// and back in, as a subscriber receives it). Raw bytes are not deserialized: roscpp resizes a vector to
// its length prefix before it checks that the bytes are there (up to 4 G elements), ROS's behaviour and
// not what is tested here.
// Any message must convert or be refused with a reason, and what a conversion accepts the core must
// accept too: a scan ValidateScan passes is one ValidateLocalizationScan passes, a SLAM scan has ranges
// and a finite, non-zero increment, a reading (of either converter) passes
// ValidatePlateReading, an accepted grid has width x height cells and converts back and forth, an
// accepted initial pose is within limits::kMaxCoordinateM with a covariance TextAmcl::Initialize takes.
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>
#include <ros/serialization.h>

#include "doorplate_localization/TextDetectionArray.h"
#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/maps/occupancy_grid.h"
#include "doorplate_localization/mcl/localization_scan.h"
#include "doorplate_localization/sensors/plate_reading.h"
#include "doorplate_localization/ros/amcl_conversions.h"
#include "doorplate_localization/ros/map_conversions.h"
#include "doorplate_localization/ros/scan_conversions.h"
#include "doorplate_localization/ros/slam_conversions.h"
#include "doorplate_localization/ros/text_detection_conversions.h"
#include "doorplate_localization/slam/text_slam.h"

namespace dl = doorplate_localization;

namespace {

// Aborts (a libFuzzer crash) naming the broken invariant.
#define Check(ok)                                                                   \
  do {                                                                              \
    if (!(ok)) {                                                                    \
      std::fprintf(stderr, "message_conversions_fuzz: line %d: %s\n", __LINE__, #ok); \
      std::abort();                                                                 \
    }                                                                               \
  } while (false)

// A number: the raw bits (any NaN, ±inf, denormal), a special value, a short decimal or any finite one.
double Number(FuzzedDataProvider& p) {
  static const double kSpecial[] = {0.0, -0.0, NAN, INFINITY, -INFINITY, 1e300, -1e300, 1e-300,
                                    std::numeric_limits<double>::max(), std::numeric_limits<float>::max(),
                                    1e6, 1e-6, M_PI, 2 * M_PI, 0.0174533, 100000.0};
  switch (p.ConsumeIntegralInRange<int>(0, 3)) {
    case 0: {
      const std::uint64_t bits = p.ConsumeIntegral<std::uint64_t>();
      double value;
      std::memcpy(&value, &bits, sizeof(value));
      return value;
    }
    case 1:
      return kSpecial[p.ConsumeIntegralInRange<size_t>(0, sizeof(kSpecial) / sizeof(kSpecial[0]) - 1)];
    case 2:
      return p.ConsumeIntegralInRange<int>(-2000, 2000) / 100.0;
    default:
      return p.ConsumeFloatingPoint<double>();
  }
}

float Float(FuzzedDataProvider& p) { return static_cast<float>(Number(p)); }

// A vector length: short ones mostly, sometimes one past a limit (kMaxScanBeams, a grid's cells).
size_t Length(FuzzedDataProvider& p) {
  switch (p.ConsumeIntegralInRange<int>(0, 7)) {
    case 0:
      return p.ConsumeIntegralInRange<size_t>(0, 200'001);
    default:
      return p.ConsumeIntegralInRange<size_t>(0, 400);
  }
}

// `n` values: those the input still holds, then the input's values repeated (a long vector from few bytes).
template <typename T, typename Make>
std::vector<T> Values(FuzzedDataProvider& p, size_t n, Make make) {
  std::vector<T> values;
  values.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    if (p.remaining_bytes() == 0 || i >= 2000) {
      values.push_back(values.empty() ? T{} : values[i % values.size()]);
    } else {
      values.push_back(make(p));
    }
  }
  return values;
}

std_msgs::Header Header(FuzzedDataProvider& p) {
  std_msgs::Header h;
  h.seq = p.ConsumeIntegral<std::uint32_t>();
  h.stamp.sec = p.ConsumeIntegral<std::uint32_t>();
  h.stamp.nsec = p.ConsumeIntegralInRange<std::uint32_t>(0, 999'999'999);
  h.frame_id = p.ConsumeRandomLengthString(40);
  return h;
}

// The message as a subscriber receives it: serialized and deserialized by roscpp.
template <typename M>
M ThroughTheWire(const M& msg) {
  const uint32_t size = ros::serialization::serializationLength(msg);
  std::vector<uint8_t> buffer(size);
  ros::serialization::OStream out(buffer.data(), size);
  ros::serialization::serialize(out, msg);
  M received;
  ros::serialization::IStream in(buffer.data(), size);
  ros::serialization::deserialize(in, received);
  return received;
}

geometry_msgs::Transform Transform(FuzzedDataProvider& p) {
  geometry_msgs::Transform t;
  t.translation.x = Number(p), t.translation.y = Number(p), t.translation.z = Number(p);
  if (p.ConsumeBool()) {  // a yaw about z (a level camera or laser), or any quaternion
    const double yaw = Number(p);
    t.rotation.z = std::sin(yaw / 2), t.rotation.w = std::cos(yaw / 2);
  } else {
    t.rotation.x = Number(p), t.rotation.y = Number(p), t.rotation.z = Number(p), t.rotation.w = Number(p);
  }
  return t;
}

void FuzzScan(FuzzedDataProvider& p) {
  sensor_msgs::LaserScan msg;
  msg.header = Header(p);
  msg.angle_min = Float(p), msg.angle_max = Float(p), msg.angle_increment = Float(p);
  msg.time_increment = Float(p), msg.scan_time = Float(p);
  msg.range_min = Float(p), msg.range_max = Float(p);
  msg.ranges = Values<float>(p, Length(p), Float);
  msg.intensities = Values<float>(p, p.ConsumeIntegralInRange<size_t>(0, 8), Float);
  const geometry_msgs::Transform mounting_tf = Transform(p);
  const double max_range_m = Number(p);
  const int min_valid_beams = p.ConsumeIntegralInRange<int>(0, 400);
  msg = ThroughTheWire(msg);

  const std::string problem = dl::ValidateScan(msg);
  if (problem.empty()) {
    Check(msg.ranges.size() <= dl::limits::kMaxScanBeams);
    // What the localizer's nodelet takes, its core must take (the laser pose comes from tf, here a level one).
    Check(dl::ValidateLocalizationScan(dl::ToLocalizationScan(msg, {0.1, 0.0, 0.0})).empty());
  }
  dl::LaserMounting mounting;
  if (!dl::ToLaserMounting(mounting_tf, &mounting).empty()) mounting = {};
  dl::LaserScan scan;
  if (dl::ToMappingScan(msg, mounting, max_range_m, min_valid_beams, &scan).empty()) {
    Check(problem.empty());  // the SLAM path never takes a scan ValidateScan refuses
    Check(!scan.ranges_m.empty() && scan.ranges_m.size() == msg.ranges.size());
    Check(std::isfinite(scan.angle_min_rad) && std::isfinite(scan.angle_increment_rad) &&
          scan.angle_increment_rad != 0.0);
    Check(std::isfinite(scan.laser_pose.x_m) && std::isfinite(scan.laser_pose.y_m) &&
          std::isfinite(scan.laser_pose.theta_rad));
    for (float r : scan.ranges_m) Check(std::isnan(r) || r >= 0.0f);  // NaN: skipped; +inf: no echo
  }
}

void FuzzGrid(FuzzedDataProvider& p) {
  nav_msgs::OccupancyGrid msg;
  msg.header = Header(p);
  msg.info.resolution = Float(p);
  const bool absurd = p.ConsumeIntegralInRange<int>(0, 15) == 0;
  msg.info.width = absurd ? p.ConsumeIntegral<std::uint32_t>() : p.ConsumeIntegralInRange<std::uint32_t>(0, 64);
  msg.info.height = absurd ? p.ConsumeIntegral<std::uint32_t>() : p.ConsumeIntegralInRange<std::uint32_t>(0, 64);
  msg.info.origin.position.x = Number(p), msg.info.origin.position.y = Number(p);
  msg.info.origin.position.z = Number(p);
  msg.info.origin.orientation.z = Number(p), msg.info.origin.orientation.w = Number(p);
  const std::uint64_t cells = std::uint64_t{msg.info.width} * msg.info.height;
  size_t n = cells <= 8192 ? static_cast<size_t>(cells) : Length(p);
  if (p.ConsumeIntegralInRange<int>(0, 7) == 0) n = Length(p);  // a data size that does not match
  msg.data = Values<std::int8_t>(p, n, [](FuzzedDataProvider& q) { return q.ConsumeIntegral<std::int8_t>(); });
  msg = ThroughTheWire(msg);

  dl::OccupancyGrid grid;
  if (!dl::FromOccupancyGridMsg(msg, &grid).empty()) return;
  Check(grid.width > 0 && grid.height > 0 &&
        static_cast<std::uint64_t>(grid.width) * grid.height == grid.cells.size() &&
        grid.cells.size() <= static_cast<std::uint64_t>(dl::limits::kMaxMapCells));
  Check(std::isfinite(grid.resolution_m) && grid.resolution_m > 0 && std::isfinite(grid.origin.x_m) &&
        std::isfinite(grid.origin.y_m) && std::isfinite(grid.origin.theta_rad));
  // What is accepted is published again as a map message (the localizer's latched `map`) and taken back.
  dl::OccupancyGrid again;
  Check(dl::FromOccupancyGridMsg(dl::ToOccupancyGridMsg(grid, "map", ros::Time(1, 0)), &again).empty());
  Check(again.width == grid.width && again.height == grid.height && again.cells == grid.cells);
}

void FuzzDetections(FuzzedDataProvider& p) {
  doorplate_localization::TextDetectionArray msg;
  msg.header = Header(p);
  const size_t n = p.ConsumeIntegralInRange<size_t>(0, 12);
  for (size_t i = 0; i < n; ++i) {
    doorplate_localization::TextDetection d;
    d.text = p.ConsumeIntegralInRange<int>(0, 15) == 0 ? std::string(p.ConsumeIntegralInRange<size_t>(0, 100'000), '4')
                                                        : p.ConsumeRandomLengthString(80);
    d.confidence = Float(p);
    d.box.x_offset = p.ConsumeIntegral<std::uint32_t>(), d.box.y_offset = p.ConsumeIntegral<std::uint32_t>();
    d.box.width = p.ConsumeIntegral<std::uint32_t>(), d.box.height = p.ConsumeIntegral<std::uint32_t>();
    d.bearing_rad = Float(p);
    d.frame_count = p.ConsumeIntegral<std::uint32_t>();
    d.crossed_center = p.ConsumeBool();
    msg.detections.push_back(d);
  }
  const geometry_msgs::Transform camera_tf = Transform(p);
  msg = ThroughTheWire(msg);

  dl::CameraAxis camera;
  if (!dl::ToCameraAxis(camera_tf, &camera).empty()) camera = {M_PI / 2, 1.0};
  Check(std::isfinite(camera.yaw_rad) && (camera.bearing_sign == 1.0 || camera.bearing_sign == -1.0));
  std::vector<std::string> problems;
  for (const dl::PlateReading& r : dl::ToPlateReadings(msg, camera, &problems)) {
    Check(dl::ValidatePlateReading(r).empty());
    Check(r.bearing_rad > -M_PI - 1e-9 && r.bearing_rad <= M_PI + 1e-9);
  }
  for (const std::string& problem : problems) Check(problem.size() < 1000);  // quotes at most a bounded text
  (void)dl::CrossedPlateTexts(msg);
  for (const doorplate_localization::TextDetection& d : msg.detections) {
    const std::string problem = dl::ValidateTextDetection(d);
    Check(problem.size() < 1000);
    std::string why_not;
    const auto sighting = dl::ToPlateSighting(d, camera, &why_not);
    if (!sighting) continue;
    Check(problem.empty());
    Check(dl::ValidatePlateReading(*sighting).empty());  // what the mapping session checks before it uses one
  }
}

void FuzzInitialPose(FuzzedDataProvider& p) {
  geometry_msgs::PoseWithCovarianceStamped msg;
  msg.header = Header(p);
  if (p.ConsumeBool()) msg.header.frame_id = "map";
  auto& pose = msg.pose.pose;
  pose.position.x = Number(p), pose.position.y = Number(p), pose.position.z = Number(p);
  if (p.ConsumeBool()) {
    const double yaw = Number(p);
    pose.orientation.z = std::sin(yaw / 2), pose.orientation.w = std::cos(yaw / 2);
  } else {
    pose.orientation.x = Number(p), pose.orientation.y = Number(p);
    pose.orientation.z = Number(p), pose.orientation.w = Number(p);
  }
  for (double& c : msg.pose.covariance) c = p.ConsumeBool() ? 0.0 : Number(p);
  msg = ThroughTheWire(msg);

  dl::Pose2D mean;
  Eigen::Matrix3d covariance;
  if (!dl::FromInitialPoseMsg(msg, "map", &mean, &covariance).empty()) return;
  Check(dl::limits::CheckCoordinate(mean.x_m).empty() && dl::limits::CheckCoordinate(mean.y_m).empty() &&
        std::isfinite(mean.theta_rad));
  // What TextAmcl::Initialize checks before it samples from it.
  Check(covariance.allFinite() && covariance.isApprox(covariance.transpose(), 1e-9));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider p(data, size);
  switch (p.ConsumeIntegralInRange<int>(0, 3)) {
    case 0: FuzzScan(p); break;
    case 1: FuzzGrid(p); break;
    case 2: FuzzDetections(p); break;
    default: FuzzInitialPose(p); break;
  }
  return 0;
}

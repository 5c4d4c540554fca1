#include "scan_tf_filter.h"

#include <cstdio>
#include <utility>

#include "doorplate_localization/common/limits.h"
#include "doorplate_localization/ros/scan_conversions.h"
#include "doorplate_localization/ros/tf_lookup.h"

namespace doorplate_localization {

std::string DescribeScanTfDrop(const sensor_msgs::LaserScan& scan, const std::string& target_frame,
                               uint32_t queue_size, tf2_ros::FilterFailureReason reason) {
  if (reason == tf2_ros::filter_failure_reasons::EmptyFrameID) return "header.frame_id is empty";
  char stamp[64];
  std::snprintf(stamp, sizeof(stamp), "%.3f", scan.header.stamp.toSec());
  const std::string problem = "no tf from '" + limits::TruncateForLog(scan.header.frame_id) + "' to '" +
                              target_frame + "' at the scan's stamp " + stamp + " s: ";
  if (reason == tf2_ros::filter_failure_reasons::OutTheBack) return problem + "older than tf's cache holds";
  return problem + "none came while " + std::to_string(queue_size) +
         " newer scans waited, or tf moved past that stamp";
}

std::optional<ScanPoses> LookupScanPoses(const tf2_ros::Buffer& buffer, const std::string& odom_frame,
                                         const std::string& base_frame, const sensor_msgs::LaserScan& scan,
                                         std::string* problem) {
  const std::optional<Pose2D> laser_in_base =
      LookupPlanarPose(buffer, base_frame, scan.header.frame_id, ros::Time(0), 0.0, problem);
  if (!laser_in_base) return std::nullopt;
  const std::optional<Pose2D> base_in_odom =
      LookupPlanarPose(buffer, odom_frame, base_frame, scan.header.stamp, 0.0, problem);
  if (!base_in_odom) return std::nullopt;
  return ScanPoses{*laser_in_base, *base_in_odom};
}

ScanTfFilter::ScanTfFilter(tf2_ros::Buffer& buffer, const std::string& target_frame, uint32_t queue_size,
                           ros::CallbackQueueInterface* queue, ScanCallback on_scan, DropCallback on_drop)
    : target_frame_(target_frame),
      queue_size_(queue_size),
      on_drop_(std::move(on_drop)),
      filter_(buffer, target_frame, queue_size, queue) {
  filter_.registerCallback(
      [on_scan = std::move(on_scan)](const sensor_msgs::LaserScan::ConstPtr& scan) { on_scan(scan); });
  filter_.registerFailureCallback(
      [this](const sensor_msgs::LaserScan::ConstPtr& scan, tf2_ros::FilterFailureReason reason) {
        on_drop_(scan, DescribeScanTfDrop(*scan, target_frame_, queue_size_, reason),
                 reason == tf2_ros::filter_failure_reasons::EmptyFrameID);
      });
}

void ScanTfFilter::Subscribe(ros::NodeHandle& nh, const std::string& topic) {
  topic_ = nh.resolveName(topic);
  subscriber_ = std::make_unique<message_filters::Subscriber<sensor_msgs::LaserScan>>();
  subscriber_->registerCallback(&ScanTfFilter::OnMessage, this);
  subscriber_->subscribe(nh, topic, queue_size_);
}

void ScanTfFilter::OnMessage(const ros::MessageEvent<const sensor_msgs::LaserScan>& event) {
  const std::string problem = ValidateScan(*event.getConstMessage());
  if (!problem.empty()) return on_drop_(event.getConstMessage(), problem, /*broken=*/true);
  filter_.add(event);
}

void ScanTfFilter::Add(const sensor_msgs::LaserScan::ConstPtr& scan) {
  const std::string problem = ValidateScan(*scan);
  if (!problem.empty()) return on_drop_(scan, problem, /*broken=*/true);
  filter_.add(scan);
}

}  // namespace doorplate_localization

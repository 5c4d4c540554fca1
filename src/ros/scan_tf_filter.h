// The scan input of Text AMCL: ScanTfFilter refuses a broken scan at once (ValidateScan) and hands on every
// other one only when tf can transform its frame into odom at its stamp (a tf2_ros::MessageFilter behind a
// message_filters::Subscriber, the way amcl queues scans), so a scan that arrives before its odometry waits
// for it instead of being refused after a fixed tf wait (issue 19); one tf never gives is dropped with
// DescribeScanTfDrop's reason. LookupScanPoses then reads what the filter waited for. Library
// doorplate_localization_nodelet. Units: metres, radians, seconds.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <message_filters/subscriber.h>
#include <ros/callback_queue_interface.h>
#include <ros/node_handle.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/message_filter.h>

#include "doorplate_localization/common/geometry2d.h"

namespace doorplate_localization {

// Scans that may wait for tf: amcl's queue (10 s of a 10 Hz laser).
inline constexpr uint32_t kScanTfQueueSize = 100;

// Why the filter dropped `scan`, naming the frames and the stamp: "no tf from '<frame>' to '<target>' at the
// scan's stamp <s> s: " and, for OutTheBack, "older than tf's cache holds", else (pushed out of the queue, or
// tf's data moved past the stamp without it) "none came while <queue_size> newer scans waited, or tf moved
// past that stamp"; an empty frame: ValidateScan's "header.frame_id is empty". The frame is quoted at most
// limits::kMaxLoggedTextBytes long.
std::string DescribeScanTfDrop(const sensor_msgs::LaserScan& scan, const std::string& target_frame,
                               uint32_t queue_size, tf2_ros::FilterFailureReason reason);

// A scan's tf: its laser's mounting (base <- the scan's frame, the latest) and the odometry at its stamp
// (odom <- base), both looked up without waiting (a ScanTfFilter on odom_frame waited for them). nullopt with
// *problem set (LookupPlanarPose's "no tf from '<source>' to '<target>': <tf2's reason>") otherwise.
struct ScanPoses {
  Pose2D laser_in_base;
  Pose2D base_in_odom;
};
std::optional<ScanPoses> LookupScanPoses(const tf2_ros::Buffer& buffer, const std::string& odom_frame,
                                         const std::string& base_frame, const sensor_msgs::LaserScan& scan,
                                         std::string* problem);

class ScanTfFilter {
 public:
  using ScanCallback = std::function<void(const sensor_msgs::LaserScan::ConstPtr& scan)>;
  // `problem`: ValidateScan's (`broken` true: the scan itself is unusable) or DescribeScanTfDrop's.
  using DropCallback =
      std::function<void(const sensor_msgs::LaserScan::ConstPtr& scan, const std::string& problem, bool broken)>;

  // Valid scans wait (at most `queue_size` of them) until `buffer` has `target_frame` <- the scan's frame at
  // their stamp. The callbacks run on `queue` (a nodelet's: its node handle's getCallbackQueue()); with a null
  // queue, inside Add() or the buffer's setTransform() that made the scan transformable.
  ScanTfFilter(tf2_ros::Buffer& buffer, const std::string& target_frame, uint32_t queue_size,
               ros::CallbackQueueInterface* queue, ScanCallback on_scan, DropCallback on_drop);
  ScanTfFilter(const ScanTfFilter&) = delete;
  ScanTfFilter& operator=(const ScanTfFilter&) = delete;

  // Subscribes `topic` on `nh` (subscriber queue: queue_size too); topic() becomes its resolved name.
  void Subscribe(ros::NodeHandle& nh, const std::string& topic);
  // One scan in, as the subscription puts each message in (a broken one is dropped here, on this thread).
  void Add(const sensor_msgs::LaserScan::ConstPtr& scan);

  const std::string& topic() const { return topic_; }  // "" before Subscribe

 private:
  void OnMessage(const ros::MessageEvent<const sensor_msgs::LaserScan>& event);

  std::string target_frame_;
  uint32_t queue_size_;
  DropCallback on_drop_;
  std::string topic_;
  tf2_ros::MessageFilter<sensor_msgs::LaserScan> filter_;
  // Made by Subscribe (a message_filters::Subscriber needs ros::init); last, so it is unsubscribed first.
  std::unique_ptr<message_filters::Subscriber<sensor_msgs::LaserScan>> subscriber_;
};

}  // namespace doorplate_localization

// The scan input of Text AMCL and the mapping nodelet: ScanTfFilter refuses a broken scan at once
// (ValidateScan) and hands on every other one only when tf can transform its frame into odom at its stamp,
// so a scan that arrives before its odometry waits for it instead of being refused after a fixed tf wait
// (issue 19), the way amcl queues scans; one tf never gives is dropped with DescribeScanTfDrop's reason.
// LookupScanPoses then reads what the filter waited for. Library doorplate_ros_conversions. Units: metres,
// radians, seconds.
// Why not tf2_ros::MessageFilter (which this used before): its add() registers a transformable request
// before it files the message, and the tf listener's thread can answer the request in between; the answer
// finds no message and is lost, and the scan waits for ever without a failure callback. Replaying a
// mapping bag lost 3-4 of 2690 scans so, silently, at random. Here the waiting scans are checked again
// after every tf change (on the nodelet's queue), in arrival order.
#pragma once

#include <atomic>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <message_filters/subscriber.h>
#include <ros/callback_queue_interface.h>
#include <ros/node_handle.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/message_filter.h>  // tf2_ros::FilterFailureReason

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
  // their stamp. The callbacks run on `queue` (a nodelet's: its node handle's getCallbackQueue()), in the
  // order the scans came; with a null queue, inside Add() or the buffer's setTransform() that made the scan
  // transformable.
  ScanTfFilter(tf2_ros::Buffer& buffer, const std::string& target_frame, uint32_t queue_size,
               ros::CallbackQueueInterface* queue, ScanCallback on_scan, DropCallback on_drop);
  ~ScanTfFilter();
  ScanTfFilter(const ScanTfFilter&) = delete;
  ScanTfFilter& operator=(const ScanTfFilter&) = delete;

  // Subscribes `topic` on `nh` (subscriber queue: queue_size too); topic() becomes its resolved name.
  void Subscribe(ros::NodeHandle& nh, const std::string& topic);
  // One scan in, as the subscription puts each message in (a broken one is dropped here, on this thread).
  void Add(const sensor_msgs::LaserScan::ConstPtr& scan);

  const std::string& topic() const { return topic_; }  // "" before Subscribe

 private:
  void OnMessage(const ros::MessageEvent<const sensor_msgs::LaserScan>& event);
  // tf changed (the listener's thread): Check() on the queue, once per batch of changes.
  void OnTfChanged();
  // Hands on every waiting scan tf can now transform and drops those it never will, in arrival order.
  void Check();

  tf2_ros::Buffer& buffer_;
  std::string target_frame_;
  uint32_t queue_size_;
  ros::CallbackQueueInterface* queue_;
  ScanCallback on_scan_;
  DropCallback on_drop_;
  std::string topic_;
  std::mutex mutex_;  // guards waiting_
  std::deque<sensor_msgs::LaserScan::ConstPtr> waiting_;
  std::atomic<bool> check_queued_{false};
  boost::signals2::connection tf_changed_;
  // Made by Subscribe (a message_filters::Subscriber needs ros::init); last, so it is unsubscribed first.
  std::unique_ptr<message_filters::Subscriber<sensor_msgs::LaserScan>> subscriber_;
};

}  // namespace doorplate_localization

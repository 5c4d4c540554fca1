#include "scan_tf_filter.h"

#include <cstdio>
#include <utility>
#include <vector>

#include <boost/make_shared.hpp>
#include <ros/callback_queue_interface.h>

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

namespace {

// Check() of a ScanTfFilter, as one callback on its queue.
class CheckCallback : public ros::CallbackInterface {
 public:
  explicit CheckCallback(std::function<void()> check) : check_(std::move(check)) {}
  CallResult call() override {
    check_();
    return Success;
  }

 private:
  std::function<void()> check_;
};

}  // namespace

ScanTfFilter::ScanTfFilter(tf2_ros::Buffer& buffer, const std::string& target_frame, uint32_t queue_size,
                           ros::CallbackQueueInterface* queue, ScanCallback on_scan, DropCallback on_drop)
    : buffer_(buffer),
      target_frame_(target_frame),
      queue_size_(queue_size),
      queue_(queue),
      on_scan_(std::move(on_scan)),
      on_drop_(std::move(on_drop)) {
  tf_changed_ = buffer_._addTransformsChangedListener([this] { OnTfChanged(); });
}

ScanTfFilter::~ScanTfFilter() {
  buffer_._removeTransformsChangedListener(tf_changed_);  // no new Check() is queued after this
  if (queue_ != nullptr) queue_->removeByID(reinterpret_cast<uint64_t>(this));
  subscriber_.reset();
}

void ScanTfFilter::Subscribe(ros::NodeHandle& nh, const std::string& topic) {
  topic_ = nh.resolveName(topic);
  subscriber_ = std::make_unique<message_filters::Subscriber<sensor_msgs::LaserScan>>();
  subscriber_->registerCallback(&ScanTfFilter::OnMessage, this);
  subscriber_->subscribe(nh, topic, queue_size_);
}

void ScanTfFilter::OnMessage(const ros::MessageEvent<const sensor_msgs::LaserScan>& event) {
  Add(event.getConstMessage());
}

void ScanTfFilter::Add(const sensor_msgs::LaserScan::ConstPtr& scan) {
  const std::string problem = ValidateScan(*scan);
  if (!problem.empty()) return on_drop_(scan, problem, /*broken=*/true);
  sensor_msgs::LaserScan::ConstPtr pushed_out;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    waiting_.push_back(scan);
    if (queue_size_ != 0 && waiting_.size() > queue_size_) {
      pushed_out = waiting_.front();
      waiting_.pop_front();
    }
  }
  if (pushed_out) {
    on_drop_(pushed_out, DescribeScanTfDrop(*pushed_out, target_frame_, queue_size_, tf2_ros::filter_failure_reasons::Unknown),
             false);
  }
  Check();
}

void ScanTfFilter::OnTfChanged() {
  if (queue_ == nullptr) return Check();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (waiting_.empty()) return;
  }
  if (check_queued_.exchange(true)) return;  // one queued Check() serves every change before it runs
  queue_->addCallback(boost::make_shared<CheckCallback>([this] {
                        check_queued_ = false;
                        Check();
                      }),
                      reinterpret_cast<uint64_t>(this));
}

void ScanTfFilter::Check() {
  // (scan, ready) in arrival order; ready false: dropped, older than tf's cache holds.
  std::vector<std::pair<sensor_msgs::LaserScan::ConstPtr, bool>> decided;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = waiting_.begin(); it != waiting_.end();) {
      const sensor_msgs::LaserScan& scan = **it;
      bool ready = buffer_.canTransform(target_frame_, scan.header.frame_id, scan.header.stamp);
      bool too_old = false;
      if (!ready) {
        try {  // as tf2's own rule: a stamp more than the cache length before tf's newest data never comes
          const ros::Time latest = buffer_.lookupTransform(target_frame_, scan.header.frame_id, ros::Time(0)).header.stamp;
          too_old = !latest.isZero() && scan.header.stamp + buffer_.getCacheLength() < latest;
        } catch (const tf2::TransformException&) {  // frames not (yet) connected: wait
        }
      }
      if (ready || too_old) {
        decided.emplace_back(*it, ready);
        it = waiting_.erase(it);
      } else {
        ++it;
      }
    }
  }
  for (const auto& [scan, ready] : decided) {
    if (ready) {
      on_scan_(scan);
    } else {
      on_drop_(scan, DescribeScanTfDrop(*scan, target_frame_, queue_size_, tf2_ros::filter_failure_reasons::OutTheBack),
               false);
    }
  }
}

}  // namespace doorplate_localization

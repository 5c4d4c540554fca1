// Tests of the scan input (scan_tf_filter.h) on a tf2 buffer filled by hand (no ROS master): scans are held
// until tf has their odometry, broken ones are refused at once, and what is dropped says why, naming frames.
#include "scan_tf_filter.h"

#include <gtest/gtest.h>
#include <ros/callback_queue.h>

#include <cmath>
#include <string>
#include <vector>

#include "doorplate_localization/ros/pose_conversions.h"

namespace doorplate_localization {
namespace {

class ScanTfFilterTest : public testing::Test {
 protected:
  void SetUp() override {
    ros::Time::init();
    Add(Pose2D{0.2, 0.0, 0.0}, "base_link", "laser", 0.0, /*is_static=*/true);
  }
  void Add(const Pose2D& pose, const std::string& parent, const std::string& child, double stamp_s,
           bool is_static = false) {
    buffer_.setTransform(ToTransformStampedMsg(pose, parent, child, ros::Time(stamp_s)), "test", is_static);
  }
  // A valid 360-beam scan in `frame` at `stamp_s`.
  static sensor_msgs::LaserScan::ConstPtr Scan(double stamp_s, const std::string& frame = "laser") {
    sensor_msgs::LaserScan::Ptr scan(new sensor_msgs::LaserScan);
    scan->header.frame_id = frame;
    scan->header.stamp = ros::Time(stamp_s);
    scan->angle_min = static_cast<float>(-M_PI);
    scan->angle_increment = static_cast<float>(2 * M_PI / 360);
    scan->angle_max = static_cast<float>(-M_PI + 359 * (2 * M_PI / 360));
    scan->range_min = 0.1f;
    scan->range_max = 10.0f;
    scan->ranges.assign(360, 2.0f);
    return scan;
  }
  struct Drop {
    double stamp_s;
    std::string problem;
    bool broken;
  };
  ScanTfFilter MakeFilter(uint32_t queue_size) {
    return ScanTfFilter(
        buffer_, "odom", queue_size, /*queue=*/nullptr,
        [this](const sensor_msgs::LaserScan::ConstPtr& s) { delivered_.push_back(s->header.stamp.toSec()); },
        [this](const sensor_msgs::LaserScan::ConstPtr& s, const std::string& problem, bool broken) {
          drops_.push_back({s->header.stamp.toSec(), problem, broken});
        });
  }
  tf2_ros::Buffer buffer_{ros::Duration(10.0)};
  std::vector<double> delivered_;
  std::vector<Drop> drops_;
};

TEST_F(ScanTfFilterTest, HoldsAScanUntilTfHasTheOdometryAtItsStampThenHandsItOn) {
  Add(Pose2D{0.0, 0.0, 0.0}, "odom", "base_link", 10.0);
  ScanTfFilter filter = MakeFilter(kScanTfQueueSize);
  filter.Add(Scan(10.0));  // tf has it: on at once
  filter.Add(Scan(10.1));  // odometry not yet at 10.1 s: waits
  EXPECT_EQ(delivered_, (std::vector<double>{10.0}));
  Add(Pose2D{0.1, 0.0, 0.0}, "odom", "base_link", 10.2);
  EXPECT_EQ(delivered_, (std::vector<double>{10.0, 10.1}));
  EXPECT_TRUE(drops_.empty());
  // What the filter waited for is there without waiting: the mount and the odometry interpolated at 10.1 s.
  std::string problem;
  const std::optional<ScanPoses> poses = LookupScanPoses(buffer_, "odom", "base_link", *Scan(10.1), &problem);
  ASSERT_TRUE(poses.has_value()) << problem;
  EXPECT_NEAR(poses->laser_in_base.x_m, 0.2, 1e-9);
  EXPECT_NEAR(poses->base_in_odom.x_m, 0.05, 1e-9);
}

// A nodelet's filter: tf changes arrive on the listener's thread and the waiting scans are checked on the
// nodelet's queue, in the order they came (one queued check for many changes).
TEST_F(ScanTfFilterTest, OnANodeletsQueueWaitingScansGoOnWhenTheQueueRunsInArrivalOrder) {
  Add(Pose2D{0.0, 0.0, 0.0}, "odom", "base_link", 10.0);
  ros::CallbackQueue queue;
  ScanTfFilter filter(
      buffer_, "odom", kScanTfQueueSize, &queue,
      [this](const sensor_msgs::LaserScan::ConstPtr& s) { delivered_.push_back(s->header.stamp.toSec()); },
      [this](const sensor_msgs::LaserScan::ConstPtr& s, const std::string& problem, bool broken) {
        drops_.push_back({s->header.stamp.toSec(), problem, broken});
      });
  filter.Add(Scan(10.1));
  filter.Add(Scan(10.2));
  filter.Add(Scan(10.3));
  EXPECT_TRUE(delivered_.empty());
  Add(Pose2D{0.1, 0.0, 0.0}, "odom", "base_link", 10.2);
  Add(Pose2D{0.2, 0.0, 0.0}, "odom", "base_link", 10.4);
  EXPECT_TRUE(delivered_.empty());  // not on the tf thread
  queue.callAvailable();
  EXPECT_EQ(delivered_, (std::vector<double>{10.1, 10.2, 10.3}));
  EXPECT_TRUE(queue.isEmpty());
  EXPECT_TRUE(drops_.empty());
}

TEST_F(ScanTfFilterTest, RefusesABrokenScanAtOnceWithValidateScansWords) {
  ScanTfFilter filter = MakeFilter(kScanTfQueueSize);
  sensor_msgs::LaserScan::Ptr broken(new sensor_msgs::LaserScan(*Scan(10.0)));
  broken->angle_increment = std::nanf("");
  filter.Add(broken);
  sensor_msgs::LaserScan::Ptr no_frame(new sensor_msgs::LaserScan(*Scan(10.0, "")));
  filter.Add(no_frame);
  ASSERT_EQ(drops_.size(), 2u);
  EXPECT_TRUE(drops_[0].broken);
  EXPECT_NE(drops_[0].problem.find("angle_increment must be finite"), std::string::npos) << drops_[0].problem;
  EXPECT_TRUE(drops_[1].broken);
  EXPECT_EQ(drops_[1].problem, "header.frame_id is empty");
  EXPECT_TRUE(delivered_.empty());
}

TEST_F(ScanTfFilterTest, AScanTfNeverGivesIsDroppedNamingTheFramesAndTheStamp) {
  Add(Pose2D{0.0, 0.0, 0.0}, "odom", "base_link", 10.0);
  ScanTfFilter filter = MakeFilter(/*queue_size=*/2);
  filter.Add(Scan(10.0, "nowhere"));  // a frame tf does not know: waits until two newer scans push it out
  filter.Add(Scan(10.5));
  EXPECT_TRUE(drops_.empty());
  filter.Add(Scan(10.6));
  ASSERT_EQ(drops_.size(), 1u);
  EXPECT_FALSE(drops_[0].broken);
  EXPECT_EQ(drops_[0].problem,
            "no tf from 'nowhere' to 'odom' at the scan's stamp 10.000 s: none came while 2 newer scans waited, "
            "or tf moved past that stamp");
  Add(Pose2D{1.0, 0.0, 0.0}, "odom", "base_link", 19.0);
  EXPECT_EQ(delivered_, (std::vector<double>{10.5, 10.6}));
  // More than the cache (10 s) behind tf's latest odometry: dropped at once.
  filter.Add(Scan(8.0));
  ASSERT_EQ(drops_.size(), 2u);
  EXPECT_FALSE(drops_[1].broken);
  EXPECT_EQ(drops_[1].problem, "no tf from 'laser' to 'odom' at the scan's stamp 8.000 s: older than tf's cache holds");
}

TEST_F(ScanTfFilterTest, AHugeFrameIdIsQuotedShort) {
  const std::string frame(100000, 'f');
  const std::string problem = DescribeScanTfDrop(*Scan(1.0, frame), "odom", kScanTfQueueSize,
                                                 tf2_ros::filter_failure_reasons::Unknown);
  EXPECT_LT(problem.size(), 300u) << problem.size();
  EXPECT_EQ(problem.rfind("no tf from 'fff", 0), 0u) << problem;
  EXPECT_NE(problem.find("' to 'odom' at the scan's stamp 1.000 s"), std::string::npos) << problem;
}

}  // namespace
}  // namespace doorplate_localization

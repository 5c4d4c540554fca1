// Tests of LookupTransform and LookupPlanarPose (tf_lookup.h) on a tf2 buffer filled by hand (no ROS master).
#include "doorplate_localization/ros/tf_lookup.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "doorplate_localization/ros/pose_conversions.h"

namespace doorplate_localization {
namespace {

class TfLookupTest : public testing::Test {
 protected:
  void SetUp() override {
    ros::Time::init();
    Add(Pose2D{1.0, 2.0, M_PI / 2}, "odom", "base_link", 10.0);
    Add(Pose2D{2.0, 2.0, M_PI / 2}, "odom", "base_link", 11.0);
  }
  void Add(const Pose2D& pose, const std::string& parent, const std::string& child, double stamp_s) {
    buffer_.setTransform(ToTransformStampedMsg(pose, parent, child, ros::Time(stamp_s)), "test");
  }
  tf2_ros::Buffer buffer_;
  std::string problem_;
};

TEST_F(TfLookupTest, GivesThePlanarPoseAtTheStampInterpolatedOrTheLatest) {
  const std::optional<Pose2D> middle =
      LookupPlanarPose(buffer_, "odom", "base_link", ros::Time(10.5), 0.0, &problem_);
  ASSERT_TRUE(middle.has_value()) << problem_;
  EXPECT_NEAR(middle->x_m, 1.5, 1e-9);
  EXPECT_NEAR(middle->y_m, 2.0, 1e-9);
  EXPECT_NEAR(middle->theta_rad, M_PI / 2, 1e-9);
  const std::optional<Pose2D> latest = LookupPlanarPose(buffer_, "odom", "base_link", ros::Time(0), 0.0, &problem_);
  ASSERT_TRUE(latest.has_value());
  EXPECT_NEAR(latest->x_m, 2.0, 1e-9);
  // The inverse direction: odom in base_link.
  const std::optional<Pose2D> inverse = LookupPlanarPose(buffer_, "base_link", "odom", ros::Time(11.0), 0.0, &problem_);
  ASSERT_TRUE(inverse.has_value());
  EXPECT_NEAR(inverse->theta_rad, -M_PI / 2, 1e-9);
}

TEST_F(TfLookupTest, AMissingFrameOrStampIsAProblemNamingBothFrames) {
  EXPECT_FALSE(LookupPlanarPose(buffer_, "map", "base_link", ros::Time(0), 0.0, &problem_).has_value());
  EXPECT_EQ(problem_.rfind("no tf from 'base_link' to 'map': ", 0), 0u) << problem_;
  EXPECT_FALSE(LookupPlanarPose(buffer_, "odom", "base_link", ros::Time(20.0), 0.0, &problem_).has_value());
  EXPECT_EQ(problem_.rfind("no tf from 'base_link' to 'odom': ", 0), 0u) << problem_;
}

TEST_F(TfLookupTest, AFixedBufferGivesTheTransformWithTheSameProblemText) {
  const tf2::BufferCore& core = buffer_;  // what doorplate_map_bag reads a bag's tf into
  const std::optional<geometry_msgs::Transform> t = LookupTransform(core, "odom", "base_link", ros::Time(10.0), &problem_);
  ASSERT_TRUE(t.has_value()) << problem_;
  EXPECT_NEAR(t->translation.x, 1.0, 1e-9);
  EXPECT_FALSE(LookupTransform(core, "odom", "camera", ros::Time(10.0), &problem_).has_value());
  EXPECT_EQ(problem_.rfind("no tf from 'camera' to 'odom': ", 0), 0u) << problem_;
  EXPECT_FALSE(LookupTransform(buffer_, "odom", "camera", ros::Time(10.0), 0.0, &problem_).has_value());
  EXPECT_EQ(problem_.rfind("no tf from 'camera' to 'odom': ", 0), 0u) << problem_;
}

TEST_F(TfLookupTest, AHugeFrameNameIsQuotedByItsStartOnly) {
  const std::string huge(1 << 20, 'f');
  EXPECT_FALSE(LookupTransform(buffer_, "odom", huge, ros::Time(0), 0.0, &problem_).has_value());
  EXPECT_EQ(problem_.rfind("no tf from 'fff", 0), 0u) << problem_.substr(0, 200);
  EXPECT_LT(problem_.size(), 1000u);
}

// The sweep's odometry: the newest transform, unless it lags the scan it serves by more than the limit.
TEST_F(TfLookupTest, TheLatestPoseIsRefusedWhenItLagsWhatItServesByMoreThanTheLimit) {
  const std::optional<Pose2D> fresh =
      LookupLatestPlanarPose(buffer_, "odom", "base_link", ros::Time(11.2), 0.3, 0.0, &problem_);
  ASSERT_TRUE(fresh.has_value()) << problem_;
  EXPECT_NEAR(fresh->x_m, 2.0, 1e-9);
  EXPECT_TRUE(LookupLatestPlanarPose(buffer_, "odom", "base_link", ros::Time(10.5), 0.3, 0.0, &problem_).has_value());
  EXPECT_FALSE(LookupLatestPlanarPose(buffer_, "odom", "base_link", ros::Time(11.5), 0.3, 0.0, &problem_).has_value());
  EXPECT_EQ(problem_, "the latest tf from 'base_link' to 'odom' is 0.500 s older than needed (at 11.500 s; limit 0.300 s)");
  EXPECT_FALSE(LookupLatestPlanarPose(buffer_, "odom", "nowhere", ros::Time(11.0), 0.3, 0.0, &problem_).has_value());
  EXPECT_EQ(problem_.rfind("no tf from 'nowhere' to 'odom': ", 0), 0u) << problem_;
}

}  // namespace
}  // namespace doorplate_localization

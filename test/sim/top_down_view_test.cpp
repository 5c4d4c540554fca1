#include "doorplate_localization/sim/top_down_view.h"

#include <gtest/gtest.h>

#include "test_worlds.h"

namespace doorplate_localization {
namespace {

TEST(TopDownView, MapsWorldCornersInsideThePictureWithYUp) {
  const World world = test::RectangleCorridor(10.0, 2.0);
  TopDownView view(world, 1.0);
  const cv::Point origin = view.ToPixel({0.0, 0.0});
  const cv::Point far_corner = view.ToPixel({10.0, 2.0});
  EXPECT_NEAR(origin.x, view.px_per_m() * 1.0, 1.0);
  EXPECT_LT(far_corner.y, origin.y);  // y up in the world is up in the picture
  EXPECT_GT(far_corner.x, origin.x);
  EXPECT_LT(far_corner.x, view.image().cols);
  EXPECT_GE(far_corner.y, 0);
}

TEST(TopDownView, DrawsWallsAndTrajectories) {
  const World world = test::RectangleCorridor(10.0, 2.0);
  TopDownView view(world, 1.0);
  const cv::Point on_wall = view.ToPixel({5.0, 0.0});
  EXPECT_LT(view.image().at<cv::Vec3b>(on_wall)[0], 100);  // dark wall line
  const cv::Point mid = view.ToPixel({5.0, 1.0});
  EXPECT_EQ(view.image().at<cv::Vec3b>(mid), cv::Vec3b(255, 255, 255));
  view.DrawTrajectory({{1.0, 1.0, 0.0}, {9.0, 1.0, 0.0}}, cv::Scalar(0, 200, 0));
  EXPECT_EQ(view.image().at<cv::Vec3b>(mid), cv::Vec3b(0, 200, 0));
}

}  // namespace
}  // namespace doorplate_localization

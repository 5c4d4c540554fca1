// The camera renderer's image helpers (src/sim/image_noise.h): noise quantiles, blur kernels, gain and noise.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include <opencv2/core.hpp>

#include "image_noise.h"

namespace doorplate_localization {
namespace {

TEST(GaussianQuantiles, DrawsHaveTheRequestedStandardDeviationInSixteenthsOfALevel) {
  const std::vector<std::int16_t> table = GaussianQuantiles(4096, 2.0);
  double sum = 0.0, sum_sq = 0.0;
  for (const std::int16_t v : table) {
    sum += v;
    sum_sq += static_cast<double>(v) * v;
  }
  const double mean = sum / table.size(), stddev = std::sqrt(sum_sq / table.size() - mean * mean);
  EXPECT_NEAR(mean, 0.0, 0.05);
  EXPECT_NEAR(stddev / 16.0, 2.0, 0.02);  // the ±3.5σ tails cut off lose ~0.4 % of the spread
  EXPECT_LT(table.front(), 0);
  EXPECT_GT(table.back(), 0);
}

TEST(BlurKernel, IsNormalisedAndWidensWithMotion) {
  const cv::Mat still = BlurKernel(1.0, 0.0), moving = BlurKernel(1.0, 6.0), none = BlurKernel(0.0, 0.0);
  EXPECT_NEAR(cv::sum(still)[0], 1.0, 1e-6);
  EXPECT_NEAR(cv::sum(moving)[0], 1.0, 1e-6);
  EXPECT_EQ(none.cols, 1);
  EXPECT_GT(moving.cols, still.cols);
}

TEST(ApplyGainAndNoise, WithoutNoiseScalesEveryChannelByTheGainAndSaturates) {
  cv::Mat image(2, 3, CV_8UC3, cv::Scalar(100, 50, 200));
  ApplyGainAndNoise(1.5, 0.0, {}, 7, &image);
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) {
      EXPECT_EQ(image.at<cv::Vec3b>(r, c), cv::Vec3b(150, 75, 255));
    }
  }
}

TEST(ApplyGainAndNoise, TheGradientBrightensOneSideAndDarkensTheOther) {
  cv::Mat image(1, 10, CV_8UC3, cv::Scalar(100, 100, 100));
  ApplyGainAndNoise(1.0, 0.4, {}, 7, &image);
  EXPECT_EQ(image.at<cv::Vec3b>(0, 0)[0], 82);  // gain 1 + 0.4 · (0.05 − 0.5) = 0.82
  EXPECT_EQ(image.at<cv::Vec3b>(0, 9)[0], 118);
}

TEST(ApplyGainAndNoise, AddsNoiseOfTheTablesSpreadReproduciblyFromTheSeed) {
  const std::vector<std::int16_t> table = GaussianQuantiles(4096, 3.0);
  const cv::Mat flat(64, 64, CV_8UC3, cv::Scalar(128, 128, 128));
  cv::Mat a = flat.clone(), b = flat.clone(), c = flat.clone();
  ApplyGainAndNoise(1.0, 0.0, table, 11, &a);
  ApplyGainAndNoise(1.0, 0.0, table, 11, &b);
  ApplyGainAndNoise(1.0, 0.0, table, 12, &c);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, c, cv::NORM_INF), 0.0);
  cv::Scalar mean, stddev;
  cv::meanStdDev(a.reshape(1), mean, stddev);
  EXPECT_NEAR(mean[0], 128.0, 0.2);
  EXPECT_NEAR(stddev[0], 3.0, 0.15);  // rounding to whole levels adds 1/12 level² of variance
}

}  // namespace
}  // namespace doorplate_localization

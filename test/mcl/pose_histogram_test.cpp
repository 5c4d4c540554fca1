#include "doorplate_localization/mcl/pose_histogram.h"

#include <gtest/gtest.h>

#include <set>

namespace doorplate_localization {
namespace {

TEST(PoseHistogram, AmclBinsAreHalfMetreAndTenDegrees) {
  const PoseBinSize size;
  EXPECT_EQ(ThetaBinCount(size), 36);
  const PoseBin b = BinOf({1.26, -0.1, 0.0}, size);
  EXPECT_EQ(b.x, 2);
  EXPECT_EQ(b.y, -1);
  EXPECT_EQ(b.theta, 18);  // heading 0 is 180° above -pi
}

TEST(PoseHistogram, HeadingsAtPlusAndMinusPiShareABin) {
  const PoseBinSize size;
  EXPECT_EQ(BinOf({0, 0, M_PI}, size).theta, BinOf({0, 0, -M_PI}, size).theta);
  EXPECT_EQ(BinOf({0, 0, -M_PI}, size).theta, 0);
  EXPECT_EQ(BinOf({0, 0, M_PI - 1e-6}, size).theta, 35);
}

TEST(PoseHistogram, KeysAreUniqueAcrossNeighboursAndSigns) {
  std::set<std::uint64_t> keys;
  int n = 0;
  for (int x = -2; x <= 2; ++x) {
    for (int y = -2; y <= 2; ++y) {
      for (int t = 0; t < 36; ++t, ++n) keys.insert(BinKey({x * 1000003, y * 999983, t}));
    }
  }
  EXPECT_EQ(static_cast<int>(keys.size()), n);
}

}  // namespace
}  // namespace doorplate_localization

#include "doorplate_localization/behaviour/isolated_returns.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <vector>

namespace doorplate_localization {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(IsIsolatedReturn, AReturnWithoutNeighboursAtItsRangeIsIsolated) {
  const std::vector<float> r{3.0f, 3.0f, 3.0f, 0.8f, 3.0f, 3.0f, 3.0f};
  EXPECT_TRUE(IsIsolatedReturn(r, 3, IsolatedReturnOptions{}));
  EXPECT_FALSE(IsIsolatedReturn(r, 1, IsolatedReturnOptions{}));
}

TEST(IsIsolatedReturn, ThreeNeighbouringReturnsOnOneObjectAreNot) {
  const std::vector<float> r{3.0f, 0.8f, 0.82f, 0.85f, 3.0f};  // a leg three beams wide
  for (std::size_t i = 1; i <= 3; ++i) EXPECT_FALSE(IsIsolatedReturn(r, i, IsolatedReturnOptions{})) << i;
}

TEST(IsIsolatedReturn, TwoSpuriousReturnsTogetherAreStillIsolated) {
  const std::vector<float> r{3.0f, 3.0f, 3.0f, 0.8f, 0.9f, 3.0f, 3.0f, 3.0f};
  EXPECT_TRUE(IsIsolatedReturn(r, 3, IsolatedReturnOptions{}));
  EXPECT_TRUE(IsIsolatedReturn(r, 4, IsolatedReturnOptions{}));
}

TEST(IsIsolatedReturn, ANearWallBesideBeamsWithoutEchoIsSupported) {
  const std::vector<float> r{kInf, 1.00f, kInf, 1.02f, 1.05f, kInf};  // dropouts in a wall
  EXPECT_FALSE(IsIsolatedReturn(r, 1, IsolatedReturnOptions{}));
}

TEST(IsIsolatedReturn, NoReturnIsNeverIsolatedAndZeroSupportKeepsAll) {
  const std::vector<float> r{3.0f, kInf, 0.8f, 3.0f};
  EXPECT_FALSE(IsIsolatedReturn(r, 1, IsolatedReturnOptions{}));
  IsolatedReturnOptions off;
  off.min_support = 0;
  EXPECT_FALSE(IsIsolatedReturn(r, 2, off));
}

TEST(IsIsolatedReturn, InvalidOptionsNameTheField) {
  IsolatedReturnOptions o;
  o.window_beams = 0;
  EXPECT_THROW(CheckIsolatedReturnOptions(o, "X."), std::invalid_argument);
  try {
    CheckIsolatedReturnOptions(o, "X.");
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "X.window_beams: must be >= 1");
  }
}

}  // namespace
}  // namespace doorplate_localization

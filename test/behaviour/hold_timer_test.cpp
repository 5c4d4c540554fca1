#include "doorplate_localization/behaviour/hold_timer.h"

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

TEST(HoldTimer, CountsFromTheFirstTimeTheConditionHeldUntilReset) {
  HoldTimer timer;
  EXPECT_EQ(timer.Held(10.0), 0.0);
  EXPECT_EQ(timer.Held(12.5), 2.5);
  EXPECT_EQ(timer.Held(14.0), 4.0);
  timer.Reset();  // the condition broke: a new count
  EXPECT_EQ(timer.Held(20.0), 0.0);
  EXPECT_EQ(timer.Held(21.0), 1.0);
}

}  // namespace
}  // namespace doorplate_localization

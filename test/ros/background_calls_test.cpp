// Tests of BackgroundCalls (background_calls.h): posted calls run in order on another thread, Post never
// waits for them, and destruction waits for the call in progress.
#include "background_calls.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <thread>
#include <vector>

namespace doorplate_localization {
namespace {

TEST(BackgroundCalls, RunsThePostedCallsInOrderOnAnotherThread) {
  std::vector<int> order;
  std::promise<std::thread::id> ran_on;
  {
    BackgroundCalls calls;
    for (int i = 0; i < 5; ++i) calls.Post([&order, i] { order.push_back(i); });
    std::promise<void> done;
    calls.Post([&] {
      ran_on.set_value(std::this_thread::get_id());
      done.set_value();
    });
    done.get_future().wait();
  }
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_NE(ran_on.get_future().get(), std::this_thread::get_id());
}

TEST(BackgroundCalls, PostReturnsWhileACallBlocksAndDestructionWaitsForIt) {
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::atomic<bool> finished{false};
  std::thread destroyer;
  {
    auto calls = std::make_unique<BackgroundCalls>();
    std::promise<void> started;
    calls->Post([&] {
      started.set_value();
      released.wait();
      finished = true;
    });
    started.get_future().wait();
    calls->Post([] {});  // queued behind the blocked call: Post does not wait
    destroyer = std::thread([&calls] { calls.reset(); });
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_FALSE(finished);
    release.set_value();
    destroyer.join();
    EXPECT_TRUE(finished) << "the destructor returned before the call in progress ended";
  }
}

}  // namespace
}  // namespace doorplate_localization

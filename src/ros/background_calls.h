// Blocking calls (service calls) run in order on a thread of their own. A nodelet must not call another
// nodelet's service from its callback: the manager's worker threads serve every nodelet's queue, and the
// other nodelet's callback can be queued behind the blocked one on the same thread (a deadlock). ROS-free.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

namespace doorplate_localization {

class BackgroundCalls {
 public:
  BackgroundCalls();
  // Waits for the call in progress (if any); the ones still queued are dropped.
  ~BackgroundCalls();
  BackgroundCalls(const BackgroundCalls&) = delete;
  BackgroundCalls& operator=(const BackgroundCalls&) = delete;

  // Queues `call`; it runs after the ones posted before it. Returns at once.
  void Post(std::function<void()> call);

 private:
  void Run();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> calls_;
  bool stop_ = false;
  std::thread thread_;  // last: starts once the members above exist
};

}  // namespace doorplate_localization

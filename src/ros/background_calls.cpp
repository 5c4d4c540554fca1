#include "background_calls.h"

#include <utility>

namespace doorplate_localization {

BackgroundCalls::BackgroundCalls() : thread_(&BackgroundCalls::Run, this) {}

BackgroundCalls::~BackgroundCalls() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
    calls_.clear();
  }
  wake_.notify_all();
  thread_.join();
}

void BackgroundCalls::Post(std::function<void()> call) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    calls_.push_back(std::move(call));
  }
  wake_.notify_one();
}

void BackgroundCalls::Run() {
  for (;;) {
    std::function<void()> call;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] { return stop_ || !calls_.empty(); });
      if (stop_) return;
      call = std::move(calls_.front());
      calls_.pop_front();
    }
    call();
  }
}

}  // namespace doorplate_localization

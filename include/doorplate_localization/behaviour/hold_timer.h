// How long a condition has held without a break: the stop-and-wait rules of the behaviours (go-to-room waits
// before something ahead, the sweep confirms a corridor's end, the floor route gives up when blocked).
// Times are seconds of any monotonic clock (scan stamps). ROS-free, header only.
#pragma once

#include <optional>

namespace doorplate_localization {

class HoldTimer {
 public:
  // The condition holds at `time_s`: seconds since the first time it held in this run of holds (0 the first
  // time).
  double Held(double time_s) {
    if (!since_s_) since_s_ = time_s;
    return time_s - *since_s_;
  }
  // The condition does not hold (any more): the next Held starts a new count.
  void Reset() { since_s_.reset(); }

 private:
  std::optional<double> since_s_;
};

}  // namespace doorplate_localization

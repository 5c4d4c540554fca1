// The progress line of the long runs (issue 19: doorplate_eval's experiments, the offline mapping tools): on a
// terminal one line rewritten in place ("\r", erased to its end, cut to the terminal's width) at most every
// terminal_refresh_s of wall time; otherwise (CI, a log file) a plain line each time the caller's clock passes
// another every_s. The caller's clock is whatever its run counts in: simulated seconds for doorplate_eval,
// wall seconds for the mapping tools. scripts/mission_progress.py does the same for the demo's phases.
// ROS-free, header-only.
#pragma once

#include <sys/ioctl.h>
#include <unistd.h>

#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <functional>
#include <string>

namespace doorplate_localization::tools {

struct ProgressLineOptions {
  double every_s = 0.0;             // plain lines: one per this many seconds of the caller's clock; <= 0: none at all
  double terminal_refresh_s = 0.5;  // terminal: the line is rewritten at most this often (wall clock)
  int terminal_columns = 0;         // terminal: lines are cut to this width less one; 0: ask the terminal
};

// Whether `stream` is a terminal (isatty of its descriptor).
inline bool StreamIsTerminal(std::FILE* stream) { return stream != nullptr && isatty(fileno(stream)) == 1; }

inline double SteadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

class ProgressLine {
 public:
  using WallClock = std::function<double()>;  // monotonic seconds

  // Lines go to `out` (not owned), rewritten in place when `terminal`.
  explicit ProgressLine(const ProgressLineOptions& options, std::FILE* out = stderr,
                        bool terminal = StreamIsTerminal(stderr), WallClock wall = SteadySeconds)
      : options_(options), out_(out), terminal_(terminal), wall_(std::move(wall)), next_s_(options.every_s),
        last_wall_s_(wall_()) {}
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  ~ProgressLine() { Finish(); }

  bool terminal() const { return terminal_; }

  // Whether a line is due now, `clock_s` being the caller's clock (non-decreasing). True at most once per
  // interval (plain: the next multiple of every_s that clock_s reached; terminal: terminal_refresh_s of wall
  // time since the last true): the caller then builds its text and calls Show.
  bool Due(double clock_s) {
    if (!(options_.every_s > 0.0)) return false;
    if (terminal_) {
      const double now_s = wall_();
      if (now_s - last_wall_s_ < options_.terminal_refresh_s) return false;
      last_wall_s_ = now_s;
      return true;
    }
    if (clock_s < next_s_) return false;
    while (next_s_ <= clock_s) next_s_ += options_.every_s;
    return true;
  }

  // Writes one line, printf-style (no newline in `format`).
  __attribute__((format(printf, 2, 3))) void Show(const char* format, ...) {
    char text[1024];
    va_list args;
    va_start(args, format);
    std::vsnprintf(text, sizeof(text), format, args);
    va_end(args);
    if (!terminal_) {
      std::fprintf(out_, "%s\n", text);
      std::fflush(out_);
      return;
    }
    std::string line = text;
    const int columns = Columns();
    if (columns > 1 && line.size() > static_cast<size_t>(columns - 1)) line.resize(static_cast<size_t>(columns - 1));
    std::fprintf(out_, "\r\033[K%s", line.c_str());
    std::fflush(out_);
    open_ = true;
  }

  // Ends a line left open on a terminal with a newline (before other output, and at the end of the run).
  void Finish() {
    if (!open_) return;
    std::fputc('\n', out_);
    std::fflush(out_);
    open_ = false;
  }

 private:
  int Columns() const {
    if (options_.terminal_columns > 0) return options_.terminal_columns;
    winsize size{};
    return ioctl(fileno(out_), TIOCGWINSZ, &size) == 0 ? size.ws_col : 0;
  }

  const ProgressLineOptions options_;
  std::FILE* const out_;
  const bool terminal_;
  const WallClock wall_;
  double next_s_;       // plain: the caller's clock at which the next line is due
  double last_wall_s_;  // terminal: wall time of the last line
  bool open_ = false;   // terminal: a line was written and not ended
};

}  // namespace doorplate_localization::tools

// The long runs' progress line (progress_line.h): plain lines at the caller's interval, a line rewritten in
// place on a terminal at the wall-clock refresh rate.
#include "progress_line.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace doorplate_localization::tools {
namespace {

// A FILE* whose text the test reads back.
class Capture {
 public:
  Capture() : file_(open_memstream(&buffer_, &size_)) {}
  ~Capture() {
    std::fclose(file_);
    std::free(buffer_);
  }
  std::FILE* file() const { return file_; }
  std::string text() {
    std::fflush(file_);
    return std::string(buffer_, size_);
  }

 private:
  char* buffer_ = nullptr;
  size_t size_ = 0;
  std::FILE* file_;
};

TEST(ProgressLine, PlainLinesAreDueOncePerIntervalOfTheCallersClock) {
  Capture out;
  ProgressLine progress({10.0}, out.file(), false);
  EXPECT_FALSE(progress.Due(0.0));
  EXPECT_FALSE(progress.Due(9.9));
  EXPECT_TRUE(progress.Due(10.0));
  EXPECT_FALSE(progress.Due(10.5));
  EXPECT_TRUE(progress.Due(35.0));   // a long step: one line, not three
  EXPECT_FALSE(progress.Due(39.9));
  EXPECT_TRUE(progress.Due(40.0));
}

TEST(ProgressLine, PlainLinesEndWithANewlineAndNeedNoFinish) {
  Capture out;
  {
    ProgressLine progress({1.0}, out.file(), false);
    progress.Show("map: %d scans, %.1f m", 12, 3.25);
    progress.Show("map: %d scans", 13);
  }
  EXPECT_EQ(out.text(), "map: 12 scans, 3.2 m\nmap: 13 scans\n");
}

TEST(ProgressLine, ZeroIntervalShowsNothingOnTerminalsOrInLogs) {
  for (const bool terminal : {false, true}) {
    double wall_s = 0.0;
    Capture out;
    ProgressLine progress({0.0}, out.file(), terminal, [&] { return wall_s; });
    wall_s = 100.0;
    EXPECT_FALSE(progress.Due(1e9)) << "terminal " << terminal;
  }
}

TEST(ProgressLine, TerminalLineIsRewrittenInPlaceAtTheWallClockRefresh) {
  double wall_s = 0.0;
  Capture out;
  ProgressLine progress({60.0, 0.5}, out.file(), true, [&] { return wall_s; });
  EXPECT_TRUE(progress.terminal());
  EXPECT_FALSE(progress.Due(1000.0));  // the caller's clock does not decide on a terminal
  wall_s = 0.5;
  EXPECT_TRUE(progress.Due(0.0));
  progress.Show("step %d", 1);
  EXPECT_FALSE(progress.Due(0.0));
  wall_s = 1.2;
  EXPECT_TRUE(progress.Due(0.0));
  progress.Show("step %d", 2);
  EXPECT_EQ(out.text(), "\r\033[Kstep 1\r\033[Kstep 2");
  progress.Finish();
  progress.Finish();  // once: nothing is open any more
  EXPECT_EQ(out.text(), "\r\033[Kstep 1\r\033[Kstep 2\n");
}

TEST(ProgressLine, TerminalLineIsCutToTheTerminalWidth) {
  Capture out;
  {
    ProgressLine progress({1.0, 0.5, 11}, out.file(), true);
    progress.Show("0123456789abcdef");
  }  // the destructor ends the open line
  EXPECT_EQ(out.text(), "\r\033[K0123456789\n");
}

TEST(ProgressLine, AMemoryStreamIsNotATerminal) {
  Capture out;
  EXPECT_FALSE(StreamIsTerminal(out.file()));
  EXPECT_FALSE(StreamIsTerminal(nullptr));
}

}  // namespace
}  // namespace doorplate_localization::tools

#include "rawlog_reader.h"

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace doorplate_localization::tools {
namespace {

std::string Trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

// Sends std::cerr into a string while it lives (CRawlog reports a corrupt entry there).
class CaptureCerr {
 public:
  CaptureCerr() : previous_(std::cerr.rdbuf(captured_.rdbuf())) {}
  ~CaptureCerr() { std::cerr.rdbuf(previous_); }
  CaptureCerr(const CaptureCerr&) = delete;
  CaptureCerr& operator=(const CaptureCerr&) = delete;
  std::string text() const { return captured_.str(); }

 private:
  std::ostringstream captured_;
  std::streambuf* previous_;
};

// Reads `path` into `rawlog` with MRPT's reader; "" or what MRPT reported ("entry 3: <message>").
std::string ReadCapturingErrors(const std::string& path, mrpt::obs::CRawlog* rawlog, bool* opened);

// AddressSanitizer reserves terabytes of address space for its shadow: no RLIMIT_AS under it.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// MRPT's reader dies with SIGSEGV on some malformed files (a 438-byte one, found by
// fuzz/rawlog_reader_fuzz.cpp) and allocates whatever a length prefix says (2.7 GB for a 4 KB file): the
// file is read first in a child process, so that a crash there is an error naming the file here, and a
// file MRPT fails on is not read a second time; the child runs under `limits`. Returns "" if the child
// read it whole, else why not.
std::string ReadInAChild(const std::string& path, const RawlogReadLimits& limits) {
  std::error_code error;
  const double size = static_cast<double>(std::filesystem::file_size(path, error));
  const double cpu_s = limits.cpu_s > 0 ? limits.cpu_s : 60.0 + size / 1e6;
  const double memory_bytes = limits.memory_bytes > 0 ? limits.memory_bytes : 2e9 + 200.0 * size;
  int channel[2];
  if (::pipe(channel) != 0) return "";  // cannot: read it in this process only, as before
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(channel[0]), ::close(channel[1]);
    return "";
  }
  if (pid == 0) {
    ::close(channel[0]);
    for (const int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGXCPU}) std::signal(sig, SIG_DFL);
    const rlimit cpu{static_cast<rlim_t>(std::ceil(cpu_s)), static_cast<rlim_t>(std::ceil(cpu_s)) + 1};
    ::setrlimit(RLIMIT_CPU, &cpu);
    if (!kAddressSanitizer) {
      const rlimit memory{static_cast<rlim_t>(memory_bytes), static_cast<rlim_t>(memory_bytes)};
      ::setrlimit(RLIMIT_AS, &memory);
    }
    const int devnull = ::open("/dev/null", O_WRONLY);  // MRPT's (or a sanitizer's) report: not the user's
    if (devnull >= 0) ::dup2(devnull, STDOUT_FILENO), ::dup2(devnull, STDERR_FILENO);
    mrpt::obs::CRawlog probe;
    bool opened = false;
    const std::string error = ReadCapturingErrors(path, &probe, &opened);
    if (!error.empty() && ::write(channel[1], error.data(), error.size()) < 0) ::_exit(4);
    ::_exit(error.empty() ? 0 : 3);
  }
  ::close(channel[1]);
  std::string reported;
  char buffer[4096];
  for (ssize_t n; (n = ::read(channel[0], buffer, sizeof(buffer))) != 0;) {
    if (n > 0) reported.append(buffer, static_cast<size_t>(n));
    else if (errno != EINTR) break;
  }
  ::close(channel[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return "";
  }
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU) {
    return "MRPT's reader ran out of its CPU time limit of " + std::to_string(static_cast<long>(std::ceil(cpu_s))) +
           " s on it";
  }
  if (WIFSIGNALED(status)) return std::string("MRPT's reader crashed on it (") + ::strsignal(WTERMSIG(status)) + ")";
  if (WEXITSTATUS(status) == 3) return reported;
  if (WEXITSTATUS(status) != 0) {
    return "MRPT's reader failed on it (exit status " + std::to_string(WEXITSTATUS(status)) + ", out of memory?)";
  }
  return "";
}

std::string ReadCapturingErrors(const std::string& path, mrpt::obs::CRawlog* rawlog, bool* opened) {
  std::string mrpt_error;
  {
    const CaptureCerr capture;
    try {
      *opened = rawlog->loadFromRawLogFile(path);
    } catch (const std::exception& e) {
      mrpt_error = e.what();
    }
    if (mrpt_error.empty()) mrpt_error = capture.text();
  }
  if (Trim(mrpt_error).empty()) return "";
  return "entry " + std::to_string(rawlog->size()) + ": " + MrptMessage(mrpt_error);
}

}  // namespace

std::string MrptMessage(const std::string& text) {
  const std::string key = "Message:";
  const std::size_t at = text.rfind(key);
  if (at == std::string::npos) {  // e.g. "==== non-MRPT exception ====\nstd::bad_alloc\n": the first other line
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      if (!Trim(line).empty() && Trim(line).rfind("====", 0) != 0) return Trim(line);
    }
    return Trim(text);
  }
  const std::size_t begin = at + key.size();
  return Trim(text.substr(begin, text.find('\n', begin) - begin));
}

void LoadRawlog(const std::string& path, mrpt::obs::CRawlog* rawlog, const RawlogReadLimits& limits) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw RawlogError(path + ": no such file");
  if (!std::ifstream(path, std::ios::binary)) throw RawlogError(path + ": cannot open");
  const std::string prefix = path + ": not an MRPT rawlog MRPT can read: ";
  if (const std::string failure = ReadInAChild(path, limits); !failure.empty()) throw RawlogError(prefix + failure);
  bool opened = false;
  if (const std::string error = ReadCapturingErrors(path, rawlog, &opened); !error.empty()) {
    throw RawlogError(prefix + error);
  }
  if (!opened) throw RawlogError(path + ": cannot open");
  if (rawlog->size() == 0) throw RawlogError(path + ": an empty rawlog");
}

}  // namespace doorplate_localization::tools

// The MRPT rawlog reader of the offline tools (src/tools/rawlog_reader.h): a good rawlog loads; a missing,
// empty, garbage or truncated file is a RawlogError naming the file with MRPT's innermost message, and
// MRPT's call stack never reaches stderr (issue 18).
#include "rawlog_reader.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

namespace doorplate_localization::tools {
namespace {

namespace fs = std::filesystem;

class RawlogReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("rawlog_reader_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string Path(const std::string& name) const { return (dir_ / name).string(); }

  std::string WriteFile(const std::string& name, const std::string& bytes) const {
    std::ofstream(Path(name), std::ios::binary) << bytes;
    return Path(name);
  }

  // A rawlog of `n` 3-beam scans, written by MRPT (gz-compressed, as MRPT writes them).
  std::string WriteGoodRawlog(const std::string& name, int n) const {
    mrpt::obs::CRawlog log;
    for (int k = 0; k < n; ++k) {
      auto scan = mrpt::obs::CObservation2DRangeScan::Create();
      scan->resizeScan(3);
      for (int i = 0; i < 3; ++i) scan->setScanRange(i, 1.0f + k), scan->setScanRangeValidity(i, true);
      log.insert(scan);
    }
    EXPECT_TRUE(log.saveToRawLogFile(Path(name)));
    return Path(name);
  }

  // What LoadRawlog says about `path`, and what reached stderr meanwhile.
  std::string ErrorOf(const std::string& path, std::string* stderr_text) const {
    mrpt::obs::CRawlog log;
    ::testing::internal::CaptureStderr();
    std::string error;
    try {
      LoadRawlog(path, &log);
    } catch (const RawlogError& e) {
      error = e.what();
    }
    *stderr_text = ::testing::internal::GetCapturedStderr();
    return error;
  }

  fs::path dir_;
};

TEST_F(RawlogReaderTest, LoadsARawlogMrptWrote) {
  mrpt::obs::CRawlog log;
  LoadRawlog(WriteGoodRawlog("good.rawlog", 3), &log);
  EXPECT_EQ(log.size(), 3u);
}

TEST_F(RawlogReaderTest, NamesTheFileOfAMissingEmptyOrGarbageRawlogWithoutMrptsCallStack) {
  std::string err;
  EXPECT_EQ(ErrorOf(Path("none.rawlog"), &err), Path("none.rawlog") + ": no such file");
  EXPECT_EQ(ErrorOf(dir_.string(), &err), dir_.string() + ": no such file");
  EXPECT_EQ(ErrorOf(WriteFile("empty.rawlog", ""), &err), Path("empty.rawlog") + ": an empty rawlog");
  const std::string garbage = ErrorOf(WriteFile("garbage.rawlog", "FLASER 3 1 2 3 0 0 0 0 0 0\n"), &err);
  EXPECT_EQ(garbage.rfind(Path("garbage.rawlog") + ": not an MRPT rawlog MRPT can read: entry 0: ", 0), 0u) << garbage;
  EXPECT_EQ(garbage.find("Call stack"), std::string::npos) << garbage;
  EXPECT_EQ(garbage.find('\n'), std::string::npos) << garbage;
  EXPECT_EQ(err, "");
}

// MRPT keeps the entries before a corrupt one and only prints the error: a truncated file is refused whole.
TEST_F(RawlogReaderTest, RefusesATruncatedRawlogNamingTheEntryWhereItBroke) {
  const std::string good = WriteGoodRawlog("good.rawlog", 20);
  std::ifstream in(good, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string err;
  const std::string error = ErrorOf(WriteFile("cut.rawlog", bytes.substr(0, bytes.size() * 2 / 3)), &err);
  EXPECT_EQ(error.rfind(Path("cut.rawlog") + ": not an MRPT rawlog MRPT can read: entry ", 0), 0u) << error;
  EXPECT_EQ(err, "");
}

// Found by fuzz/rawlog_reader_fuzz.cpp (issue 18): MRPT's reader dies with SIGSEGV on this 438-byte file
// (a corrupt CActionRobotMovement2D); it is read in a child process first, so the tool reports it.
TEST_F(RawlogReaderTest, AFileMrptsReaderCrashesOnIsAnErrorNamingIt) {
  const std::string path = std::string(DOORPLATE_SOURCE_DIR) +
                           "/fuzz/corpus/rawlog_reader/regression_mrpt_segv_in_action_robot_movement_438_bytes.rawlog";
  std::string err;
  const std::string error = ErrorOf(path, &err);
  // "crashed on it (Segmentation fault)"; under AddressSanitizer its report ends the child instead.
  EXPECT_EQ(error.rfind(path + ": not an MRPT rawlog MRPT can read: MRPT's reader ", 0), 0u) << error;
  EXPECT_EQ(err, "");
}

TEST(MrptMessage, KeepsTheInnermostMessageOfANestedMrptException) {
  EXPECT_EQ(MrptMessage("==== MRPT exception ====\nMessage:  outer\nOriginal exception:\n==== MRPT exception ====\n"
                        "Message:  Expecting 0x00 00 00 (gz?)\nLocation: a.cpp:3: [f]\nCall stack backtrace:\n[0] x\n"),
            "Expecting 0x00 00 00 (gz?)");
  EXPECT_EQ(MrptMessage("filesystem error: cannot get file size\n[0] x"), "filesystem error: cannot get file size");
  EXPECT_EQ(MrptMessage("==== non-MRPT exception ====\nstd::bad_alloc\n"), "std::bad_alloc");
}

}  // namespace
}  // namespace doorplate_localization::tools

#include "doorplate_localization/common/freed_memory.h"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

// VmRSS of this process in kB (Linux), -1 if unreadable.
long ResidentKb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmRSS:", 0) == 0) return std::strtol(line.c_str() + 6, nullptr, 10);
  }
  return -1;
}

TEST(ReturnFreedMemoryToSystem, GivesBackTheHeapPagesOfFreedBlocksBelowALiveOne) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__) || !defined(__GLIBC__)
  GTEST_SKIP() << "a sanitizer's allocator (or a C library other than glibc) keeps its own heap";
#else
  if (ResidentKb() < 0) GTEST_SKIP() << "no /proc/self/status";
  // 48 MB in blocks of 4 kB (below glibc's mmap threshold: they come from the heap), written so their pages
  // are resident; then every 16th block stays and the rest are freed: the heap's top stays in use, so glibc's
  // own trimming at free() cannot give the pages between the live blocks back (what a solve leaves behind
  // among the blocks the mapper keeps).
  constexpr int kBlocks = 12 * 1024;
  constexpr int kKeepEvery = 16;
  constexpr std::size_t kBlockBytes = 4000;
  std::vector<char*> blocks;
  blocks.reserve(kBlocks);
  for (int i = 0; i < kBlocks; ++i) {
    blocks.push_back(static_cast<char*>(std::malloc(kBlockBytes)));
    ASSERT_NE(blocks.back(), nullptr);
    std::memset(blocks.back(), 1, kBlockBytes);
  }
  for (int i = 0; i < kBlocks; ++i) {
    if (i % kKeepEvery != kKeepEvery - 1) std::free(blocks[i]);
  }
  const long before_kb = ResidentKb();
  const bool returned = ReturnFreedMemoryToSystem();
  const long after_kb = ResidentKb();
  for (int i = kKeepEvery - 1; i < kBlocks; i += kKeepEvery) std::free(blocks[i]);
  EXPECT_TRUE(returned);
  EXPECT_GT(before_kb - after_kb, 32 * 1024) << "resident before " << before_kb << " kB, after " << after_kb << " kB";
#endif
}

}  // namespace
}  // namespace doorplate_localization

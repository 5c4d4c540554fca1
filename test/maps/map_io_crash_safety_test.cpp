// Crash safety of map saving (issue 8): a child process saves maps over and over (the occupancy map as
// PGM + YAML with SaveOccupancyMap, the text map with SaveTextMap) and is SIGKILLed at a random moment
// (seeded). Whatever the moment, what is on disk must load with our loaders and be one complete saved
// version, never a half-written file, and never the image of one save with the YAML of another (the
// occupancy map is two files: SaveOccupancyMap keeps the previous image as `.prev` while it renames them). The random delay before the kill is the point of the test: it is
// not a wait for a condition.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "doorplate_localization/maps/map_io.h"
#include "doorplate_localization/maps/text_map.h"
#include "map_test_util.h"

namespace doorplate_localization {
namespace {

// Two versions of a growing map, as SLAM saves them: different size, origin and cells.
OccupancyGrid Grid(int version) {
  const int width = 40 + 20 * version, height = 30 + 5 * version;
  OccupancyGrid grid(width, height, 0.05, {-1.0 * version, -0.5 * version, 0.0}, OccupancyGrid::kFree);
  for (int x = 0; x < width; ++x) grid.At(x, (x * (version + 2)) % height) = OccupancyGrid::kOccupied;
  grid.At(version, 0) = OccupancyGrid::kUnknown;
  return grid;
}

TextMap Plates(int version) {
  TextMap map;
  map.occupancy_map = "map.yaml";
  for (int i = 0; i < 3 + version; ++i) {
    TextLandmark plate;
    plate.text = std::to_string(200 + 10 * version + i);
    plate.pose = {1.5 * i, version == 0 ? 1.0 : -1.0, 0.0};
    plate.wall = "north";
    map.landmarks.push_back(plate);
  }
  ComputeAdjacentDistances(&map);
  return map;
}

bool SameCells(const OccupancyGrid& a, const OccupancyGrid& b) {
  return a.width == b.width && a.height == b.height && a.cells == b.cells;
}
bool SameGeometry(const OccupancyGrid& a, const OccupancyGrid& b) {
  return a.resolution_m == b.resolution_m && a.origin.x_m == b.origin.x_m && a.origin.y_m == b.origin.y_m;
}
bool SameGrid(const OccupancyGrid& a, const OccupancyGrid& b) { return SameCells(a, b) && SameGeometry(a, b); }

// Which saved version `what_is_on_disk` is (0 or 1), or -1 for none of them.
template <typename T, typename Same>
int VersionOf(const T& what_is_on_disk, T (*make)(int), Same same) {
  for (int v = 0; v < 2; ++v) {
    if (same(what_is_on_disk, make(v))) return v;
  }
  return -1;
}

// Forks a child that saves versions first, 1 - first, first, ... until it is killed, and kills it `delay`
// after it started its first save, and reaps it.
void SaveInChildAndKill(const std::string& grid_base, const std::string& text_map_path, int first,
                        std::chrono::microseconds delay) {
  int started[2];
  ASSERT_EQ(::pipe(started), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(started[0]);
    for (int i = 0;; ++i) {
      if (i == 0 && ::write(started[1], "s", 1) != 1) ::_exit(3);
      const int version = (first + i) % 2;
      SaveOccupancyMap(Grid(version), grid_base);
      SaveTextMap(Plates(version), text_map_path);
    }
  }
  ::close(started[1]);
  char byte = 0;
  ASSERT_EQ(::read(started[0], &byte, 1), 1);
  ::close(started[0]);
  std::this_thread::sleep_for(delay);
  ASSERT_EQ(::kill(child, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the saving child ended on its own (status " << status << ")";
}

TEST(MapSaveCrashSafety, AMapSavedWhileTheProcessIsKilledIsAlwaysTheOldOrTheNewCompleteMap) {
  test::TempDir dir;
  const std::string grid_base = dir.Path("map"), text_map_path = dir.Path("map.text_map.yaml");
  SaveOccupancyMap(Grid(0), grid_base);
  SaveTextMap(Plates(0), text_map_path);

  // One save cycle (both maps) takes milliseconds, most of it in fsync; kill anywhere within 5 cycles, so
  // the kills land in every part of the cycle whatever the disk's speed.
  const auto cycle_start = std::chrono::steady_clock::now();
  constexpr int kTimedCycles = 4;
  for (int i = 0; i < kTimedCycles; ++i) {
    SaveOccupancyMap(Grid(i % 2), grid_base);
    SaveTextMap(Plates(i % 2), text_map_path);
  }
  const auto cycle = (std::chrono::steady_clock::now() - cycle_start) / kTimedCycles;
  const int max_delay_us = static_cast<int>(5.0 * std::chrono::duration_cast<std::chrono::microseconds>(cycle).count());
  std::mt19937 rng(8);  // seeded: the same sequence of kill moments (in cycles) every run
  std::uniform_int_distribution<int> delay_us(0, std::max(1, max_delay_us));
  constexpr int kKills = 40;
  int grid_versions_seen[2] = {0, 0}, text_versions_seen[2] = {0, 0}, mixed_pairs = 0;
  int on_disk = 1;  // the timing cycles above end with version 1 on disk
  for (int kill = 0; kill < kKills; ++kill) {
    // The child starts with the version that is not on disk, so every save it completes changes the disk.
    SaveInChildAndKill(grid_base, text_map_path, 1 - on_disk, std::chrono::microseconds(delay_us(rng)));
    if (HasFatalFailure()) return;
    OccupancyGrid grid;
    ASSERT_NO_THROW(grid = LoadOccupancyMap(grid_base + ".yaml")) << "kill " << kill;
    TextMap plates;
    ASSERT_NO_THROW(plates = LoadTextMap(text_map_path)) << "kill " << kill;

    const int grid_version = VersionOf(grid, &Grid, SameGrid);
    const int text_version = VersionOf(plates, &Plates, [](const TextMap& a, const TextMap& b) {
      return TextMapToYaml(a) == TextMapToYaml(b);
    });
    EXPECT_GE(text_version, 0) << "kill " << kill << ": the text map on disk is no saved version";
    if (text_version >= 0) ++text_versions_seen[text_version];
    if (text_version >= 0) on_disk = text_version;
    if (grid_version >= 0) {
      ++grid_versions_seen[grid_version];
      continue;
    }
    ++mixed_pairs;
    ADD_FAILURE() << "kill " << kill << ": the occupancy map on disk is no saved version ("
                  << (SameCells(grid, Grid(0)) || SameCells(grid, Grid(1)) ? "image and YAML of different saves"
                                                                          : "unknown cells") << ")";
  }
  std::cout << "[ crash    ] " << kKills << " kills: occupancy map version 0/1/mixed: " << grid_versions_seen[0]
            << "/" << grid_versions_seen[1] << "/" << mixed_pairs << "; text map version 0/1: "
            << text_versions_seen[0] << "/" << text_versions_seen[1] << "\n";
  // The kills landed at different moments of the save cycle, so the test saw both versions on disk.
  EXPECT_GT(grid_versions_seen[0] + grid_versions_seen[1], 0);
  EXPECT_GT(text_versions_seen[0], 0);
  EXPECT_GT(text_versions_seen[1], 0);
}

// The state a kill between the two renames leaves, made by hand: the new image, the previous YAML and the
// previous image kept as `.prev`. The loader must pair the YAML with `.prev`; a later save cleans up.
TEST(MapSaveCrashSafety, TheYamlIsPairedWithThePreviousImageWhenTheImageIsFromANewerSave) {
  test::TempDir dir;
  const std::string base = dir.Path("map");
  SaveOccupancyMap(Grid(0), base);
  const std::string old_yaml = dir.Read("map.yaml"), old_image = dir.Read("map.pgm");
  SaveOccupancyMap(Grid(1), base);
  dir.Write("map.yaml", old_yaml);
  dir.Write("map.pgm.prev", old_image);
  EXPECT_TRUE(SameGrid(LoadOccupancyMap(base + ".yaml"), Grid(0)));
  // Without `.prev` the newer image is all there is: it loads (with the YAML's geometry).
  std::filesystem::remove(dir.Path("map.pgm.prev"));
  EXPECT_TRUE(SameCells(LoadOccupancyMap(base + ".yaml"), Grid(1)));
  SaveOccupancyMap(Grid(1), base);
  EXPECT_TRUE(SameGrid(LoadOccupancyMap(base + ".yaml"), Grid(1)));
  EXPECT_EQ(dir.List(), (std::vector<std::string>{"map.pgm", "map.yaml"}));
  // The save marker is a hash of the content: saving the same map again writes the same bytes.
  const std::string yaml = dir.Read("map.yaml"), image = dir.Read("map.pgm");
  SaveOccupancyMap(Grid(1), base);
  EXPECT_EQ(dir.Read("map.yaml"), yaml);
  EXPECT_EQ(dir.Read("map.pgm"), image);
}

}  // namespace
}  // namespace doorplate_localization

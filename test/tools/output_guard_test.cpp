#include "output_guard.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace doorplate_localization::tools {
namespace {

namespace fs = std::filesystem;

fs::path TempDir() {
  const fs::path dir = fs::temp_directory_path() / "output_guard_test";
  fs::create_directories(dir);
  return dir;
}

TEST(SameFile, OtherSpellingsAndHardLinksOfOneFileAreTheSameFile) {
  const fs::path dir = TempDir();
  const fs::path world = dir / "w.yaml";
  std::ofstream(world) << "x";
  EXPECT_TRUE(SameFile(world.string(), (dir / "." / "w.yaml").string()));
  EXPECT_TRUE(SameFile(world.string(), (dir / "sub" / ".." / "w.yaml").string()));
  const fs::path link = dir / "link.yaml";
  fs::remove(link);
  fs::create_hard_link(world, link);
  EXPECT_TRUE(SameFile(world.string(), link.string()));
  EXPECT_FALSE(SameFile(world.string(), (dir / "w2.yaml").string()));
  EXPECT_TRUE(SameFile((dir / "new.pgm").string(), (dir / "." / "new.pgm").string()));  // neither exists
}

TEST(RefuseOverwritingInputs, AnOutputThatIsAnInputIsAUsageErrorNamingBoth) {
  const fs::path dir = TempDir();
  const std::string world = (dir / "x.yaml").string();
  std::ofstream(world) << "x";
  try {
    RefuseOverwritingInputs({{"--world", world}}, {{"--out", (dir / "x.pgm").string()}, {"--out", world}});
    FAIL() << "accepted an output that is the input";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), "--out: would write " + world + ", the input given to --world; nothing was written");
  }
  EXPECT_NO_THROW(RefuseOverwritingInputs({{"--world", world}}, {{"--out", (dir / "y.yaml").string()}, {"--topdown", ""}}));
}

OccupancyGrid Grid(int width, int height, std::vector<std::int8_t> cells) {
  OccupancyGrid g;
  g.width = width;
  g.height = height;
  g.resolution_m = 0.05;
  g.cells = std::move(cells);
  return g;
}

TEST(RequireUsableMap, AMapWithoutFreeOrOccupiedCellsOrWithANonFiniteOriginIsRefused) {
  EXPECT_NO_THROW(RequireUsableMap(Grid(2, 1, {OccupancyGrid::kFree, OccupancyGrid::kOccupied}), "log"));
  try {
    RequireUsableMap(Grid(1, 1, {OccupancyGrid::kUnknown}), "x.log");
    FAIL() << "accepted a 1 x 1 unknown map";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "x.log: the run produced no usable map (1 x 1 cells, 0 free, 0 occupied): nothing was written");
  }
  OccupancyGrid far = Grid(2, 1, {OccupancyGrid::kFree, OccupancyGrid::kOccupied});
  far.origin.x_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(RequireUsableMap(far, "log"), std::runtime_error);
}

struct Point {
  Pose2D pose;
};

TEST(RequireFiniteTrajectory, AnEmptyTrajectoryOrANonFinitePoseIsRefusedNamingThePose) {
  EXPECT_NO_THROW(RequireFiniteTrajectory(std::vector<Point>{{{0, 0, 0}}, {{1, 0, 0}}}, "log"));
  EXPECT_THROW(RequireFiniteTrajectory(std::vector<Point>{}, "log"), std::runtime_error);
  try {
    RequireFiniteTrajectory(std::vector<Point>{{{0, 0, 0}}, {{1, std::numeric_limits<double>::infinity(), 0}}}, "x.log");
    FAIL() << "accepted an infinite pose";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "x.log: pose 1 of the trajectory is not finite: nothing was written");
  }
}

}  // namespace
}  // namespace doorplate_localization::tools

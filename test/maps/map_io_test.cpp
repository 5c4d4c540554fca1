#include "doorplate_localization/maps/map_io.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "map_test_util.h"

namespace doorplate_localization {
namespace {

using test::Contains;
using test::ErrorOf;

const char kYaml[] =
    "image: m.pgm\nresolution: 0.1\norigin: [-1.0, 2.0, 0.0]\nnegate: 0\n"
    "occupied_thresh: 0.65\nfree_thresh: 0.196\n";

// A 3 × 2 PGM, top row first: black (occupied) at the top left, white (free), mid grey (unknown).
std::string TinyPgm() {
  std::string bytes = "P5\n3 2\n255\n";
  for (int v : {0, 254, 205, 254, 254, 254}) bytes.push_back(static_cast<char>(v));
  return bytes;
}

TEST(LoadOccupancyMap, ImageRowZeroIsTheHighestRowOfTheGrid) {
  test::TempDir dir;
  dir.Write("m.pgm", TinyPgm());
  const OccupancyGrid grid = LoadOccupancyMap(dir.Write("m.yaml", kYaml));
  ASSERT_EQ(grid.width, 3);
  ASSERT_EQ(grid.height, 2);
  EXPECT_EQ(grid.At(0, 1), OccupancyGrid::kOccupied);  // top-left pixel: highest y
  EXPECT_EQ(grid.At(1, 1), OccupancyGrid::kFree);
  EXPECT_EQ(grid.At(2, 1), OccupancyGrid::kUnknown);
  EXPECT_EQ(grid.At(0, 0), OccupancyGrid::kFree);
  EXPECT_NEAR(grid.resolution_m, 0.1, 1e-12);
  EXPECT_NEAR(grid.origin.x_m, -1.0, 1e-12);
  EXPECT_NEAR(grid.origin.y_m, 2.0, 1e-12);
  EXPECT_NEAR(grid.CellCenter(0, 1).y, 2.15, 1e-12);
}

TEST(LoadOccupancyMap, NegateSwapsFreeAndOccupied) {
  test::TempDir dir;
  dir.Write("m.pgm", TinyPgm());
  std::string yaml = kYaml;
  yaml.replace(yaml.find("negate: 0"), 9, "negate: 1");
  const OccupancyGrid grid = LoadOccupancyMap(dir.Write("m.yaml", yaml));
  EXPECT_EQ(grid.At(0, 1), OccupancyGrid::kFree);
  EXPECT_EQ(grid.At(1, 1), OccupancyGrid::kOccupied);
}

TEST(LoadOccupancyMap, ScaleModeMapsGreysBetweenTheThresholdsToOneTo99) {
  test::TempDir dir;
  dir.Write("m.pgm", "P2 3 1 255 0 128 255");
  const OccupancyGrid grid = LoadOccupancyMap(dir.Write(
      "m.yaml", "image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.9\n"
                "free_thresh: 0.1\nmode: scale\n"));
  EXPECT_EQ(grid.At(0, 0), OccupancyGrid::kOccupied);
  EXPECT_EQ(grid.At(1, 0), 49);  // occupancy 127/255: 1 + 98 * (0.498 - 0.1) / 0.8
  EXPECT_EQ(grid.At(2, 0), OccupancyGrid::kFree);
}

TEST(LoadOccupancyMap, RawModeCopiesThePixelValues) {
  test::TempDir dir;
  dir.Write("m.pgm", "P2 3 1 255 0 42 100");
  const OccupancyGrid grid = LoadOccupancyMap(dir.Write(
      "m.yaml", "image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n"
                "free_thresh: 0.196\nmode: raw\n"));
  EXPECT_EQ(grid.cells, (std::vector<std::int8_t>{0, 42, 100}));
}

TEST(LoadOccupancyMap, FindsTheImageRelativeToTheYamlFolderOrUnderHome) {
  test::TempDir dir;
  dir.Write("maps/images/m.pgm", TinyPgm());
  std::string yaml = kYaml;
  yaml.replace(yaml.find("m.pgm"), 5, "images/m.pgm");
  EXPECT_EQ(LoadOccupancyMap(dir.Write("maps/m.yaml", yaml)).width, 3);

  const char* old_home = std::getenv("HOME");
  const std::string saved_home = old_home ? old_home : "";
  ::setenv("HOME", dir.Path("maps").c_str(), 1);
  yaml.replace(yaml.find("images/m.pgm"), 12, "~/images/m.pgm");
  const std::string yaml_path = dir.Write("elsewhere/m.yaml", yaml);
  int width = -1;
  const std::string error = ErrorOf<MapFileError>([&] { width = LoadOccupancyMap(yaml_path).width; });
  ::setenv("HOME", saved_home.c_str(), 1);
  EXPECT_EQ(width, 3) << error;
}

struct BrokenCase {
  const char* name;
  std::string yaml;
  std::string expected;  // message part after "<yaml path>: "
};

TEST(LoadOccupancyMap, EachBrokenFileGivesAnErrorNamingTheFileAndField) {
  const std::string ok = kYaml;
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string y = ok;
    y.replace(y.find(from), from.size(), to);
    return y;
  };
  const std::vector<BrokenCase> cases = {
      {"missing image", with("m.pgm", "gone.pgm"), "image: image file '"},
      {"zero resolution", with("resolution: 0.1", "resolution: 0"), "resolution: must be > 0, got 0"},
      {"negative resolution", with("resolution: 0.1", "resolution: -0.05"), "resolution: must be > 0"},
      {"nan resolution", with("resolution: 0.1", "resolution: .nan"), "resolution: must be a finite number"},
      {"thresholds out of order", with("free_thresh: 0.196", "free_thresh: 0.7"),
       "free_thresh: must be < occupied_thresh (0.65), got 0.7"},
      {"threshold above one", with("occupied_thresh: 0.65", "occupied_thresh: 1.5"),
       "occupied_thresh: must be within [0, 1], got 1.5"},
      {"origin of two numbers", with("[-1.0, 2.0, 0.0]", "[1, 2]"), "origin: must be a list of 3 numbers, got 2"},
      {"origin not a list", with("[-1.0, 2.0, 0.0]", "here"), "origin: must be a list"},
      {"missing resolution", with("resolution: 0.1\n", ""), "resolution: required field is missing"},
      {"unknown field", ok + "resolutoin: 2\n", "(top level): unknown field 'resolutoin'"},
      {"bad mode", ok + "mode: fuzzy\n", "mode: must be trinary, scale or raw, got 'fuzzy'"},
      {"bad negate", with("negate: 0", "negate: 2"), "negate: must be 0 or 1, got '2'"},
      {"syntax error", ok + "origin: [\n", "line "},
      // common/limits.h bounds (issue 18)
      {"resolution below 1 mm", with("resolution: 0.1", "resolution: 0.00001"),
       "resolution: must be finite and in [0.001, 100] m (limits::kMinMapResolutionM, kMaxMapResolutionM)"},
      {"origin far away", with("[-1.0, 2.0, 0.0]", "[1e300, 2.0, 0.0]"),
       "origin: x must be finite and within +-1e+06 m (limits::kMaxCoordinateM), got 1e+300"},
      {"origin y far away", with("[-1.0, 2.0, 0.0]", "[-1.0, -2e6, 0.0]"), "origin: y must be finite and within"},
  };
  for (const BrokenCase& c : cases) {
    test::TempDir dir;
    dir.Write("m.pgm", TinyPgm());
    const std::string path = dir.Write("m.yaml", c.yaml);
    const std::string error = ErrorOf<MapFileError>([&] { LoadOccupancyMap(path); });
    EXPECT_TRUE(Contains(error, path + ": " + c.expected)) << c.name << ": " << error;
  }
}

// A 20000 x 20000 image (4e8 cells) is refused from its header, naming the image and the limit, before
// the file is read or the grid allocated; 10 bytes of pixels stand for the 400 MB a real one would hold.
TEST(LoadOccupancyMap, RefusesAnImageLargerThanTheCellLimitFromItsHeader) {
  test::TempDir dir;
  const std::string image = dir.Write("m.pgm", "P5\n20000 20000\n255\n0123456789");
  const std::string path = dir.Write("m.yaml", kYaml);
  const std::string error = ErrorOf<MapFileError>([&] { LoadOccupancyMap(path); });
  EXPECT_TRUE(Contains(error, image + ": header: size 20000 x 20000 = 4e+08 cells, more than the limit of "
                                      "100000000 (limits::kMaxMapCells)"))
      << error;
}

TEST(LoadOccupancyMap, BrokenImagesAreReportedWithTheImagePath) {
  test::TempDir dir;
  const std::string yaml_path = dir.Write("m.yaml", kYaml);
  dir.Write("m.pgm", "P3 3 2 255\n");
  EXPECT_TRUE(Contains(ErrorOf<MapFileError>([&] { LoadOccupancyMap(yaml_path); }),
                       dir.Path("m.pgm") + ": not an 8-bit grey PGM image (bad magic 'P3'"));
  dir.Write("m.pgm", TinyPgm().substr(0, 14));
  EXPECT_TRUE(Contains(ErrorOf<MapFileError>([&] { LoadOccupancyMap(yaml_path); }),
                       dir.Path("m.pgm") + ": pixel data: truncated, expected 6 bytes after the header, got 3"));
  EXPECT_TRUE(Contains(ErrorOf<MapFileError>([&] { LoadOccupancyMap(dir.Path("none.yaml")); }),
                       dir.Path("none.yaml") + ": cannot open"));
}

TEST(SaveOccupancyMap, SaveThenLoadGivesTheSameGrid) {
  test::TempDir dir;
  OccupancyGrid grid(7, 5, 0.05, {-3.125, 0.1, 0.0}, OccupancyGrid::kUnknown);
  for (int x = 0; x < 7; ++x) grid.At(x, 0) = OccupancyGrid::kOccupied;
  for (int x = 1; x < 6; ++x) grid.At(x, 2) = OccupancyGrid::kFree;
  grid.At(6, 4) = OccupancyGrid::kOccupied;
  SaveOccupancyMap(grid, dir.Path("saved"));
  EXPECT_EQ(dir.List(), (std::vector<std::string>{"saved.pgm", "saved.yaml"}));  // no temporary file left
  EXPECT_TRUE(Contains(dir.Read("saved.yaml"), "image: saved.pgm\n"));
  const OccupancyGrid back = LoadOccupancyMap(dir.Path("saved.yaml"));
  EXPECT_EQ(back.width, grid.width);
  EXPECT_EQ(back.height, grid.height);
  EXPECT_EQ(back.resolution_m, grid.resolution_m);
  EXPECT_EQ(back.origin.x_m, grid.origin.x_m);
  EXPECT_EQ(back.origin.y_m, grid.origin.y_m);
  EXPECT_EQ(back.cells, grid.cells);
}

TEST(SaveOccupancyMap, IntermediateProbabilitiesAreSavedAgainstTheWrittenThresholds) {
  test::TempDir dir;
  OccupancyGrid grid(4, 1, 1.0, {});
  grid.cells = {10, 50, 80, -1};
  SaveOccupancyMap(grid, dir.Path("p"));
  EXPECT_EQ(LoadOccupancyMap(dir.Path("p.yaml")).cells,
            (std::vector<std::int8_t>{OccupancyGrid::kFree, OccupancyGrid::kUnknown, OccupancyGrid::kOccupied,
                                      OccupancyGrid::kUnknown}));
}

TEST(SaveOccupancyMap, AFailedSaveNamesThePath) {
  test::TempDir dir;
  const OccupancyGrid grid(2, 2, 0.1, {});
  const std::string base = dir.Path("no/such/folder/m");
  const std::string error = ErrorOf<MapFileError>([&] { SaveOccupancyMap(grid, base); });
  EXPECT_TRUE(Contains(error, base + ".pgm: cannot create the temporary file")) << error;
}

TEST(WriteFileAtomically, ReplacesTheContentAndLeavesNoTemporaryFile) {
  test::TempDir dir;
  dir.Write("f.txt", "old and longer");
  WriteFileAtomically(dir.Path("f.txt"), "new");
  EXPECT_EQ(dir.Read("f.txt"), "new");
  EXPECT_EQ(dir.List(), std::vector<std::string>{"f.txt"});
}

TEST(WriteFileAtomically, AFailedWriteThrowsNamingThePathAndKeepsTheOldFile) {
  test::TempDir dir;
  dir.Write("f.txt", "old");
  // A folder where the temporary file must go makes the write fail even for root (chmod would not).
  std::filesystem::create_directory(dir.Path("f.txt.tmp." + std::to_string(::getpid())));
  const std::string error = ErrorOf<std::runtime_error>([&] { WriteFileAtomically(dir.Path("f.txt"), "new"); });
  EXPECT_TRUE(Contains(error, dir.Path("f.txt") + ": cannot create the temporary file")) << error;
  EXPECT_EQ(dir.Read("f.txt"), "old");
}

TEST(WriteFileAtomically, AMissingFolderThrowsNamingThePath) {
  test::TempDir dir;
  const std::string path = dir.Path("missing/f.txt");
  const std::string error = ErrorOf<std::runtime_error>([&] { WriteFileAtomically(path, "x"); });
  EXPECT_TRUE(Contains(error, path + ": cannot create the temporary file")) << error;
  EXPECT_TRUE(Contains(error, "No such file or directory")) << error;
}

}  // namespace
}  // namespace doorplate_localization

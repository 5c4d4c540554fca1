// The files of `doorplate_eval map --out-dir`: they load back with the package's own readers.
#include "map_output.h"

#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "doorplate_localization/maps/map_io.h"

namespace doorplate_localization {
namespace {

TEST(WriteMapOutputs, WritesAMapServerMapATextMapNamingItAndAPicture) {
  MapEvalResult r;
  r.grid = OccupancyGrid(40, 20, 0.05, {-1.0, -0.5, 0.0}, OccupancyGrid::kFree);
  for (int x = 0; x < 40; ++x) r.grid.At(x, 0) = OccupancyGrid::kOccupied;
  TextLandmark plate;
  plate.text = "201";
  plate.pose = {0.5, -0.45, 1.5707963};
  plate.wall = "wall0";
  r.text_map.landmarks = {plate};
  r.trajectory = {{-0.5, 0.2, 0.0}, {0.5, 0.2, 0.0}};
  TextMap truth = r.text_map;
  const std::string dir = (std::filesystem::temp_directory_path() / "doorplate_map_output_test").string();
  std::filesystem::remove_all(dir);
  WriteMapOutputs(r, truth, dir);
  const OccupancyGrid grid = LoadOccupancyMap(dir + "/map.yaml");
  EXPECT_EQ(grid.width, 40);
  EXPECT_EQ(grid.height, 20);
  EXPECT_EQ(grid.At(3, 0), OccupancyGrid::kOccupied);
  const TextMap text_map = LoadTextMap(dir + "/text_map.yaml");
  ASSERT_EQ(text_map.landmarks.size(), 1u);
  EXPECT_EQ(text_map.landmarks[0].text, "201");
  EXPECT_EQ(text_map.occupancy_map, "map.yaml");
  const cv::Mat png = cv::imread(dir + "/map.png");
  EXPECT_FALSE(png.empty());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace doorplate_localization

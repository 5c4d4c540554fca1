#include "doorplate_localization/sim/photo_world.h"

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <unistd.h>

#include "doorplate_localization/sim/camera_renderer.h"
#include "doorplate_localization/sim/world_loader.h"

namespace doorplate_localization {
namespace {

namespace fs = std::filesystem;

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

// A temporary folder with one synthetic 60 × 40 "photo": grey, with a red 20 × 10 box at (10, 5) and a
// green 30 × 30 box at (25, 8).
class PhotoWorldTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("photo_world_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    cv::Mat photo(40, 60, CV_8UC3, cv::Scalar(128, 128, 128));
    photo(cv::Rect(10, 5, 20, 10)).setTo(cv::Scalar(0, 0, 255));
    photo(cv::Rect(25, 8, 30, 30)).setTo(cv::Scalar(0, 255, 0));
    ASSERT_TRUE(cv::imwrite((dir_ / "photo.png").string(), photo));
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST(ParsePlateCropTsv, ReadsBoxesSkipsCommentsAndResolvesPaths) {
  const std::vector<PlateCrop> crops = ParsePlateCropTsv(
      "# image\tx\ty\tw\th\ttext\n\nphotos/a.jpg\t1\t2\t30\t15\tE14-295\r\n/abs/b.png\t0\t0\t8\t8\t3.21\n",
      "crops.tsv", "/data");
  ASSERT_EQ(crops.size(), 2u);
  EXPECT_EQ(crops[0].image_path, "/data/photos/a.jpg");
  EXPECT_EQ(crops[0].x_px, 1);
  EXPECT_EQ(crops[0].y_px, 2);
  EXPECT_EQ(crops[0].width_px, 30);
  EXPECT_EQ(crops[0].height_px, 15);
  EXPECT_EQ(crops[0].text, "E14-295");
  EXPECT_EQ(crops[0].where, "crops.tsv:3");
  EXPECT_EQ(crops[1].image_path, "/abs/b.png");
  EXPECT_EQ(crops[1].text, "3.21");
}

TEST(ParsePlateCropTsv, MalformedLinesNameTheLineAndTheColumn) {
  EXPECT_EQ(ErrorOf([] { ParsePlateCropTsv("a.png\t1\t2\t3\t4\n", "c.tsv", ""); }),
            "c.tsv:1: expected 6 tab-separated columns (image_path, x, y, w, h, text), got 5");
  EXPECT_EQ(ErrorOf([] { ParsePlateCropTsv("# h\na.png\t1\t2\t0\t4\t101\n", "c.tsv", ""); }),
            "c.tsv:2: w must be a whole number >= 1, got '0'");
  EXPECT_EQ(ErrorOf([] { ParsePlateCropTsv("a.png\t1.5\t2\t3\t4\t101\n", "c.tsv", ""); }),
            "c.tsv:1: x must be a whole number >= 0, got '1.5'");
  EXPECT_EQ(ErrorOf([] { ParsePlateCropTsv("a.png\t1\t2\t3\t4\t\n", "c.tsv", ""); }), "c.tsv:1: text is empty");
}

TEST(PlateSizeForCrop, KeepsTheCropAspectAroundTheTargetWidth) {
  PhotoWorldOptions o;
  double w = 0.0, h = 0.0;
  PlateSizeForCrop(o, 200, 100, &w, &h);
  EXPECT_DOUBLE_EQ(w, 0.25);
  EXPECT_DOUBLE_EQ(h, 0.125);
  PlateSizeForCrop(o, 100, 200, &w, &h);  // tall: capped at max_plate_height_m
  EXPECT_DOUBLE_EQ(h, 0.25);
  EXPECT_DOUBLE_EQ(w, 0.125);
}

TEST_F(PhotoWorldTest, WritesCropsAndALoadableWorldWhoseCameraSeesThem) {
  const std::string tsv = "photo.png\t10\t5\t20\t10\tE14-295\nphoto.png\t25\t8\t30\t30\t102A\nphoto.png\t10\t5\t20\t10\t\"x\"\n";
  const std::vector<PlateCrop> crops = ParsePlateCropTsv(tsv, "c.tsv", dir_.string());
  const PhotoWorld written = WritePhotoWorld(crops, PhotoWorldOptions{}, (dir_ / "out").string());
  ASSERT_EQ(written.face_paths.size(), 3u);
  const cv::Mat first = cv::imread(written.face_paths[0]);
  ASSERT_EQ(first.size(), cv::Size(20, 10));
  EXPECT_EQ(first.at<cv::Vec3b>(5, 10), cv::Vec3b(0, 0, 255));  // the red box, cut exactly
  EXPECT_EQ(cv::imread(written.face_paths[1]).size(), cv::Size(30, 30));

  const World world = LoadWorldFile(written.world_path);
  const std::vector<const TextSign*> plates = world.Plates();
  ASSERT_EQ(plates.size(), 3u);
  EXPECT_EQ(plates[0]->text, "E14-295");
  EXPECT_EQ(plates[1]->text, "102A");
  EXPECT_EQ(plates[2]->text, "\"x\"");  // quoted in the YAML
  EXPECT_EQ(world.walls[plates[0]->wall_index].id, "north");  // alternating walls
  EXPECT_EQ(world.walls[plates[1]->wall_index].id, "south");
  EXPECT_NEAR(plates[0]->width_m, 0.25, 1e-3);   // 2:1 crop
  EXPECT_NEAR(plates[0]->height_m, 0.125, 1e-3);
  EXPECT_NEAR(plates[1]->width_m, 0.25, 1e-3);   // square crop: 0.25 × 0.25
  EXPECT_NEAR(plates[1]->height_m, 0.25, 1e-3);
  EXPECT_NEAR(world.SignPosition(*plates[1]).x - world.SignPosition(*plates[0]).x, 2.7, 1e-9);
  EXPECT_EQ(plates[0]->image_path, (dir_ / "out" / "worlds" / "faces" / "plate_01.png").string());

  // The camera, facing the first (north) plate from the corridor's middle, sees its red face.
  CameraOptions camera;
  camera.lens_blur_sigma_px = camera.pixel_noise_stddev = camera.lighting_gain_stddev = 0.0;
  camera.lighting_gradient = 0.0;
  const CameraRenderer renderer(world, camera);
  const Vec2 at = world.SignPosition(*plates[0]);
  const Pose2D pose{at.x, 0.6, 0.0};
  cv::Point2d centre;
  ASSERT_TRUE(renderer.Project(pose, {at.x, at.y, plates[0]->center_height_m}, &centre));
  const cv::Vec3b seen = renderer.RenderClean(pose).at<cv::Vec3b>(cv::Point(centre));
  EXPECT_GT(seen[2], 150);
  EXPECT_LT(seen[1], 60);
}

TEST_F(PhotoWorldTest, BoxesOutsideThePhotoAndMissingPhotosNameTheLine) {
  const std::string out = (dir_ / "out").string();
  EXPECT_NE(ErrorOf([&] {
              WritePhotoWorld(ParsePlateCropTsv("photo.png\t50\t5\t20\t10\t101\n", "c.tsv", dir_.string()), {}, out);
            }).find("c.tsv:1: box (50, 5, 20, 10) leaves the 60x40 image"),
            std::string::npos);
  EXPECT_NE(ErrorOf([&] {
              WritePhotoWorld(ParsePlateCropTsv("# x\nnone.png\t0\t0\t20\t10\t101\n", "c.tsv", dir_.string()), {}, out);
            }).find("c.tsv:2: cannot read image '" + (dir_ / "none.png").string() + "'"),
            std::string::npos);
}

}  // namespace
}  // namespace doorplate_localization

// doorplate_read_image end to end: the built tool on a rendered plate (Tesseract + MSER, always
// installed), its JSON, and its exit statuses for a bad image and a bad command line.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "../text/text_fixtures.h"

namespace doorplate_localization {
namespace {

namespace fs = std::filesystem;

class ReadImageTool : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("read_image_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    cv::Mat image = test::MakeWall();
    test::DrawPlate(image, "E14-295", cv::Point(320, test::kBandCenterY));
    ASSERT_TRUE(cv::imwrite((dir_ / "plate.png").string(), image));
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs the tool with `args`; returns its exit status, stdout+stderr in *output.
  int Run(const std::string& args, std::string* output) {
    const std::string log = (dir_ / "out.txt").string();
    const int status = std::system((std::string(DOORPLATE_READ_IMAGE) + " " + args + " > " + log + " 2>&1").c_str());
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    *output = text.str();
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  fs::path dir_;
};

TEST_F(ReadImageTool, PrintsEveryReadAndWritesItsJson) {
  std::string output;
  const std::string json = (dir_ / "reads.json").string();
  ASSERT_EQ(Run((dir_ / "plate.png").string() + " --json " + json, &output), 0) << output;
  EXPECT_NE(output.find("room E14"), std::string::npos) << output;  // Tesseract drops the hyphen
  std::ifstream in(json);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("\"detector\": \"mser\""), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("\"room\": \"E14"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("\"box_px\""), std::string::npos) << text.str();
}

TEST_F(ReadImageTool, AnUnreadableImageIsNamedAndTheOthersAreStillRead) {
  std::string output;
  EXPECT_EQ(Run((dir_ / "missing.png").string() + " " + (dir_ / "plate.png").string(), &output), 1);
  EXPECT_NE(output.find("missing.png: not an image"), std::string::npos) << output;
  EXPECT_NE(output.find("room E14"), std::string::npos) << output;
}

TEST_F(ReadImageTool, ABadCommandLineExitsWithStatusTwoAndTheUsage) {
  std::string output;
  EXPECT_EQ(Run("--recognizer easyocr " + (dir_ / "plate.png").string(), &output), 2);
  EXPECT_NE(output.find("tesseract, ppocr"), std::string::npos) << output;
  EXPECT_NE(output.find("Usage: doorplate_read_image"), std::string::npos) << output;
  EXPECT_EQ(Run("", &output), 2);
}

}  // namespace
}  // namespace doorplate_localization

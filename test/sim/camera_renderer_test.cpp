#include "doorplate_localization/sim/camera_renderer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <unistd.h>

namespace doorplate_localization {
namespace {

constexpr double kPi = 3.14159265358979323846;
const ColorRgb kPlateBlue{40, 60, 220};
const ColorRgb kWhite{250, 250, 250};

// No blur, noise or lighting change, so pixels can be compared with the geometry.
CameraOptions CleanOptions(double pitch_deg) {
  CameraOptions options;
  options.pitch_deg = pitch_deg;
  options.lens_blur_sigma_px = 0.0;
  options.pixel_noise_stddev = 0.0;
  options.lighting_gain_stddev = 0.0;
  options.lighting_gradient = 0.0;
  return options;
}

// One grey wall along y = 2 from x = -10 to 10 with a blue plate (white text) centred at x = 0 at the
// default camera height. `plate_faces_left` picks the side of a→b (+x) it faces: left is y > 2.
World WallWithPlate(bool plate_faces_left, const std::string& text = "123") {
  World world;
  world.walls = {{"north", {{-10.0, 2.0}, {10.0, 2.0}}, plate_faces_left, {200, 200, 200}}};
  TextSign plate;
  plate.text = text;
  plate.wall_index = 0;
  plate.offset_m = 10.0;
  plate.center_height_m = 1.2;
  plate.width_m = 0.3;
  plate.height_m = 0.15;
  plate.background = kPlateBlue;
  plate.foreground = kWhite;
  plate.corridor_side_left = plate_faces_left;
  world.signs.push_back(plate);
  BuildSurfaces(world);
  return world;
}

cv::Mat BlueMask(const cv::Mat& bgr) {
  cv::Mat mask;
  cv::inRange(bgr, cv::Scalar(150, 0, 0), cv::Scalar(255, 110, 90), mask);
  return mask;
}

cv::Rect BoundingBox(const cv::Mat& mask) {
  std::vector<cv::Point> points;
  cv::findNonZero(mask, points);
  return points.empty() ? cv::Rect() : cv::boundingRect(points);
}

cv::Point2d Centre(const cv::Rect& box) {
  return {box.x + (box.width - 1) / 2.0, box.y + (box.height - 1) / 2.0};
}

TEST(CameraRenderer, PlateCentreProjectsOntoItsRenderedPixels) {
  const World world = WallWithPlate(false);
  const CameraRenderer camera(world, CleanOptions(10.0));
  const Pose2D pose{0.4, 0.3, 0.15};  // plate off-centre and seen at an angle
  const cv::Mat image = camera.RenderClean(pose);
  const cv::Rect box = BoundingBox(BlueMask(image));
  ASSERT_GT(box.area(), 100);
  cv::Point2d centre;
  ASSERT_TRUE(camera.Project(pose, {0.0, 2.0, 1.2}, &centre));
  EXPECT_NEAR(Centre(box).x, centre.x, 1.5);
  EXPECT_NEAR(Centre(box).y, centre.y, 1.5);

  // The whole plate (blue, or white text and border, not the grey wall) spans its projected corners.
  cv::Mat white;
  cv::inRange(image, cv::Scalar(215, 215, 215), cv::Scalar(255, 255, 255), white);
  const cv::Rect plate = BoundingBox(BlueMask(image) | white);
  double left = 1e9, right = -1e9, top = 1e9, bottom = -1e9;
  for (double x : {-0.15, 0.15}) {
    for (double z : {1.125, 1.275}) {
      cv::Point2d corner;
      ASSERT_TRUE(camera.Project(pose, {x, 2.0, z}, &corner));
      left = std::min(left, corner.x), right = std::max(right, corner.x);
      top = std::min(top, corner.y), bottom = std::max(bottom, corner.y);
    }
  }
  EXPECT_NEAR(plate.x, left, 1.0);
  EXPECT_NEAR(plate.x + plate.width, right, 1.0);
  EXPECT_NEAR(plate.y, top, 1.0);
  EXPECT_NEAR(plate.y + plate.height, bottom, 1.0);
}

TEST(CameraRenderer, PlateStraightAheadProjectsToTheCentreColumn) {
  const World world = WallWithPlate(false);
  const CameraRenderer camera(world, CleanOptions(0.0));
  cv::Point2d pixel;
  ASSERT_TRUE(camera.Project({0, 0, 0}, {0.0, 2.0, 1.2}, &pixel));
  EXPECT_NEAR(pixel.x, 319.5, 1e-9);
  EXPECT_NEAR(pixel.y, 239.5, 1e-9);
  const cv::Point2d rendered = Centre(BoundingBox(BlueMask(camera.RenderClean({0, 0, 0}))));
  EXPECT_NEAR(rendered.x, 319.5, 1.0);
  EXPECT_NEAR(rendered.y, 239.5, 1.0);
}

TEST(CameraRenderer, PitchingUpMovesThePlateDownInTheImage) {
  const World world = WallWithPlate(false);
  const CameraRenderer camera(world, CleanOptions(10.0));
  cv::Point2d pixel;
  ASSERT_TRUE(camera.Project({0, 0, 0}, {0.0, 2.0, 1.2}, &pixel));
  const double fy = camera.intrinsics().fy_px;
  EXPECT_NEAR(pixel.y, 239.5 + fy * std::tan(10.0 * kPi / 180.0), 1e-6);
  const cv::Point2d rendered = Centre(BoundingBox(BlueMask(camera.RenderClean({0, 0, 0}))));
  EXPECT_NEAR(rendered.x, 319.5, 1.0);
  EXPECT_NEAR(rendered.y, pixel.y, 1.0);
}

TEST(CameraRenderer, SignsAreInvisibleFromTheBackOfTheirWall) {
  const World world = WallWithPlate(true);  // faces y > 2, the camera is at y = 0
  const CameraRenderer camera(world, CleanOptions(0.0));
  const cv::Mat image = camera.RenderClean({0, 0, 0});
  EXPECT_EQ(cv::countNonZero(BlueMask(image)), 0);
  const cv::Vec3b centre = image.at<cv::Vec3b>(240, 320);  // plain wall instead
  EXPECT_EQ(centre[0], centre[2]);
  EXPECT_GT(centre[0], 150);
}

// Text must read left to right from the front: "L" has most of its ink left of its glyph's centre.
// Returns that offset as a fraction of the glyph's width (negative: unmirrored).
double InkCentroidOffset(const cv::Mat& image) {
  const cv::Rect box = BoundingBox(BlueMask(image));
  const cv::Rect inner(box.x + box.width / 8, box.y + box.height / 8, box.width * 3 / 4, box.height * 3 / 4);
  cv::Mat ink;  // white text inside the border
  cv::inRange(image(inner), cv::Scalar(170, 170, 170), cv::Scalar(255, 255, 255), ink);
  const cv::Rect glyph = BoundingBox(ink);
  EXPECT_GT(glyph.area(), 20);
  const cv::Moments m = cv::moments(ink(glyph), true);
  return (m.m10 / m.m00 - (glyph.width - 1) / 2.0) / glyph.width;
}

TEST(CameraRenderer, LeftCameraReadsSignsUnmirrored) {
  const World world = WallWithPlate(false, "L");
  const CameraRenderer camera(world, CleanOptions(0.0));
  EXPECT_LT(InkCentroidOffset(camera.RenderClean({0, 0, 0})), -0.1);
}

TEST(CameraRenderer, RightCameraLooksAlongMinusYAndReadsSignsUnmirrored) {
  const World world = WallWithPlate(true, "L");
  CameraOptions options = CleanOptions(0.0);
  options.side = "right";
  const CameraRenderer camera(world, options);
  const Pose2D pose{0.0, 4.0, 0.0};  // north of the wall, the right camera looks south at it
  cv::Point2d pixel;
  ASSERT_TRUE(camera.Project(pose, {0.0, 2.0, 1.2}, &pixel));
  EXPECT_NEAR(pixel.x, 319.5, 1e-9);
  EXPECT_FALSE(camera.Project(pose, {0.0, 6.0, 1.2}, &pixel));  // behind the camera
  EXPECT_LT(InkCentroidOffset(camera.RenderClean(pose)), -0.1);
}

TEST(CameraRenderer, FloorIsBelowTheHorizonAndCeilingAbove) {
  World world;
  world.walls = {{"far", {{-50.0, 30.0}, {50.0, 30.0}}, false, {200, 200, 200}}};
  world.floor_color = {200, 30, 30};
  world.ceiling_color = {30, 200, 30};
  BuildSurfaces(world);
  const CameraRenderer camera(world, CleanOptions(0.0));
  const cv::Mat image = camera.RenderClean({0, 0, 0});
  const cv::Vec3b bottom = image.at<cv::Vec3b>(470, 320), top = image.at<cv::Vec3b>(10, 320);
  EXPECT_GT(bottom[2], 2 * bottom[1]);  // red floor (BGR)
  EXPECT_GT(top[1], 2 * top[2]);        // green ceiling
  const cv::Vec3b horizon = image.at<cv::Vec3b>(240, 320);  // the far wall: grey
  EXPECT_EQ(horizon[0], horizon[2]);
}

TEST(CameraRenderer, ClosedDoorsAreDrawnOnTheWallAndOpenDoorsShowTheRoom) {
  World world;
  world.walls = {{"north", {{-10.0, 2.0}, {10.0, 2.0}}, false, {230, 40, 40}}};
  Door door;
  door.wall_index = 0;
  door.offset_m = 10.0;
  door.color = {40, 200, 40};
  world.doors.push_back(door);
  BuildSurfaces(world);
  const CameraOptions options = CleanOptions(0.0);
  const Pose2D pose{0.0, -1.0, 0.0};
  cv::Point2d panel, lintel;
  {
    const CameraRenderer camera(world, options);
    ASSERT_TRUE(camera.Project(pose, {0.0, 2.0, 1.0}, &panel));
    ASSERT_TRUE(camera.Project(pose, {0.0, 2.0, 2.4}, &lintel));
    const cv::Mat image = camera.RenderClean(pose);
    const cv::Vec3b p = image.at<cv::Vec3b>(cv::Point(panel)), l = image.at<cv::Vec3b>(cv::Point(lintel));
    EXPECT_GT(p[1], 2 * p[2]);  // green panel
    EXPECT_GT(l[2], 2 * l[1]);  // red wall above the door
  }
  world.doors[0].open = true;
  BuildSurfaces(world);
  const CameraRenderer camera(world, options);
  const cv::Mat image = camera.RenderClean(pose);
  const cv::Vec3b p = image.at<cv::Vec3b>(cv::Point(panel)), l = image.at<cv::Vec3b>(cv::Point(lintel));
  EXPECT_LT(p[1], 2 * p[2]);  // not the door: the room behind
  EXPECT_LT(p[2], 2 * p[1]);  // and not the wall
  EXPECT_GT(l[2], 2 * l[1]);  // the lintel keeps the wall colour
}

TEST(CameraRenderer, RenderIsDeterministicPerSeedAndHasTheConfiguredSize) {
  const World world = WallWithPlate(false);
  const CameraRenderer camera(world, CameraOptions{});
  std::mt19937_64 rng_a(7), rng_b(7), rng_c(8);
  const cv::Mat a = camera.Render({0, 0, 0}, 0.5, 0.1, rng_a);
  const cv::Mat b = camera.Render({0, 0, 0}, 0.5, 0.1, rng_b);
  const cv::Mat c = camera.Render({0, 0, 0}, 0.5, 0.1, rng_c);
  EXPECT_EQ(a.cols, 640);
  EXPECT_EQ(a.rows, 480);
  EXPECT_EQ(a.type(), CV_8UC3);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::norm(a, c, cv::NORM_L1), 640.0 * 480.0);  // noise differs nearly everywhere
}

TEST(CameraRenderer, PixelNoiseHasTheConfiguredSpread) {
  World world;  // nothing but floor and ceiling
  BuildSurfaces(world);
  CameraOptions options = CleanOptions(0.0);
  options.pixel_noise_stddev = 4.0;
  const CameraRenderer camera(world, options);
  std::mt19937_64 rng(3);
  cv::Mat diff;
  camera.Render({0, 0, 0}, 0.0, 0.0, rng).convertTo(diff, CV_32F);
  cv::Mat clean;
  camera.RenderClean({0, 0, 0}).convertTo(clean, CV_32F);
  cv::Scalar mean, stddev;
  cv::meanStdDev(cv::Mat(diff - clean).reshape(1), mean, stddev);
  EXPECT_NEAR(mean[0], 0.0, 0.1);
  EXPECT_NEAR(stddev[0], 4.0, 0.2);  // rounding to grey levels adds 1/12 of variance
}

// Sum of squared horizontal gradients: blur spreads an edge's step over more pixels and lowers it.
double HorizontalGradientEnergy(const cv::Mat& image) {
  cv::Mat grey, dx;
  cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  cv::Sobel(grey, dx, CV_32F, 1, 0);
  return cv::norm(dx, cv::NORM_L2SQR);
}

TEST(CameraRenderer, DrivingPastSmearsTheImageHorizontally) {
  const World world = WallWithPlate(false);
  CameraOptions options = CleanOptions(0.0);
  options.exposure_s = 0.02;  // 1 m/s at 2 m: 0.02 · 554 / 2 ≈ 5.5 px of smear
  const CameraRenderer camera(world, options);
  std::mt19937_64 rng(1);
  const double still = HorizontalGradientEnergy(camera.Render({0, 0, 0}, 0.0, 0.0, rng));
  const double moving = HorizontalGradientEnergy(camera.Render({0, 0, 0}, 1.0, 0.0, rng));
  EXPECT_LT(moving, 0.5 * still);
  // Turning left while driving forward cancels the image motion when ω = v / depth.
  const double cancelled = HorizontalGradientEnergy(camera.Render({0, 0, 0}, 1.0, 0.5, rng));
  EXPECT_NEAR(cancelled, still, 0.02 * still);
}

TEST(CameraRenderer, MountPoseFollowsTheOptions) {
  const World world = WallWithPlate(false);
  CameraOptions options;
  options.mount_x_m = 0.1;
  options.mount_height_m = 1.3;
  options.pitch_deg = 10.0;
  options.side = "right";
  const CameraRenderer camera(world, options);
  double x, y, z, yaw, pitch;
  camera.MountPose(&x, &y, &z, &yaw, &pitch);
  EXPECT_DOUBLE_EQ(x, 0.1);
  EXPECT_DOUBLE_EQ(y, 0.0);
  EXPECT_DOUBLE_EQ(z, 1.3);
  EXPECT_NEAR(yaw, -kPi / 2, 1e-12);
  EXPECT_NEAR(pitch, -10.0 * kPi / 180.0, 1e-12);  // REP-103: tilted up is negative pitch
}

TEST(CameraRenderer, RejectsUnusableOptionsAndSigns) {
  World world = WallWithPlate(false);
  CameraOptions options;
  options.side = "up";
  EXPECT_THROW(CameraRenderer(world, options), std::invalid_argument);
  options = CameraOptions{};
  options.pitch_deg = 80.0;
  EXPECT_THROW(CameraRenderer(world, options), std::invalid_argument);
  world.signs[0].width_m = 0.0;
  EXPECT_THROW(CameraRenderer(world, CameraOptions{}), std::invalid_argument);
}

TEST(CameraRenderer, AnImageSignShowsThePhotoStretchedToItsSize) {
  // A 40 × 40 px photo (left half red, right half green) on a 0.3 × 0.15 m sign: stretched 2:1.
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("camera_renderer_test_" + std::to_string(::getpid()) + ".png")).string();
  cv::Mat photo(40, 40, CV_8UC3, cv::Scalar(0, 0, 255));
  photo.colRange(20, 40).setTo(cv::Scalar(0, 255, 0));
  ASSERT_TRUE(cv::imwrite(path, photo));
  World world = WallWithPlate(false);
  world.signs[0].image_path = path;
  const CameraRenderer camera(world, CleanOptions(0.0));
  std::filesystem::remove(path);  // the texture is made in the constructor
  const cv::Mat image = camera.RenderClean({0, 0, 0});
  cv::Mat red, green;
  cv::inRange(image, cv::Scalar(0, 0, 150), cv::Scalar(90, 90, 255), red);
  cv::inRange(image, cv::Scalar(0, 150, 0), cv::Scalar(90, 255, 90), green);
  EXPECT_EQ(cv::countNonZero(BlueMask(image)), 0);  // no drawn plate
  cv::Point2d left, right, top, bottom;  // the sign's edges: x -0.15..0.15 on the wall at y = 2
  ASSERT_TRUE(camera.Project({0, 0, 0}, {-0.15, 2.0, 1.2}, &left));
  ASSERT_TRUE(camera.Project({0, 0, 0}, {0.15, 2.0, 1.2}, &right));
  ASSERT_TRUE(camera.Project({0, 0, 0}, {0.0, 2.0, 1.275}, &top));
  ASSERT_TRUE(camera.Project({0, 0, 0}, {0.0, 2.0, 1.125}, &bottom));
  const cv::Rect r = BoundingBox(red), g = BoundingBox(green);
  ASSERT_GT(r.area(), 100);
  ASSERT_GT(g.area(), 100);
  EXPECT_LT(r.x, g.x);  // the photo's left half is on the image left: read unmirrored
  EXPECT_NEAR(std::min(r.x, g.x), std::min(left.x, right.x), 1.5);
  EXPECT_NEAR(std::max(r.x + r.width, g.x + g.width), std::max(left.x, right.x), 1.5);
  EXPECT_NEAR(r.y, top.y, 1.5);
  EXPECT_NEAR(r.y + r.height, bottom.y, 1.5);
  EXPECT_NEAR(r.width, g.width, 2.0);
}

TEST(CameraRenderer, AnUnreadableImageSignIsAnErrorNamingTheFile) {
  World world = WallWithPlate(false);
  world.signs[0].image_path = "/nonexistent/face.png";
  try {
    CameraRenderer camera(world, CleanOptions(0.0));
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("signs[0] ('123').image: cannot read image '/nonexistent/face.png'"),
              std::string::npos) << e.what();
  }
}

TEST(CameraRenderer, LightingZonesDarkenWhatIsInsideThem) {
  World world = WallWithPlate(false);
  const CameraRenderer lit(world, CleanOptions(0.0));
  const cv::Vec3b before = lit.RenderClean({0, 0, 0}).at<cv::Vec3b>(100, 100);  // plain wall
  LightZone dark;
  dark.min = {-10.0, 1.5};
  dark.max = {10.0, 2.5};
  dark.gain = dark.gain_at_max = 0.5;
  world.lighting.push_back(dark);
  const CameraRenderer dimmed(world, CleanOptions(0.0));
  const cv::Mat image = dimmed.RenderClean({0, 0, 0});
  const cv::Vec3b after = image.at<cv::Vec3b>(100, 100);
  for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(after[ch], 0.5 * before[ch], 1.0);
  EXPECT_EQ(image.at<cv::Vec3b>(470, 100), lit.RenderClean({0, 0, 0}).at<cv::Vec3b>(470, 100));  // floor
}

TEST(CameraRenderer, ExplicitIntrinsicsAt1280x720AreUsedForRenderingAndProjection) {
  const World world = WallWithPlate(false);
  CameraOptions options = CleanOptions(0.0);
  options.width_px = 1280;
  options.height_px = 720;
  options.fx_px = 900.0;
  options.fy_px = 880.0;
  options.cx_px = 600.0;
  options.cy_px = 380.0;
  const CameraRenderer camera(world, options);
  EXPECT_DOUBLE_EQ(camera.intrinsics().fx_px, 900.0);
  EXPECT_DOUBLE_EQ(camera.intrinsics().fy_px, 880.0);
  EXPECT_DOUBLE_EQ(camera.intrinsics().cx_px, 600.0);
  EXPECT_DOUBLE_EQ(camera.intrinsics().cy_px, 380.0);
  const cv::Mat image = camera.RenderClean({0, 0, 0});
  EXPECT_EQ(image.cols, 1280);
  EXPECT_EQ(image.rows, 720);
  const cv::Rect box = BoundingBox(BlueMask(image));
  EXPECT_NEAR(Centre(box).x, 600.0, 1.0);  // plate straight ahead, at camera height
  EXPECT_NEAR(Centre(box).y, 380.0, 1.0);
  cv::Mat white;  // the plate's border is drawn in the text colour
  cv::inRange(image, cv::Scalar(215, 215, 215), cv::Scalar(255, 255, 255), white);
  const cv::Rect plate = BoundingBox(BlueMask(image) | white);
  EXPECT_NEAR(plate.width, 900.0 * 0.3 / 2.0, 1.5);   // 0.3 m wide at 2 m
  EXPECT_NEAR(plate.height, 880.0 * 0.15 / 2.0, 1.5);
}

}  // namespace
}  // namespace doorplate_localization
